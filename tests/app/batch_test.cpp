// fastshade batch as users run it: images identical to `fastshade render` of the equivalent
// scene, a results line per image, failures reported while the rest goes on, resume, shards,
// bad usage, and an interrupted run leaving only whole images.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "fastshade/error.h"
#include "fastshade/image.h"
#include "fastshade/render.h"
#include "fastshade/scene.h"
#include "io/scene_template.h"
#include "support/cli_fixture.h"

namespace fastshade {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::Outcome;

// Tiny meshes keep every run fast: an octahedron (OFF) and a tetrahedron (OBJ).
constexpr const char* kOctahedron =
    "OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n"
    "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n";
constexpr const char* kTetrahedron =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

class Batch : public test::CliFixture {
 protected:
  // `batch dir_/m -o dir_/out --views VIEWS --size SIZE`, for run_batch in process.
  BatchCommand command(int views, const std::string& size) const {
    BatchCommand cmd;
    cmd.inputs = {(dir_ / "m").string()};
    cmd.outdir = (dir_ / "out").string();
    cmd.views = views;
    cmd.size = size;
    return cmd;
  }

  // Every line of OUTDIR/results.jsonl.
  std::vector<json> results(const fs::path& outdir) {
    std::vector<json> lines;
    std::ifstream in(outdir / "results.jsonl");
    for (std::string line; std::getline(in, line);) lines.push_back(json::parse(line));
    return lines;
  }

  // The files in a directory other than results.jsonl.
  static std::set<std::string> images_in(const fs::path& dir) {
    std::set<std::string> names;
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().filename() != "results.jsonl") names.insert(e.path().filename().string());
    return names;
  }
};

// The scene rendered in this process, read back through the same PNG round trip.
ImageF render_scene_text(const std::string& text, const fs::path& dir) {
  const fs::path png = dir / "expected.png";
  write_image(render(parse_scene(text, "equivalent.json", dir), RenderOptions{}), png);
  return read_image(png);
}

TEST_F(Batch, ViewsMatchRenderOfTheEquivalentSceneAndFailuresAreReported) {
  write("meshes/a/oct.off", kOctahedron);
  write("meshes/b/oct.off", kOctahedron);  // same base name, other directory
  write("meshes/broken.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n");
  const fs::path out = dir_ / "out";
  const Outcome r = run("batch " + (dir_ / "meshes").string() + " " +
                        (dir_ / "nonexistent.obj").string() + " -o " + out.string() +
                        " --views 3 --size 40x30 --threads 2");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.out.find("6 ok, 6 failed"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("failed: " + (dir_ / "meshes/broken.ply").string()), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("failed: " + (dir_ / "nonexistent.obj").string()), std::string::npos) << r.out;
  // Not a terminal: one plain progress line per image.
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 12) << r.err;

  std::map<std::string, std::vector<json>> by_mesh;
  for (const json& line : results(out)) by_mesh[line["mesh"].get<std::string>()].push_back(line);
  ASSERT_EQ(by_mesh.size(), 4u);
  for (const auto& [mesh, lines] : by_mesh) {
    ASSERT_EQ(lines.size(), 3u) << mesh;
    const bool bad = mesh.find("broken") != std::string::npos || mesh.find("nonexistent") != std::string::npos;
    std::set<int> views;
    for (const json& line : lines) {
      views.insert(line["view"].get<int>());
      EXPECT_EQ(line["status"], bad ? "failed" : "ok") << line;
      EXPECT_EQ(line.contains("error"), bad) << line;
      EXPECT_EQ(fs::exists(out / line["output"].get<std::string>()), !bad) << line;
    }
    EXPECT_EQ(views, (std::set<int>{0, 1, 2})) << mesh;
  }
  EXPECT_EQ(images_in(out).size(), 6u);  // two meshes named oct.off do not collide

  // The equivalent scene: the default template, the mesh as its only object, --size, and
  // for a turned view the camera its line gives.
  json scene = json::parse(default_batch_template_json());
  scene["image"]["width"] = 40;
  scene["image"]["height"] = 30;
  scene["objects"] = json::array({{{"mesh", "meshes/a/oct.off"}}});
  for (const json& line : by_mesh[(dir_ / "meshes/a/oct.off").string()]) {
    SCOPED_TRACE(line.dump());
    EXPECT_EQ(line["vertices"], 6);
    EXPECT_EQ(line["triangles"], 8);
    json view_scene = scene;
    if (line["view"] != 0) view_scene["camera"] = line["camera"];
    const ImageF expected = render_scene_text(view_scene.dump(), dir_);
    const ImageF batch = read_image(out / line["output"].get<std::string>());
    ASSERT_EQ(batch.width, 40);
    ASSERT_EQ(batch.height, 30);
    EXPECT_TRUE(batch.rgb == expected.rgb);
  }
  // Turned views differ from the front view.
  const auto& oct = by_mesh[(dir_ / "meshes/a/oct.off").string()];
  EXPECT_NE(oct[0]["camera"]["eye"], oct[1]["camera"]["eye"]);
}

