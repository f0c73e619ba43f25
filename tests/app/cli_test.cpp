// The program as users run it: bad input of every kind gives one line on stderr naming the
// file and the problem, exit code 2, and no output file; good input gives an image and stats.
#include <gtest/gtest.h>

#include <set>

#include <nlohmann/json.hpp>

#include "fastshade/image.h"
#include "support/cli_fixture.h"

namespace {

namespace fs = std::filesystem;
using fastshade::test::Outcome;
using fastshade::test::slurp;

class Cli : public fastshade::test::CliFixture {};

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

TEST_F(Cli, HybridStatsCountSegmentPlans) {
  const fs::path out = dir_ / "hybrid.png", stats = dir_ / "stats.json";
  const Outcome r = run("render -o " + out.string() + " --method hybrid --stats " + stats.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto segments = nlohmann::json::parse(slurp(stats))["hybrid_segments"];
  EXPECT_EQ(segments["length_px"], nlohmann::json({1, 2, 4, 8, 16}));
  ASSERT_EQ(segments["triangles"].size(), 5u);
  long long listed = 0;
  for (const auto& count : segments["triangles"]) listed += count.get<long long>();
  EXPECT_GT(listed, 0);
  EXPECT_LE(segments["split_light"].get<long long>(), listed);
  EXPECT_LE(segments["no_specular"].get<long long>(), listed);
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

// The program loads OpenImageIO only for a format other than PNG (src/io/image_codec.h): linked
// in, its 250 libraries cost every start 0.3 s. LD_DEBUG=files names each library the loader
// opens; a PNG render opens none of OpenImageIO's, a TIFF render opens the plugin.
TEST_F(Cli, PngNeedsNoOpenImageIoAndOtherFormatsLoadIt) {
  // What the loader opened while rendering to `file`.
  const auto libraries_opened = [&](const std::string& file) {
    const fs::path log = dir_ / "ld.txt";
    const std::string cmd = "LD_DEBUG=files " + std::string(FASTSHADE_BINARY) + " render -o " + (dir_ / file).string() +
                            " >/dev/null 2>" + log.string();
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    return slurp(log);
  };
  const std::string png = libraries_opened("a.png");
  EXPECT_NE(png.find("libtbb"), std::string::npos) << "LD_DEBUG printed no library";
  EXPECT_EQ(png.find("libOpenImageIO"), std::string::npos);
  EXPECT_EQ(png.find("libfastshade_oiio"), std::string::npos);
  const std::string tif = libraries_opened("a.tif");
  EXPECT_NE(tif.find("libfastshade_oiio"), std::string::npos);
  EXPECT_NE(tif.find("libOpenImageIO"), std::string::npos);
  EXPECT_EQ(fastshade::read_image(dir_ / "a.png").rgb, fastshade::read_image(dir_ / "a.tif").rgb);  // the same pixels either way
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

TEST_F(Cli, BenchScalingWritesCsvJsonAndTables) {
  const fs::path scene = write("s.json", scene_with(R"([{"primitive": "icosphere"}])"));
  const fs::path out = dir_ / "results";  // created by the run
  const Outcome r = run("bench scaling " + scene.string() + " --max-threads 2 --tiles 16,8 --frames 2 "
                        "--no-plot --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("load-balance model"), std::string::npos) << r.out;
  EXPECT_EQ(listing(), (std::set<std::string>{"results", "s.json"}));
  // CSV: a header and one row per tile size and thread count, tiles ascending.
  std::istringstream csv(slurp(out / "scaling.csv"));
  std::vector<std::string> lines;
  for (std::string line; std::getline(csv, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 5u) << slurp(out / "scaling.csv");
  EXPECT_EQ(lines[0].rfind("scene,method,width,height,tile,threads,", 0), 0u) << lines[0];
  EXPECT_NE(lines[1].find(",8,1,0,2,"), std::string::npos) << lines[1];
  EXPECT_NE(lines[4].find(",16,2,0,2,"), std::string::npos) << lines[4];
  const auto j = nlohmann::json::parse(slurp(out / "scaling.json"));
  ASSERT_EQ(j["points"].size(), 4u);
  for (const auto& p : j["points"]) {
    for (const char* stage : {"front_end", "binning", "raster_shade", "total"})
      EXPECT_GT(p["median_ms"][stage].get<double>(), 0.0) << stage;
    if (p["threads"] == 1) {
      EXPECT_DOUBLE_EQ(p["speedup"]["total"].get<double>(), 1.0);
    }
  }
  ASSERT_EQ(j["model"].size(), 2u);
  for (const auto& m : j["model"]) {
    ASSERT_EQ(m["predictions"].size(), 7u);
    EXPECT_EQ(m["predictions"][0]["workers"], 1);
    EXPECT_EQ(m["predictions"][6]["workers"], 64);
    EXPECT_DOUBLE_EQ(m["predictions"][0]["speedup"].get<double>(), 1.0);
    EXPECT_LE(m["critical_path_ms"].get<double>(), m["predictions"][6]["total_ms"].get<double>() + 1e-9);
  }
}

TEST_F(Cli, BenchScalingPlotsOrSaysHowTo) {
  const fs::path scene = write("s.json", scene_with(R"([{"primitive": "icosphere"}])"));
  const Outcome r = run("bench scaling " + scene.string() + " --max-threads 1 --tiles 16 --frames 1 "
                        "--out " + dir_.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir_ / "scaling.png") ||
              r.err.find("apt-get install python3-matplotlib") != std::string::npos)
      << r.err;
  EXPECT_TRUE(fs::exists(dir_ / "scaling.csv"));
}

TEST_F(Cli, BenchScalingRefusesBadUsage) {
  const fs::path scene = write("s.json", scene_with(R"([{"primitive": "icosphere"}])"));
  const std::string base = "bench scaling " + scene.string() + " --frames 1 --no-plot --out " + dir_.string();
  expect_bad_input(base + " --tiles 48", "--tiles");
  expect_bad_input(base + " --tiles 8,,16", "--tiles");
  expect_bad_input(base + " --tiles 512", "--tiles");
  expect_bad_input(base + " --max-threads -1", "--max-threads");
  expect_bad_input(base + " --max-threads 5000", "--max-threads");
  expect_bad_input(base + " --frames 0", "--frames");
  expect_bad_input(base + " --method nope", "--method");
  expect_bad_input("bench scaling " + (dir_ / "missing.json").string() + " --no-plot --out " + dir_.string(),
                   "missing.json");
  expect_bad_input("bench scaling " + scene.string() + " --out " + scene.string(), "not a directory");
  expect_bad_input("bench scaling " + scene.string() + " --out " + (dir_ / "a" / "b").string(), "does not exist");
  expect_bad_input("bench", "subcommand");
}

}  // namespace
