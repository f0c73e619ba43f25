// `fastshade render --max-error E` without --method as users run it: it says what it picked, the
// stats carry the calibration, and the image it writes is within E of `reference`, measured
// apart from the calibration. Which candidate is fastest is timing and decides nothing here;
// only the budget's side of the choice is asserted.
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "support/cli_fixture.h"

namespace {

namespace fs = std::filesystem;
using fastshade::test::Outcome;
using fastshade::test::slurp;
using nlohmann::json;

// A coarse sphere over a torus (the fixture's 96x48 frame): Gouraud misses the highlights by
// tens of LSB, the cheap BRDF fits are off by several, phong by at most 1.
constexpr const char* kObjects = R"([{"primitive": "icosphere", "subdivisions": 1, "material": "m"},
  {"primitive": "torus", "major": 1.4, "minor": 0.2, "segments": 24, "sides": 8, "material": "m"}])";

class Calibration : public fastshade::test::CliFixture {
 protected:
  void SetUp() override {
    CliFixture::SetUp();
    scene_ = write("scene.json", scene_with(kObjects, 96)).string();
    image_ = dir_ / "out.png";
    stats_ = dir_ / "stats.json";
  }
  // Renders with --max-error `budget` (and `extra` flags); the calibration from --stats.
  json calibrated(const std::string& budget, const std::string& extra = "") {
    const Outcome r = run("render " + scene_ + " -o " + image_.string() + " --stats " + stats_.string() +
                          " --threads 1 --max-error " + budget + extra);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    out_ = r.out;
    const json stats = json::parse(slurp(stats_));
    EXPECT_TRUE(stats.contains("calibration")) << stats.dump(2);
    return stats.value("calibration", json::object());
  }
  // The candidate rows whose config is `config`.
  static json row(const json& calibration, const std::string& config) {
    for (const json& r : calibration["candidates"])
      if (r["config"] == config) return r;
    ADD_FAILURE() << "no candidate " << config << " in " << calibration.dump(2);
    return json::object();
  }
  std::string scene_;
  fs::path image_, stats_;
  std::string out_;
};

TEST_F(Calibration, PicksAConfigurationWithinTheBudgetAndSaysWhich) {
  const json c = calibrated("1");
  const std::string picked = c["picked"];
  // One line says it, before render's own summary line (and says so when the noise guard kept
  // render's default, which on this frame of tiny triangles is often as fast as the best).
  EXPECT_TRUE(out_.starts_with("calibration: picked " + picked + ": ") ||
              out_.starts_with("calibration: picked " + picked + " (render's default): "))
      << out_;
  EXPECT_NE(out_.find("(budget 1 LSB)"), std::string::npos) << out_;
  EXPECT_EQ(json::parse(slurp(stats_))["method"], picked.substr(0, picked.find(' ')));

  // Report's table without auto's lines, one hybrid at the budget, tune's auto grid.
  for (const char* config : {"reference", "phong", "phong --brdf schlick", "phong --normals equal-angle", "gouraud",
                             "gouraud --gouraud sierpinski", "hybrid --max-error 1",
                             "auto --spec-threshold 0.001961 --spec-method hybrid --max-error 1",
                             "auto --spec-threshold 0.001961 --spec-method phong --max-error 1"})
    row(c, config);
  int chosen = 0, defaults = 0;
  for (const json& r : c["candidates"]) {
    const std::string verdict = r["verdict"];
    EXPECT_EQ(r["config"].get<std::string>().find("--max-error 0.5"), std::string::npos) << r;
    defaults += r["default"].get<bool>();
    if (verdict.starts_with("over budget")) {
      EXPECT_GT(r["max_abs_lsb"].get<double>(), 1.0) << r;
      continue;
    }
    EXPECT_LE(r["max_abs_lsb"].get<double>(), 1.0) << r;
    EXPECT_EQ(r["frames"], 3) << r;  // timed; those over budget are not
    chosen += verdict == "chosen";
    if (verdict == "chosen") {
      EXPECT_EQ(r["config"], picked);
    }
  }
  EXPECT_EQ(chosen, 1);
  EXPECT_EQ(defaults, 1);
  EXPECT_TRUE(row(c, "gouraud")["verdict"].get<std::string>().starts_with("over budget")) << c.dump(2);
  EXPECT_EQ(c["width"], 96);
  EXPECT_EQ(c["height"], 48);
  EXPECT_EQ(c["max_error_lsb"], 1.0);

  // What was written is within the budget, measured apart from the calibration.
  EXPECT_LE(max_error_against_reference(scene_, image_), 1.0);
}