// In process (no program start-up): run_batch's exit code, its output captured and dropped.
int run_in_process(const BatchCommand& cmd) {
  ::testing::internal::CaptureStdout();
  ::testing::internal::CaptureStderr();
  const int code = run_batch(cmd);
  ::testing::internal::GetCapturedStdout();
  ::testing::internal::GetCapturedStderr();
  return code;
}

TEST_F(Batch, ResumeSkipsCompleteImagesAndShardsSplitTheRest) {
  for (const char* name : {"m/a.off", "m/b.off", "m/c.obj", "m/d/e.obj"})
    write(name, std::string(name).ends_with(".off") ? kOctahedron : kTetrahedron);
  const fs::path out = dir_ / "out";
  BatchCommand cmd = command(2, "24x24");
  ASSERT_EQ(run_in_process(cmd), 0);
  const std::set<std::string> first = images_in(out);
  ASSERT_EQ(first.size(), 8u);

  // One image lost, one left half-written as a temp file by a killed run, one foreign file.
  const std::string lost = *first.begin();
  fs::remove(out / lost);
  const std::string stale = "." + *first.rbegin() + ".tmp999999.3.png";
  write("out/" + stale, "half an image");
  write("out/notes.txt", "mine");
  ASSERT_EQ(run_in_process(cmd), 0);
  EXPECT_FALSE(fs::exists(out / stale));
  EXPECT_TRUE(fs::exists(out / "notes.txt"));
  const std::vector<json> lines = results(out);
  ASSERT_EQ(lines.size(), 16u);
  for (std::size_t i = 8; i < 16; ++i)
    EXPECT_EQ(lines[i]["status"], lines[i]["output"] == lost ? "ok" : "skipped") << lines[i];

  // Another size changes every image: shard 0/2 and 1/2 re-render disjoint halves.
  cmd.size = "16x16";
  std::map<std::string, int> shard_of;
  for (int shard = 0; shard < 2; ++shard) {
    const std::size_t before = results(out).size();
    cmd.shard = std::to_string(shard) + "/2";
    ASSERT_EQ(run_in_process(cmd), 0);
    const std::vector<json> now = results(out);
    for (std::size_t i = before; i < now.size(); ++i) {
      EXPECT_EQ(now[i]["status"], "ok") << now[i];
      const std::string mesh = now[i]["mesh"];
      EXPECT_TRUE(shard_of.emplace(mesh, shard).second || shard_of[mesh] == shard)
          << mesh << " in two shards";
    }
  }
  EXPECT_EQ(shard_of.size(), 4u);  // every mesh in exactly one shard
  EXPECT_EQ(read_image(out / lost).width, 16);
}

