#include "app/calibration.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iterator>

#include "app/format.h"
#include "app/progress.h"
#include "app/report_configs.h"
#include "app/report_metrics.h"
#include "app/timing_rounds.h"
#include "app/tune_rule.h"
#include "fastshade/error.h"
#include "fastshade/render_config.h"

namespace fastshade {

namespace {

constexpr std::string_view kBudgetFlag = "--max-error";

constexpr const char* kRule =
    "every candidate renders one frame at the scene's own size, measured against reference; those "
    "whose max error stays within the budget are timed in interleaved rounds (one warm-up, then the "
    "median of timed_frames) and the fastest is picked, unless render's defaults (auto at this "
    "budget) are within it and the fastest beats them by no more than tune's min_gain_pct "
    "(docs/TUNING.md)";

void apply_run_keys(const RenderOptions& run, RenderOptions& o) {
  for (const RenderConfigKey& key : kRenderConfigKeys)
    if (is_calibration_run_key(key.key)) copy_option(key, run, o);
}

// Whether --max-error changes what `o` renders (render.h: auto, hybrid, --normals adaptive),
// and so belongs in its label.
bool budget_applies(const RenderOptions& o) {
  return o.method == ShadingMethod::Hybrid || method_classifies(o.method) || o.normals == PhongNormals::Adaptive;
}

std::string with_budget(const std::string& label, const RenderOptions& o) {
  return budget_applies(o) ? label + " " + std::string(kBudgetFlag) + " " + format_double("%g", o.max_error) : label;
}

std::size_t count_within(const TuneDecision& d) {
  return static_cast<std::size_t>(std::count_if(d.verdicts.begin(), d.verdicts.end(),
                                                [](const Verdict& v) { return v.rejected_because.empty(); }));
}

}  // namespace

bool is_calibration_run_key(std::string_view key) {
  return std::find(std::begin(kCalibrationRunKeys), std::end(kCalibrationRunKeys), key) != std::end(kCalibrationRunKeys);
}

std::vector<Candidate> calibration_candidates(const RenderOptions& run, const RenderFlagsParser& parse,
                                              std::size_t& baseline) {
  std::vector<Candidate> out;
  for (ReportConfig config : configs_to_measure({})) {  // reference first
    const std::optional<MethodDescription> method = find_method(config.method);
    if (method && method->classifies) continue;  // auto: tune's grid, below
    // The line's own budget goes: every candidate runs at the user's.
    for (auto f = config.flags.begin(); f != config.flags.end();)
      f = *f == kBudgetFlag && f + 1 != config.flags.end() ? config.flags.erase(f, f + 2) : f + 1;
    std::string label = config.method;
    for (const std::string& flag : config.flags) label += " " + flag;
    RenderOptions options;
    try {
      options = config_options(config, parse, [&](RenderOptions& o) { apply_run_keys(run, o); });
    } catch (const InputError&) {
      continue;  // not in this build, as report skips it
    }
    if (std::none_of(out.begin(), out.end(), [&](const Candidate& c) { return c.options == options; }))
      out.push_back({with_budget(label, options), options});
  }
  TuneCommand grid;
  grid.methods = {"auto"};
  grid.tiles = {run.tile_px};
  RenderOptions defaults;
  apply_run_keys(run, defaults);
  const std::size_t first_auto = out.size();
  baseline = plan_candidates(grid, defaults, out);
  for (std::size_t i = first_auto; i < out.size(); ++i) out[i].label = with_budget(out[i].label, out[i].options);
  return out;
}

Calibration calibrate(const Scene& scene, const std::string& scene_name, const RenderOptions& run,
                      const RenderFlagsParser& parse) {
  const auto start = std::chrono::steady_clock::now();
  Calibration c;
  std::size_t baseline = 0;
  c.candidates = calibration_candidates(run, parse, baseline);
  c.width = scene.width;
  c.height = scene.height;
  const std::size_t n = c.candidates.size();
  TuneTable& table = c.table;
  table.criteria = {.max_abs_lsb = run.max_error, .min_gain_pct = TuneCommand{}.min_gain_pct, .baseline = baseline};
  table.scene_names = {scene_name};
  for (const Candidate& candidate : c.candidates) table.labels.push_back(candidate.label);
  table.figures.assign(n, std::vector<SceneFigures>(1));
  c.frames.assign(n, 1);

  const double cost = frame_cost(scene);
  const bool terminal = ::isatty(STDERR_FILENO) != 0;
  Progress progress(cost * double(n) * (kCalibrationFrames + 2), terminal ? stderr : nullptr, terminal);
  // Every candidate once, the reference (candidate 0) first: the errors, deterministic.
  Image reference;
  long long covered_px = 0;
  for (std::size_t i = 0; i < n; ++i) {
    Renderer renderer(scene, c.candidates[i].options);
    StageTimes t;
    const Image image = renderer.render_frame(&t);
    if (i == 0) reference = image, covered_px = renderer.last_stats().covered_pixels;
    const ErrorMetrics e = measure_error(image, reference, covered_px);
    table.figures[i][0] = {t.total, e.max_abs_lsb, e.pct_covered_over_1lsb};
    progress.advance(cost, scene_name + " error: " + c.candidates[i].label);
  }
  // Those within the budget: their times, as tune takes them.
  const TuneDecision by_error = decide_tuning(table.figures, table.scene_names, table.criteria);
  std::vector<std::size_t> within;
  std::vector<RenderOptions> options;
  std::vector<std::string> labels;
  for (std::size_t i = 0; i < n; ++i)
    if (by_error.verdicts[i].rejected_because.empty())
      within.push_back(i), options.push_back(c.candidates[i].options), labels.push_back(c.candidates[i].label);
  progress.set_total(cost * (double(n) + double(within.size()) * (kCalibrationFrames + 1)));
  const std::vector<Measured> m = measure_in_rounds(scene_name, scene, options, labels, kCalibrationFrames, progress);
  for (std::size_t k = 0; k < within.size(); ++k) {
    table.figures[within[k]][0].median_ms = median(m[k].total_ms);
    c.frames[within[k]] = kCalibrationFrames;
  }
  progress.finish();
  table.decision = decide_tuning(table.figures, table.scene_names, table.criteria);
  c.picked = table.decision.chosen.value_or(0);  // never empty: the reference is within any budget
  c.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return c;
}

std::string calibration_summary(const Calibration& c) {
  const TuneDecision& d = c.table.decision;
  const TuneCriteria& budget = c.table.criteria;
  const SceneFigures& picked = c.table.figures[c.picked][0];
  const std::string lsb = format_double("%g", budget.max_abs_lsb) + " LSB";
  std::string line = "calibration: picked " + c.candidates[c.picked].label +
                     (c.picked == budget.baseline ? " (render's default)" : "") + ": " +
                     format_double("%.2f", picked.median_ms) + " ms, max error " +
                     format_double("%g", picked.max_abs_lsb) + " LSB (budget " + lsb + ")";
  if (d.fastest && d.fastest != d.chosen)
    line += "; the fastest within budget, " + c.candidates[*d.fastest].label + ", is only " +
            format_double("%.1f", d.fastest_gain_pct) + " % faster (noise guard " +
            format_double("%g", budget.min_gain_pct) + " %)";
  const std::size_t within = count_within(d);
  if (within == 1) {  // the reference alone: say how far the closest other one is
    std::size_t closest = c.picked;
    for (std::size_t i : d.fastest_first)
      if (i != c.picked && (closest == c.picked || d.verdicts[i].worst_max_abs_lsb < d.verdicts[closest].worst_max_abs_lsb))
        closest = i;
    if (closest != c.picked)
      line += "; nothing else stays within " + lsb + ": the closest, " + c.candidates[closest].label +
              ", is off by " + format_double("%g", d.verdicts[closest].worst_max_abs_lsb) + " LSB";
  }
  return line + "; " + std::to_string(within) + " of " + std::to_string(c.candidates.size()) +
         " candidates within budget at " + std::to_string(c.width) + "x" + std::to_string(c.height) +
         ", median of " + std::to_string(kCalibrationFrames) + " frames, " + format_double("%.1f", c.seconds) +
         " s";
}

nlohmann::json calibration_json(const Calibration& c) {
  const TuneDecision& d = c.table.decision;
  nlohmann::json rows = nlohmann::json::array();
  for (std::size_t i : d.fastest_first) {
    const SceneFigures& f = c.table.figures[i][0];
    rows.push_back({{"config", c.candidates[i].label},
                    {"median_ms", f.median_ms},
                    {"frames", c.frames[i]},
                    {"max_abs_lsb", f.max_abs_lsb},
                    {"pct_covered_over_1lsb", f.pct_covered_over_1lsb},
                    {"default", i == c.table.criteria.baseline},
                    {"verdict", verdict_text(c.table, i)}});
  }
  return {{"max_error_lsb", c.table.criteria.max_abs_lsb},
          {"min_gain_pct", c.table.criteria.min_gain_pct},
          {"width", c.width},
          {"height", c.height},
          {"timed_frames", kCalibrationFrames},
          {"seconds", c.seconds},
          {"rule", kRule},
          {"picked", c.candidates[c.picked].label},
          {"picked_options", c.candidates[c.picked].options.to_string()},
          {"within_budget", count_within(d)},
          {"candidates", rows}};
}

}  // namespace fastshade