TEST_F(Calibration, TinyBudgetKeepsReferenceAccuracyAndSaysSo) {
  // The shipped default scene at 320x180: there every float kernel is 1 LSB off the
  // double-precision reference somewhere, and only the reference itself meets 0.01 LSB.
  json scene = json::parse(slurp(fs::path(FASTSHADE_SOURCE_DIR) / "scenes" / "default.json"));
  scene["image"]["width"] = 320;
  scene["image"]["height"] = 180;
  scene_ = write("default_320.json", scene.dump()).string();
  const json c = calibrated("0.01");
  EXPECT_EQ(row(c, c["picked"])["max_abs_lsb"], 0.0);
  if (c["picked"] == "reference") {
    EXPECT_EQ(c["within_budget"], 1);
    EXPECT_NE(out_.find("nothing else stays within 0.01 LSB: the closest, "), std::string::npos) << out_;
  }
  EXPECT_EQ(max_error_against_reference(scene_, image_), 0.0);
  // On the small scene a float kernel may be exact: then it is picked, and says so.
  scene_ = write("scene.json", scene_with(kObjects, 96)).string();
  calibrated("0.01");
  EXPECT_NE(out_.find(", max error 0 LSB (budget 0.01 LSB)"), std::string::npos) << out_;
  EXPECT_EQ(max_error_against_reference(scene_, image_), 0.0);
}

TEST_F(Calibration, HugeBudgetAdmitsEveryCandidateGouraudIncluded) {
  const json c = calibrated("255", " --tile 32 --srgb");
  for (const json& r : c["candidates"]) EXPECT_FALSE(r["verdict"].get<std::string>().starts_with("over")) << r;
  EXPECT_EQ(row(c, "gouraud")["frames"], 3);
  // The run keys reach the final frame and every candidate.
  EXPECT_EQ(json::parse(slurp(stats_))["tile"], 32);
  EXPECT_NE(c["picked_options"].get<std::string>().find("tile=32 isa=best srgb=on"), std::string::npos) << c;
  EXPECT_LE(max_error_against_reference(scene_ + " --tile 32 --srgb", image_), 255.0);
}

TEST_F(Calibration, WithAMethodMaxErrorKeepsItsPerMethodMeaning) {
  const fs::path config = write("c.json", R"({"options": {"method": "gouraud"}})");
  for (const std::string& flags : {std::string(" --method hybrid --max-error 2"), std::string(" --method auto --max-error 1"),
                                   " --config " + config.string() + " --max-error 2"}) {
    const Outcome r = run("render " + scene_ + " -o " + image_.string() + " --stats " + stats_.string() + flags);
    ASSERT_EQ(r.exit_code, 0) << flags << "\n" << r.err;
    EXPECT_EQ(r.out.find("calibration"), std::string::npos) << r.out;
    EXPECT_FALSE(json::parse(slurp(stats_)).contains("calibration")) << flags;
  }
}

TEST_F(Calibration, HelpSaysWhatMaxErrorDoesWithAndWithoutAMethod) {
  const Outcome r = run("render --help");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("Without --method (and --config): renders with the fastest configuration"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("with --method: the budget of auto, hybrid"), std::string::npos) << r.out;
}

TEST_F(Calibration, BadBudgetsAndMethodOptionsExitTwo) {
  const std::string render = "render " + scene_ + " -o " + image_.string() + " --max-error ";
  expect_bad_input(render + "-1", "--max-error: expected 0 to 255");
  expect_bad_input(render + "256", "--max-error: expected 0 to 255");
  expect_bad_input(render + "nan", "--max-error");
  expect_bad_input(render + "2 --brdf schlick", "--brdf: chosen by the calibration");
  expect_bad_input(render + "2 --spec-threshold 0.01", "--spec-threshold: chosen by the calibration");
}

}  // namespace