// Bad usage in the program: exit 2, one line, nothing written. Every other usage error is an
// InputError too (the same path to exit 2), checked in process below.
TEST_F(Batch, BadUsageExitsTwoWithOneLineAndNoOutput) {
  write("m/a.off", kOctahedron);
  const fs::path out = dir_ / "out";
  const Outcome r = run("batch " + (dir_ / "m").string() + " -o " + out.string() + " --shard 2/2");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("--shard"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

// Each bad option, in process: an InputError naming it (exit 2 in the program, as above), and
// the output directory not even created.
TEST_F(Batch, EveryBadOptionIsAUsageError) {
  write("m/a.off", kOctahedron);
  write("explicit.json", R"({"camera": {"eye": [0, 0, 5], "target": [0, 0, 0]}})");
  fs::create_directories(dir_ / "empty");
  write("in_the_way", "a file");
  const BatchCommand good = command(1, "");
  const std::vector<std::pair<std::function<void(BatchCommand&)>, std::string>> cases = {
      {[](BatchCommand& c) { c.views = 0; }, "--views"},
      {[](BatchCommand& c) { c.views = 361; }, "--views"},
      {[](BatchCommand& c) { c.size = "64"; }, "--size"},
      {[](BatchCommand& c) { c.size = "0x8"; }, "--size"},
      {[](BatchCommand& c) { c.size = "8x99999"; }, "--size"},
      {[](BatchCommand& c) { c.format = "gif"; }, "--format"},
      {[](BatchCommand& c) { c.shard = "1/1"; }, "--shard"},
      {[](BatchCommand& c) { c.options.threads = -1; }, "--threads"},
      {[](BatchCommand& c) { c.options.method = static_cast<ShadingMethod>(99); }, "--method"},
      {[&](BatchCommand& c) { c.scene = (dir_ / "explicit.json").string(); }, "fit camera"},
      {[&](BatchCommand& c) { c.scene = (dir_ / "none.json").string(); }, "none.json"},
      {[&](BatchCommand& c) { c.inputs = {(dir_ / "m" / "a.off").string() + ".md"}; }, "a.off.md"},
      {[&](BatchCommand& c) { c.inputs = {(dir_ / "empty").string()}; }, "no mesh files"},
      {[&](BatchCommand& c) { c.outdir = (dir_ / "in_the_way").string(); }, "not a directory"},
  };
  for (const auto& [spoil, needle] : cases) {
    BatchCommand cmd = good;
    spoil(cmd);
    try {
      run_batch(cmd);
      ADD_FAILURE() << "accepted, expected an error naming " << needle;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(dir_ / "out")) << needle;
  }
}

// SIGINT while images are being written: the run stops (or had finished), and every image
// file in the directory is whole, with its ok line; no temp file is left; a rerun completes it.
TEST_F(Batch, InterruptLeavesOnlyWholeImagesAndResumes) {
  write("m/a.off", kOctahedron);
  const fs::path out = dir_ / "out";
  const std::string args = "batch " + (dir_ / "m").string() + " -o " + out.string() +
                           " --views 90 --size 16x16 --threads 2";
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const std::string cmd = "exec " + std::string(FASTSHADE_BINARY) + " " + args + " >/dev/null 2>&1";
    ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  // Signal once the first image is recorded (or the run ends); a bound keeps a hang finite.
  const auto recorded_one = [&] {
    std::error_code ec;
    const std::uintmax_t bytes = fs::file_size(out / "results.jsonl", ec);
    return !ec && bytes > 0;
  };
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  int status = 0;
  bool exited = false;
  while (!(exited = ::waitpid(pid, &status, WNOHANG) == pid) && !recorded_one() &&
         std::chrono::steady_clock::now() < give_up)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  if (!exited) {
    ::kill(pid, SIGINT);
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  }
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_TRUE(WEXITSTATUS(status) == 0 || WEXITSTATUS(status) == 128 + SIGINT) << WEXITSTATUS(status);

  std::set<std::string> recorded;
  for (const json& line : results(out)) {
    if (line["status"] == "ok") recorded.insert(line["output"].get<std::string>());
  }
  for (const std::string& name : images_in(out)) {
    EXPECT_NE(name[0], '.') << "temp file left: " << name;
    EXPECT_TRUE(recorded.count(name)) << name << " has no ok line";
    EXPECT_EQ(read_image(out / name).width, 16) << name;
  }
  EXPECT_EQ(run_in_process(command(90, "16x16")), 0);
  EXPECT_EQ(images_in(out).size(), 90u);
}

}  // namespace
}  // namespace fastshade
