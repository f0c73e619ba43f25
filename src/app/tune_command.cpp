// `fastshade tune`: measures a grid of render configurations (method x tile, and for `auto`
// x threshold x specular kernel x classifier) on a set of scenes, picks the fastest whose error
// stays within the budget (app/tune_rule.h), prints the table and writes the choice as a config
// file for `fastshade render --config`.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <system_error>

#include "app/build_info.h"
#include "app/commands.h"
#include "app/format.h"
#include "app/progress.h"
#include "app/report_metrics.h"
#include "app/report_scenes.h"
#include "app/timing_rounds.h"
#include "app/tune_grid.h"
#include "app/tune_output.h"
#include "fastshade/error.h"
#include "fastshade/atomic_file.h"
#include "fastshade/render_config.h"

namespace fastshade {

namespace fs = std::filesystem;

namespace {

constexpr int kMaxFrames = 1000;
// --min-gain above this would keep the defaults against a candidate twice as fast: a typo.
constexpr double kMaxGainPct = 100;

void check_config_output(const fs::path& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw InputError(path.string(), "is a directory (-o)");
  const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
  if (!fs::is_directory(dir, ec))
    throw InputError(path.string(), "directory '" + dir.string() + "' does not exist (-o)");
  if (::access(dir.c_str(), W_OK) != 0)
    throw InputError(path.string(), "directory '" + dir.string() + "' is not writable (-o)");
}

void check_usage(const TuneCommand& cmd) {
  if (cmd.frames < 1 || cmd.frames > kMaxFrames)
    throw InputError("--frames",
                     "expected 1 to " + std::to_string(kMaxFrames) + ", got " + std::to_string(cmd.frames));
  if (!(cmd.min_gain_pct >= 0 && cmd.min_gain_pct <= kMaxGainPct))
    throw InputError("--min-gain", "expected 0 to " + format_double("%g", kMaxGainPct) + " (%), got " +
                                       format_double("%g", cmd.min_gain_pct));
  if (!(cmd.max_pct_over_1lsb >= 0 && cmd.max_pct_over_1lsb <= 100))
    throw InputError("--max-pct-over-1lsb",
                     "expected 0 to 100, got " + format_double("%g", cmd.max_pct_over_1lsb));
  RenderOptions common;
  common.threads = cmd.threads;
  common.max_error = cmd.max_error;  // its range: validate() names --max-error
  validate(common);
  check_config_output(cmd.output);
}

// The config's keys: what was tuned and what it was measured with.
std::vector<std::string_view> tuned_keys(const RenderOptions& o) {
  std::vector<std::string_view> keys = {"method", "tile", "threads", "isa", "max_error"};
  if (method_classifies(o.method))
    for (const RenderConfigKey& key : kRenderConfigKeys)
      if (key.classifying_only) keys.push_back(key.key);
  return keys;
}

}  // namespace

int run_tune(const TuneCommand& cmd) {
  check_usage(cmd);
  const std::string isa_name(option_name(resolve_isa(cmd.isa)));  // refuses a bad --isa first
  RenderOptions defaults;
  defaults.threads = cmd.threads;
  defaults.isa = cmd.isa;
  defaults.max_error = cmd.max_error;
  std::vector<Candidate> candidates;
  const std::size_t default_candidate = plan_candidates(cmd, defaults, candidates);

  std::vector<fs::path> inputs(cmd.scenes.begin(), cmd.scenes.end());
  if (inputs.empty()) {
    const fs::path scenes = find_near_program("scenes");
    if (scenes.empty()) throw InputError("tune", "no scenes given and no scenes/ directory found near the program");
    inputs.push_back(scenes);
  }
  const std::vector<SceneInput> scene_inputs = expand_scene_inputs(inputs);
  if (scene_inputs.empty()) throw InputError("tune", "no scene or mesh files in the given directories");
  // Every scene is read before anything is rendered: a bad one stops the run at once.
  std::vector<Scene> scenes;
  double total_cost = 0;
  for (const SceneInput& in : scene_inputs) {
    scenes.push_back(load_report_scene(in));
    total_cost += ((cmd.frames + 1.0) * double(candidates.size()) + 1.0) * frame_cost(scenes.back());
  }

  TuneTable table;
  table.run = {cpu_model(), isa_name, build_commit(), utc_now(), 0, cmd.frames, load_average()};
  table.criteria = {cmd.max_error, cmd.max_pct_over_1lsb, cmd.min_gain_pct, default_candidate};
  std::vector<RenderOptions> options;
  for (const Candidate& c : candidates) options.push_back(c.options), table.labels.push_back(c.label);
  table.figures.resize(candidates.size());
  {
    Progress progress(total_cost, stderr, ::isatty(STDERR_FILENO) != 0);
    for (std::size_t s = 0; s < scenes.size(); ++s) {
      const std::string& name = scene_inputs[s].name;
      table.scene_names.push_back(name);
      table.scene_paths.push_back(scene_inputs[s].path.string());
      RenderOptions yardstick = options[default_candidate];
      yardstick.method = ShadingMethod::Reference;
      RenderStats reference_stats;
      const Image reference = render(scenes[s], yardstick, 1, &reference_stats);
      progress.advance(frame_cost(scenes[s]), name + ": reference");
      const std::vector<Measured> m = measure_in_rounds(name, scenes[s], options, table.labels, cmd.frames, progress);
      for (std::size_t c = 0; c < m.size(); ++c) {
        const ErrorMetrics e = measure_error(m[c].image, reference, reference_stats.covered_pixels);
        table.figures[c].push_back({median(m[c].total_ms), e.max_abs_lsb, e.pct_covered_over_1lsb});
      }
      table.run.threads = m[0].stats.threads;
    }
  }
  table.run.load_end = load_average();
  table.decision = decide_tuning(table.figures, table.scene_names, table.criteria);
  std::printf("%s", tune_table_markdown(table).c_str());
  if (!table.decision.chosen) {
    std::fprintf(stderr, "fastshade: tune: no candidate stays within the budget on every scene; %s not written\n",
                 cmd.output.c_str());
    return 1;
  }
  const TuneDecision& d = table.decision;
  const Candidate& chosen = candidates[*d.chosen];
  write_text_file(cmd.output, render_config_text(chosen.options, tuned_keys(chosen.options), tune_provenance(table)));
  if (d.chosen == d.fastest)
    std::printf("\n%s: %s, %.2f× the defaults' speed (geometric mean over the scenes)\n", cmd.output.c_str(),
                chosen.label.c_str(), speedup_vs_default(table, *d.chosen));
  else
    std::printf("\n%s: %s: the defaults, kept: the fastest within budget, %s, is only %.1f %% faster "
                "(--min-gain %g)\n",
                cmd.output.c_str(), chosen.label.c_str(), candidates[*d.fastest].label.c_str(), d.fastest_gain_pct,
                cmd.min_gain_pct);
  return 0;
}

}  // namespace fastshade
