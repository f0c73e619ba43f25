// `fastshade render --max-error E` without --method: the fastest configuration whose error
// against `reference` on this very scene stays within E, found by a quick calibration pass made
// of the machinery `report` and `tune` already have: report's table of configurations for the
// methods without a classifier, tune's grid for `auto`, tune's timing rounds and tune's rule.
// docs/TUNING.md, "Error-budget rendering".
#pragma once
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "app/tune_grid.h"
#include "app/tune_output.h"
#include "fastshade/render.h"
#include "fastshade/scene.h"

namespace fastshade {

// The options the user sets for every candidate alike (render config keys): how the frame is
// run and encoded, and the budget. The other method options are what the calibration chooses.
inline constexpr std::string_view kCalibrationRunKeys[] = {"threads", "tile", "isa", "srgb", "max_error"};
bool is_calibration_run_key(std::string_view key);

// Timed frames per candidate within the budget, after one warm-up round: a median of three
// takes one slow frame (another agent's burst) out, and keeps the pass a few seconds long on a
// 1080p mesh.
inline constexpr int kCalibrationFrames = 3;

struct Calibration {
  std::vector<Candidate> candidates;  // [0] is `reference`, the yardstick
  std::vector<int> frames;            // per candidate: frames behind its time (1: its error frame)
  TuneTable table;                    // one scene: the figures and tune's decision on them
  std::size_t picked = 0;
  int width = 0, height = 0;          // where the errors were measured: the scene's own size
  double seconds = 0;                 // the whole pass, wall clock
};

// What is measured: `reference`; report's table lines (kReportConfigs) of the methods without a
// classifier, each at run.max_error (hybrid's several budgets become one); tune's `auto` grid at
// run.max_error (its thresholds, both --spec-method) with render's defaults. Every candidate
// runs with run's kCalibrationRunKeys. Lines this build cannot run are left out. `baseline`
// receives the index of render's defaults (tune's noise guard keeps them).
std::vector<Candidate> calibration_candidates(const RenderOptions& run, const RenderFlagsParser& parse,
                                              std::size_t& baseline);

// Renders every candidate once against the reference at the scene's own size (an error measured
// smaller would not be the output's: hybrid's segments and Gouraud's triangles scale with it),
// times those within the budget in tune's rounds (kCalibrationFrames), and picks by tune's
// rule. `reference` is within any budget, so something is always picked. A progress bar goes
// to stderr when it is a terminal.
Calibration calibrate(const Scene& scene, const std::string& scene_name, const RenderOptions& run,
                      const RenderFlagsParser& parse);

// One line: what was picked, its time and error, and why it rather than another.
std::string calibration_summary(const Calibration& c);

// For render --stats: the budget, the rule, every candidate (time, frames, errors, verdict),
// fastest first, and the pick.
nlohmann::json calibration_json(const Calibration& c);

}  // namespace fastshade
