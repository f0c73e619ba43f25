// --aov from the command line: render and batch write the library's AOVs (Renderer with an
// AovSet) into the image or beside it, resume knows the AOV file, bad lists are usage errors.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <nlohmann/json.hpp>

#include "fastshade/image.h"
#include "fastshade/render.h"
#include "fastshade/scene.h"
#include "support/cli_fixture.h"

namespace fastshade {
namespace {

namespace fs = std::filesystem;

class AovCli : public test::CliFixture {};

// Channel `name` of an EXR as 32-bit words (float bits or uint); empty if absent.
std::vector<uint32_t> channel(const fs::path& path, const std::string& name) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) return {};
  const int c = in->spec().channelindex(name);
  if (c < 0) return {};
  std::vector<uint32_t> words(std::size_t(in->spec().width) * in->spec().height);
  if (!in->read_image(0, 0, c, c + 1, in->spec().channelformat(c), words.data())) return {};
  return words;
}

template <typename T>
std::vector<uint32_t> words(const std::vector<T>& v) {
  std::vector<uint32_t> out(v.size());
  std::memcpy(out.data(), v.data(), v.size() * 4);
  return out;
}

TEST_F(AovCli, RenderWritesTheLibrarysAovsBesideOrInTheImage) {
  const fs::path scene = write("s.json", scene_with(R"([{"primitive": "torus"}, {"primitive": "icosphere"}])"));
  Renderer renderer(load_scene(scene), RenderOptions{});
  Image colour;
  AovImages expected;
  renderer.render_frame(colour, AovSet{true, true, true, true}, expected);

  ASSERT_EQ(run("render " + scene.string() + " -o " + (dir_ / "a.png").string() + " --aov depth,object_id").exit_code, 0);
  EXPECT_TRUE(fs::exists(dir_ / "a.png"));
  EXPECT_EQ(channel(dir_ / "a.aov.exr", "Z"), words(expected.depth));
  EXPECT_EQ(channel(dir_ / "a.aov.exr", "object_id"), words(expected.object_id));
  EXPECT_TRUE(channel(dir_ / "a.aov.exr", "triangle_id").empty());

  ASSERT_EQ(run("render " + scene.string() + " -o " + (dir_ / "b.exr").string() + " --aov all --threads 1 --tile 8").exit_code, 0);
  EXPECT_FALSE(fs::exists(dir_ / "b.aov.exr"));
  EXPECT_EQ(channel(dir_ / "b.exr", "triangle_id"), words(expected.triangle_id));
  EXPECT_FALSE(channel(dir_ / "b.exr", "R").empty());
  EXPECT_FALSE(channel(dir_ / "b.exr", "N.Z").empty());
}

TEST_F(AovCli, BadAovListsAreUsageErrors) {
  expect_bad_input("render -o " + (dir_ / "x.png").string() + " --aov depth,colour", "--aov: unknown output 'colour'");
  expect_bad_input("render -o " + (dir_ / "x.png").string() + " --aov ,", "--aov");
  expect_bad_input("batch " + dir_.string() + " -o " + (dir_ / "out").string() + " --aov nope", "--aov");
}

TEST_F(AovCli, BatchWritesAovsBesideEachImageAndResumesOnlyWhenBothExist) {
  write("m/oct.off",
        "OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n"
        "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n");
  const fs::path out = dir_ / "out";
  const std::string args = "batch " + (dir_ / "m").string() + " -o " + out.string() + " --size 40x30 --views 2 --aov all";
  ASSERT_EQ(run(args).exit_code, 0);
  // Each results line names its image's AOV file, STEM.aov.exr beside it.
  std::map<int, fs::path> aov_file;
  std::ifstream results(out / "results.jsonl");
  for (std::string line; std::getline(results, line);) {
    const nlohmann::json j = nlohmann::json::parse(line);
    const fs::path image = j["output"].get<std::string>();
    EXPECT_EQ(j["aov_output"], image.stem().string() + ".aov.exr") << line;
    aov_file[j["view"].get<int>()] = out / j["aov_output"].get<std::string>();
  }
  ASSERT_EQ(aov_file.size(), 2u);
  // The ids say the one mesh (object 0) wherever a face (id 0..7) is drawn.
  const std::vector<uint32_t> object = channel(aov_file[0], "object_id");
  const std::vector<uint32_t> face = channel(aov_file[0], "triangle_id");
  ASSERT_EQ(object.size(), 1200u);
  int drawn = 0;
  for (std::size_t i = 0; i < object.size(); ++i) {
    EXPECT_EQ(object[i] == 0, face[i] < 8) << i;
    drawn += object[i] == 0;
  }
  EXPECT_GT(drawn, 100);

  fs::remove(aov_file[1]);
  const test::Outcome again = run(args);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.out.find("1 images"), std::string::npos) << again.out;  // v1 only
  EXPECT_TRUE(fs::exists(aov_file[1]));
}

}  // namespace
}  // namespace fastshade
