// `fastshade report`: its pure helpers (Pareto front, heat map, NaN suspects, progress line),
// its table of configurations, and the command on a tiny scene (files, columns, bad usage).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "app/heat_map.h"
#include "app/pareto.h"
#include "app/progress.h"
#include "app/report_configs.h"
#include "app/report_metrics.h"
#include "app/report_output.h"
#include "app/report_scenes.h"
#include "fastshade/error.h"
#include "fastshade/options.h"
#include "light/brdf.h"
#include "support/cli_fixture.h"

namespace fastshade {
namespace {

namespace fs = std::filesystem;

TEST(Pareto, HandMadeFront) {
  // time, error: a dominates d (faster and better); b and c trade; e ties a exactly; f is
  // faster than everything but worst; g has a NaN error; h equals b in time, worse in error.
  const TimeError points[] = {{10, 1},  {5, 4},   {20, 0}, {12, 2},
                              {10, 1},  {1, 100}, {3, NAN}, {5, 5}};
  const std::vector<bool> front = pareto_front(points);
  const std::vector<bool> expected = {true, true, true, false, true, true, false, false};
  EXPECT_EQ(front, expected);
}

TEST(Pareto, EmptyAndSingle) {
  EXPECT_TRUE(pareto_front({}).empty());
  const TimeError one[] = {{7, 3}};
  EXPECT_EQ(pareto_front(one), std::vector<bool>{true});
}

TEST(HeatMap, ColoursAtStopsAndPixelsByError) {
  EXPECT_EQ(heat_colour(1), (Rgb8{45, 75, 200}));
  EXPECT_EQ(heat_colour(64), (Rgb8{255, 255, 255}));
  EXPECT_EQ(heat_colour(255), heat_colour(64));
  EXPECT_NE(heat_colour(2), heat_colour(3));  // between stops: interpolated, not a step

  // Pixels: background exact, object exact, off by 3 in one channel, off by 200.
  const Image ref{4, 1, {9, 9, 9, 100, 50, 50, 100, 50, 50, 0, 0, 0}};
  const Image img{4, 1, {9, 9, 9, 100, 50, 50, 100, 53, 50, 200, 0, 0}};
  const Image map = error_heat_map(img, ref, Rgb8{9, 9, 9});
  ASSERT_EQ(map.rgb.size(), 12u);
  EXPECT_EQ((Rgb8{map.rgb[0], map.rgb[1], map.rgb[2]}), (Rgb8{0, 0, 0}));
  EXPECT_EQ((Rgb8{map.rgb[3], map.rgb[4], map.rgb[5]}), (Rgb8{48, 48, 48}));
  EXPECT_EQ((Rgb8{map.rgb[6], map.rgb[7], map.rgb[8]}), heat_colour(3));
  EXPECT_EQ((Rgb8{map.rgb[9], map.rgb[10], map.rgb[11]}), heat_colour(200));
  EXPECT_THROW(error_heat_map(Image{1, 1, {0, 0, 0}}, ref, Rgb8{}), InputError);
}

TEST(ReportMetrics, NanSuspectsAreZeroedVisibleChannels) {
  // A channel counts when it is 0 here and at least 2 LSB in the reference.
  const Image ref{2, 1, {2, 1, 0, 255, 3, 0}};
  const Image img{2, 1, {0, 0, 0, 0, 3, 0}};
  EXPECT_EQ(nan_suspect_channels(img, ref), 2);
  EXPECT_EQ(nan_suspect_channels(ref, ref), 0);
}

TEST(ReportMetrics, ErrorFiguresAgainstReference) {
  const Image ref{2, 1, {10, 10, 10, 20, 20, 20}};
  const Image img{2, 1, {10, 10, 10, 23, 20, 20}};
  const ErrorMetrics same = measure_error(ref, ref, 2);
  EXPECT_EQ(same.max_abs_lsb, 0);
  EXPECT_EQ(same.rmse_lsb, 0);
  EXPECT_TRUE(std::isinf(same.psnr_db));
  const ErrorMetrics m = measure_error(img, ref, 1);  // one covered pixel
  EXPECT_EQ(m.max_abs_lsb, 3);
  EXPECT_NEAR(m.rmse_lsb, std::sqrt(9.0 / 6.0), 1e-4);
  EXPECT_NEAR(m.pct_covered_over_1lsb, 100.0, 1e-9);  // 1 of 2 image pixels = the covered one
}

TEST(Progress, LineAndDurations) {
  EXPECT_EQ(format_duration(0), "0s");
  EXPECT_EQ(format_duration(59.4), "59s");
  EXPECT_EQ(format_duration(187), "3m07s");
  EXPECT_EQ(format_duration(3720), "1h02m");
  const std::string half = progress_line(5, 10, 70, "bunny.ply");
  EXPECT_NE(half.find(" 50%"), std::string::npos) << half;
  EXPECT_NE(half.find("ETA 1m10s"), std::string::npos) << half;
  EXPECT_NE(half.find("bunny.ply"), std::string::npos) << half;
  EXPECT_NE(progress_line(0, 10, -1, "").find("ETA ?"), std::string::npos);
}

bool table_has(std::string_view line) {
  for (std::string_view c : kReportConfigs)
    if (c == line) return true;
  return false;
}

TEST(ReportConfigs, TableCoversEveryOptionWorthKnowing) {
  for (const BrdfChoice& brdf : brdf_choices()) {
    if (brdf.kind != BrdfKind::Exact) {
      EXPECT_TRUE(table_has("phong --brdf " + option_name(brdf))) << option_name(brdf);
    }
  }
  for (const char* normals : {"adaptive", "equal-angle"})
    EXPECT_TRUE(table_has(std::string("phong --normals ") + normals)) << normals;
  for (const char* e : {"0.5", "1", "2", "4"})
    EXPECT_TRUE(table_has(std::string("hybrid --max-error ") + e)) << e;
  for (const char* line : {"reference", "phong", "gouraud", "gouraud --gouraud sierpinski", "auto"})
    EXPECT_TRUE(table_has(line)) << line;
}

TEST(ReportConfigs, ReferenceAndBaselineComeFirstOnce) {
  const std::vector<std::string> chosen = {"gouraud", "phong", "  hybrid   --max-error 2 ", "gouraud"};
  const std::vector<ReportConfig> c = configs_to_measure(chosen);
  ASSERT_EQ(c.size(), 4u);
  EXPECT_EQ(c[0].label, "reference");
  EXPECT_EQ(c[1].label, "phong");
  EXPECT_EQ(c[2].label, "gouraud");
  EXPECT_EQ(c[3].label, "hybrid --max-error 2");
  EXPECT_EQ(c[3].method, "hybrid");
  EXPECT_EQ(c[3].flags, (std::vector<std::string>{"--max-error", "2"}));
  EXPECT_EQ(configs_to_measure({}).size(), std::size(kReportConfigs));
  EXPECT_THROW(parse_config("   ", "--config"), InputError);
}

TEST(ReportScenes, DirectoriesExpandToScenesAndMeshesWithUniqueNames) {
  const fs::path dir = fs::temp_directory_path() / ("fastshade_report_scenes_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "sub");
  std::ofstream(dir / "b.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  std::ofstream(dir / "a.json") << "{}";
  std::ofstream(dir / "notes.txt") << "not a scene";
  std::ofstream(dir / "sub" / "a.json") << "{}";
  const std::vector<SceneInput> in = expand_scene_inputs({dir, dir / "sub" / "a.json"});
  ASSERT_EQ(in.size(), 3u);  // the .txt and the subdirectory are not inputs
  EXPECT_EQ(in[0].name, "a.json");
  EXPECT_FALSE(in[0].mesh);
  EXPECT_EQ(in[1].name, "b.obj");
  EXPECT_TRUE(in[1].mesh);
  EXPECT_EQ(in[2].name, "a.json#2");
  EXPECT_THROW(expand_scene_inputs({dir / "notes.txt"}), InputError);
  EXPECT_THROW(expand_scene_inputs({dir / "missing.json"}), InputError);

  // A bare mesh becomes a fit-camera scene.
  const Scene mesh = load_report_scene(in[1]);
  EXPECT_EQ(mesh.width, 1920);
  EXPECT_EQ(mesh.height, 1080);
  ASSERT_EQ(mesh.objects.size(), 1u);
  EXPECT_EQ(mesh.objects[0].mesh->triangles.size(), 1u);
  EXPECT_TRUE(mesh.two_sided);
  fs::remove_all(dir);
}

TEST(ReportScenes, FindsTheRepositoryScenesNearTheProgram) {
  // The test binary sits beside fastshade; in a build directory inside the repository (build/,
  // as tools/dev.sh makes it) scenes/ is one level up.
  const fs::path build_dir = fs::weakly_canonical(fs::path(FASTSHADE_BINARY).parent_path());
  if (build_dir.parent_path() != fs::weakly_canonical(FASTSHADE_SOURCE_DIR))
    GTEST_SKIP() << "build directory outside the source tree: " << build_dir;
  const fs::path scenes = find_near_program("scenes");
  ASSERT_FALSE(scenes.empty());
  EXPECT_TRUE(fs::exists(scenes / "default.json")) << scenes;
  EXPECT_TRUE(find_near_program("no_such_directory_anywhere_near").empty());
}

// The command itself, run as users run it.
class ReportCli : public test::CliFixture {
 protected:
  void SetUp() override {
    CliFixture::SetUp();
    // Tiny: 48x32, one sphere with a sharp highlight so gouraud misses it.
    write("tiny.json", R"({"image": {"width": 48, "height": 32},
      "camera": {"fit": true}, "lights": [{"direction": [0.3, 0.4, 1]}],
      "materials": {"m": {"diffuse": 0.6, "specular": 0.6, "shininess": 60}},
      "objects": [{"primitive": "icosphere", "subdivisions": 1}]})");
  }
  test::Outcome report(const std::string& args) { return run("report " + args + " </dev/null"); }
  void expect_usage_error(const std::string& args, const std::string& needle) {
    expect_bad_input("report " + args + " </dev/null", needle);
  }
};

TEST_F(ReportCli, TinySceneWritesRowsWithEveryColumn) {
  const fs::path out = dir_ / "out";
  const test::Outcome r = report((dir_ / "tiny.json").string() + " --out " + out.string() +
                       " --config gouraud --frames 1 --threads 1 --no-plots");
  ASSERT_EQ(r.exit_code, 0) << r.err;

  std::istringstream csv(test::slurp(out / "results.csv"));
  std::string header;
  std::getline(csv, header);
  std::string expected_header;
  for (const std::string& c : report_columns()) expected_header += (expected_header.empty() ? "" : ",") + c;
  EXPECT_EQ(header, expected_header);
  for (const char* column : {"median_ms", "speedup_vs_phong", "max_abs_lsb", "rmse_lsb", "psnr_db",
                             "pct_covered_over_1lsb", "nan_suspect_channels", "pareto_rmse", "machine",
                             "isa", "threads", "commit"})
    EXPECT_NE(header.find(column), std::string::npos) << column;
  int lines = 0;
  for (std::string line; std::getline(csv, line);) ++lines;
  EXPECT_EQ(lines, 3);  // reference, phong, gouraud

  const nlohmann::json j = nlohmann::json::parse(test::slurp(out / "results.json"));
  ASSERT_EQ(j["rows"].size(), 3u);
  const nlohmann::json& ref = j["rows"][0];
  EXPECT_EQ(ref["config"], "reference");
  EXPECT_EQ(ref["max_abs_lsb"].get<double>(), 0.0);
  EXPECT_EQ(ref["rmse_lsb"].get<double>(), 0.0);
  EXPECT_TRUE(ref["psnr_db"].is_null());  // +inf
  EXPECT_EQ(ref["nan_suspect_channels"].get<long long>(), 0);
  // The only exact configuration is on the front, unless another is exact too and faster.
  bool beaten = false;
  for (const auto& row : j["rows"])
    beaten = beaten || (row["rmse_lsb"].get<double>() == 0 && row["median_ms"] < ref["median_ms"]);
  EXPECT_EQ(ref["pareto_rmse"].get<bool>(), !beaten);
  EXPECT_EQ(j["rows"][1]["speedup_vs_phong"].get<double>(), 1.0);
  const nlohmann::json& gouraud = j["rows"][2];
  EXPECT_EQ(gouraud["config"], "gouraud");
  EXPECT_GT(gouraud["max_abs_lsb"].get<double>(), 1.0);
  EXPECT_GT(gouraud["median_ms"].get<double>(), 0.0);
  EXPECT_EQ(j["run"]["threads"], 1);
  EXPECT_FALSE(j["run"]["commit"].get<std::string>().empty());
  for (const auto& row : j["rows"]) EXPECT_EQ(row.size(), report_columns().size());

  // The worst configuration's heat map, written by fastshade; the summary names it.
  const std::string map = gouraud["heat_map"];
  EXPECT_TRUE(fs::exists(out / map)) << map;
  const std::string summary = test::slurp(out / "summary.md");
  EXPECT_NE(summary.find("| gouraud |"), std::string::npos);
  EXPECT_NE(summary.find(map), std::string::npos);
  EXPECT_NE(summary.find("No plots"), std::string::npos);  // --no-plots, and the summary says so
}

TEST_F(ReportCli, SeveralIsasGiveRowsAndSpeedUpsPerIsa) {
  const std::vector<Isa> isas = available_isas();
  if (isas.size() < 2) GTEST_SKIP() << "this CPU runs one ISA";
  const std::string first(option_name(isas.front())), last(option_name(isas.back()));
  const fs::path out = dir_ / "out";
  const test::Outcome r = report((dir_ / "tiny.json").string() + " --out " + out.string() + " --isa " + first +
                                 ",best --config gouraud --frames 1 --threads 1 --no-plots --heat-maps 1");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(test::slurp(out / "results.json"));
  EXPECT_EQ(j["run"]["isa"], first + "," + last);
  ASSERT_EQ(j["rows"].size(), 6u);  // reference, phong, gouraud on each
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(j["rows"][i]["isa"], i < 3 ? first : last) << i;
    if (j["rows"][i]["config"] == "phong") EXPECT_EQ(j["rows"][i]["speedup_vs_phong"].get<double>(), 1.0);
  }
  // Each ISA's heat map under its own name.
  EXPECT_NE(j["rows"][2]["heat_map"], j["rows"][5]["heat_map"]);
  EXPECT_TRUE(fs::exists(out / j["rows"][5]["heat_map"].get<std::string>()));
  const std::string summary = test::slurp(out / "summary.md");
  EXPECT_NE(summary.find("## Speed-up over phong by ISA"), std::string::npos);
  EXPECT_NE(summary.find("| configuration | " + first + " | " + last + " |"), std::string::npos);
  EXPECT_NE(summary.find(", ISA " + last), std::string::npos);
}

TEST_F(ReportCli, OnlyConfigurationsOfMissingMethodsOrFlagsAreSkipped) {
  const test::Outcome r = report("--list-configs");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::istringstream lines(r.out);
  int measured = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line.starts_with("measured")) ++measured;
    else EXPECT_TRUE(line.find("no method") != std::string::npos ||
                     line.find("not expected") != std::string::npos) << line;
  }
  EXPECT_GE(measured, 18);
}

TEST_F(ReportCli, BadUsageExitsTwoAndWritesNothing) {
  const std::string tiny = (dir_ / "tiny.json").string(), out = " --out " + (dir_ / "out").string();
  expect_usage_error(tiny + out + " --frames 0", "--frames");
  expect_usage_error(tiny + out + " --config nosuch", "nosuch");
  expect_usage_error(tiny + out + " --config \"phong --bogus 1\"", "--bogus");
  expect_usage_error(tiny + out + " --config \"phong --brdf nope\"", "--brdf");
  expect_usage_error((dir_ / "missing.json").string() + out, "missing.json");
  expect_usage_error(tiny + " --out " + tiny, "not a directory");
  expect_usage_error(tiny + out + " --isa scalar,scalar", "listed twice");
  expect_usage_error(tiny + out + " --isa scalar,nope", "--isa");
}

}  // namespace
}  // namespace fastshade
