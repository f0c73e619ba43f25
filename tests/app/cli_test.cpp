// The program as users run it: bad input of every kind gives one line on stderr naming the
// file and the problem, exit code 2, and no output file; good input gives an image and stats.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "app/cli_run.h"

namespace {

namespace fs = std::filesystem;
using fastshade::testing::Outcome;
using fastshade::testing::slurp;

class Cli : public fastshade::testing::ProgramTest {
 protected:
  // Exit 2, one line naming `needle`, and nothing left in the directory but our own files.
  void expect_bad_input(const std::string& args, const std::string& needle) {
    const auto before = listing();
    const Outcome r = run(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "not one line: " << r.err;
    EXPECT_NE(r.err.find(needle), std::string::npos) << "'" << needle << "' not in: " << r.err;
    EXPECT_EQ(listing(), before) << "output left behind by: " << args;
  }
  std::set<std::string> listing() {
    std::set<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) {
      const std::string n = e.path().filename().string();
      if (n != "stdout.txt" && n != "stderr.txt") names.insert(n);
    }
    return names;
  }
  std::string scene_with(const std::string& objects, int width = 64) {
    return R"({"image": {"width": )" + std::to_string(width) +
           R"(, "height": 48, "background": [0, 0, 0]},
      "camera": {"fit": true, "distance": 3, "fovy_deg": 45},
      "lights": [{"type": "directional", "direction": [0, 0, 1], "color": [1, 1, 1]}],
      "materials": {"m": {"diffuse": 0.7, "specular": 0.3, "shininess": 20}},
      "objects": )" + objects + "}";
  }
};

TEST_F(Cli, DefaultSceneRendersWithStats) {
  const fs::path out = dir_ / "default.png", stats = dir_ / "stats.json";
  const Outcome r = run("render -o " + out.string() + " --stats " + stats.string() + " --frames 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out));
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
  const auto j = nlohmann::json::parse(slurp(stats));
  for (const char* key : {"triangles_in", "triangles_drawn", "triangles_dropped", "tiles_total",
                          "tiles_nonempty", "covered_pixels", "threads", "tile", "isa", "method",
                          "mpix_per_s", "mtri_per_s"})
    EXPECT_TRUE(j.contains(key)) << key;
  for (const char* key : {"front_end", "binning", "raster_shade", "total"})
    EXPECT_GT(j["median_ms"][key].get<double>(), 0.0) << key;
  EXPECT_GT(j["covered_pixels"].get<long long>(), 0);
  EXPECT_EQ(listing(), (std::set<std::string>{"default.png", "stats.json"}));
}

TEST_F(Cli, CompareReportsIdenticalImages) {
  const fs::path out = dir_ / "a.png";
  ASSERT_EQ(run("render -o " + out.string()).exit_code, 0);
  const Outcome r = run("compare " + out.string() + " " + out.string() + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["max_abs_lsb"].get<double>(), 0.0);
}

TEST_F(Cli, BadScenesAndOptionsFailWithOneLine) {
  const std::string out = (dir_ / "out.png").string();
  expect_bad_input("render " + (dir_ / "missing.json").string() + " -o " + out, "missing.json");
  expect_bad_input("render " + dir_.string() + " -o " + out, dir_.string());
  const fs::path bad_key = write("bad_key.json", scene_with(R"([{"primitive": "icosphere", "colour": 1}])"));
  expect_bad_input("render " + bad_key.string() + " -o " + out, "objects[0]");
  const fs::path huge = write("huge.json", scene_with(R"([{"primitive": "icosphere"}])", 1000000));
  expect_bad_input("render " + huge.string() + " -o " + out, "image.width");
  const fs::path good = write("good.json", scene_with(R"([{"primitive": "icosphere"}])"));
  expect_bad_input("render " + good.string() + " -o " + (dir_ / "no_dir" / "x.png").string(), "no_dir");
  expect_bad_input("render " + good.string() + " -o " + (dir_ / "x.unknownext").string(), "x.unknownext");
  expect_bad_input("render " + good.string() + " -o " + out + " --tile 48", "--tile");
  expect_bad_input("render " + good.string() + " -o " + out + " --method nope", "--method");
  expect_bad_input("render " + good.string() + " -o " + out + " --threads -3", "--threads");
  expect_bad_input("render " + good.string() + " -o " + out + " --bogus", "bogus");
  expect_bad_input("render " + good.string() + " -o " + out + " --frames 0", "--frames");
  EXPECT_EQ(run("render " + good.string() + " -o " + out).exit_code, 0);
}

TEST_F(Cli, BadMeshesFailWithOneLineNamingTheMesh) {
  const std::string out = (dir_ / "out.png").string();
  const std::pair<std::string, std::string> meshes[] = {
      {"empty.obj", ""},
      {"nan.obj", "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n"},
      {"inf.obj", "v 0 0 0\nv 1 0 0\nv 0 inf 0\nf 1 2 3\n"},
      {"range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n"},
      {"points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"},
      {"lies.off", "OFF\n3 353535235358 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"},
      {"utf16.obj", std::string("\xFF\xFEv\0 \0" "0\0", 8)},
  };
  for (const auto& [name, text] : meshes) {
    write(name, text);
    const fs::path scene = write("scene_" + name + ".json", scene_with(R"([{"mesh": ")" + name + R"("}])"));
    expect_bad_input("render " + scene.string() + " -o " + out, name);
    expect_bad_input("info " + (dir_ / name).string(), name);
  }
  expect_bad_input("info " + (dir_ / "nothing.ply").string(), "nothing.ply");
  expect_bad_input("info " + dir_.string(), dir_.string());
}

TEST_F(Cli, CompareRejectsMismatchedSizes) {
  const fs::path a = write("a.json", scene_with(R"([{"primitive": "icosphere"}])", 64));
  const fs::path b = write("b.json", scene_with(R"([{"primitive": "icosphere"}])", 32));
  ASSERT_EQ(run("render " + a.string() + " -o " + (dir_ / "a.png").string()).exit_code, 0);
  ASSERT_EQ(run("render " + b.string() + " -o " + (dir_ / "b.png").string()).exit_code, 0);
  const Outcome r = run("compare " + (dir_ / "a.png").string() + " " + (dir_ / "b.png").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("sizes differ"), std::string::npos) << r.err;
}

}  // namespace
