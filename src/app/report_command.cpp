// `fastshade report`: every configuration of kReportConfigs on every scene, against `reference`,
// timed in interleaved rounds; writes results.csv/json, summary.md, plots and heat maps.
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>

#include "app/build_info.h"
#include "app/commands.h"
#include "app/heat_map.h"
#include "app/pareto.h"
#include "app/progress.h"
#include "app/report_configs.h"
#include "app/report_output.h"
#include "app/report_scenes.h"
#include "app/timing_rounds.h"
#include "fastshade/error.h"
#include "fastshade/atomic_file.h"

extern char** environ;

namespace fastshade {

namespace fs = std::filesystem;

namespace {

constexpr int kMaxFrames = 1000;
constexpr int kMaxHeatMaps = 100;
// tools/report_plots.py exits with this when matplotlib cannot be imported.
constexpr int kPlotsNoMatplotlib = 3;

struct PlannedConfig {
  ReportConfig config;
  RenderOptions options;
};

struct Plan {
  std::vector<PlannedConfig> configs;  // [0] reference, [1] phong
  std::vector<SkippedConfig> skipped;
};

// A table line this build cannot run is skipped; a --config line it cannot run is bad usage.
Plan plan_configs(const ReportCommand& cmd, Isa isa) {
  Plan plan;
  for (ReportConfig& c : configs_to_measure(cmd.configs)) {
    std::string why;
    RenderOptions options;
    try {
      options = config_options(c, cmd.parse_render_flags, [&](RenderOptions& o) {
        o.threads = cmd.threads;
        o.isa = isa;
      });
    } catch (const InputError& e) {
      why = e.what();
    }
    if (why.empty()) {
      plan.configs.push_back({std::move(c), options});
    } else if (!cmd.configs.empty() || plan.configs.size() < 2) {  // asked for, or reference/phong
      throw InputError("--config \"" + c.label + "\"", why);
    } else {
      plan.skipped.push_back({c.label, why});
    }
  }
  return plan;
}

// The output directory may exist (a directory) or be creatable in an existing one.
void check_out_dir(const fs::path& out) {
  std::error_code ec;
  if (fs::exists(out, ec)) {
    if (!fs::is_directory(out, ec)) throw InputError(out.string(), "exists and is not a directory (--out)");
    return;
  }
  const fs::path parent = out.has_parent_path() ? out.parent_path() : fs::path(".");
  if (!fs::is_directory(parent, ec))
    throw InputError(out.string(), "directory '" + parent.string() + "' does not exist (--out)");
  if (::access(parent.c_str(), W_OK) != 0)
    throw InputError(out.string(), "directory '" + parent.string() + "' is not writable (--out)");
}

// Scene and configuration names as file names: letters, digits, '.', '-', '_' only.
std::string file_stem(const std::string& name) {
  std::string s = name;
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '_') c = '_';
  return s;
}

// One scene's rows on one ISA, against that ISA's reference and phong.
std::vector<ReportRow> scene_rows(const std::string& name, const std::string& isa, const Plan& plan,
                                  const std::vector<Measured>& m) {
  const Measured& reference = m[0];
  const double phong_ms = median(m[1].total_ms);
  std::vector<ReportRow> rows;
  for (std::size_t i = 0; i < m.size(); ++i) {
    ReportRow r;
    r.scene = name;
    r.isa = isa;
    r.config = plan.configs[i].config.label;
    r.method = plan.configs[i].config.method;
    r.width = m[i].image.width;
    r.height = m[i].image.height;
    r.triangles = m[i].stats.triangles_in;
    r.covered_px = m[i].stats.covered_pixels;
    r.median_ms = median(m[i].total_ms);
    r.raster_shade_ms = median(m[i].raster_ms);
    r.speedup_vs_phong = phong_ms / r.median_ms;
    r.error = measure_error(m[i].image, reference.image, reference.stats.covered_pixels);
    rows.push_back(r);
  }
  std::vector<TimeError> by_rmse, by_max;
  for (const ReportRow& r : rows) {
    by_rmse.push_back({r.median_ms, r.error.rmse_lsb});
    by_max.push_back({r.median_ms, r.error.max_abs_lsb});
  }
  const std::vector<bool> front_rmse = pareto_front(by_rmse), front_max = pareto_front(by_max);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    rows[i].pareto_rmse = front_rmse[i];
    rows[i].pareto_max = front_max[i];
  }
  return rows;
}

Rgb8 background_rgb8(const Scene& scene) {
  Rgb8 out;
  for (int c = 0; c < 3; ++c)
    out[c] = static_cast<uint8_t>(std::clamp(scene.background[c], 0.0f, 1.0f) * 255.0f + 0.5f);
  return out;
}

// Heat maps of the `count` configurations with the largest RMSE among those off by more than
// 1 LSB somewhere (an error of one step is rounding, and its map says nothing). `suffix` tells
// the ISAs of one run apart ("" when there is one).
void write_heat_maps(const fs::path& out, const Scene& scene, std::vector<ReportRow>& rows,
                     const std::vector<Measured>& m, int count, const std::string& suffix) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (rows[i].error.max_abs_lsb > 1) order.push_back(i);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return rows[a].error.rmse_lsb > rows[b].error.rmse_lsb; });
  if (order.size() > static_cast<std::size_t>(count)) order.resize(count);
  for (std::size_t i : order) {
    const fs::path rel =
        fs::path("heatmaps") / (file_stem(rows[i].scene) + "--" + file_stem(rows[i].config) + suffix + ".png");
    fs::create_directories(out / rel.parent_path());
    write_image(error_heat_map(m[i].image, m[0].image, background_rgb8(scene)), out / rel);
    rows[i].heat_map = rel.string();
  }
}

// Runs `argv` and returns its exit code (127 if it could not be started).
int run_program(const std::vector<std::string>& argv) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid;
  if (posix_spawnp(&pid, args[0], nullptr, nullptr, args.data(), environ) != 0) return 127;
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return 127;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

// Draws the plots with tools/report_plots.py; returns "" or why there are none. Tries the
// python3 on PATH, then Debian's (python3-matplotlib installs there, and a PATH may put
// another Python first).
std::string draw_plots(const fs::path& out) {
  const fs::path script = find_near_program("tools") / "report_plots.py";
  if (!fs::is_regular_file(script))
    return "tools/report_plots.py was not found near the program; results.csv holds every figure.";
  bool python_found = false;
  for (const char* python : {"python3", "/usr/bin/python3"}) {
    const int code = run_program({python, script.string(), (out / "results.csv").string(), out.string()});
    if (code == 0) return "";
    if (code == 127) continue;
    python_found = true;
    if (code != kPlotsNoMatplotlib)
      return "the plot script failed (exit code " + std::to_string(code) + "); results.csv holds every figure.";
  }
  return python_found ? "matplotlib is not installed (Debian: apt-get install python3-matplotlib); "
                        "results.csv holds every figure."
                      : "python3 is not installed; results.csv holds every figure.";
}

}  // namespace

int run_report(const ReportCommand& cmd) {
  if (cmd.frames < 1 || cmd.frames > kMaxFrames)
    throw InputError("--frames", "expected 1 to " + std::to_string(kMaxFrames) + ", got " + std::to_string(cmd.frames));
  if (cmd.heat_maps < 0 || cmd.heat_maps > kMaxHeatMaps)
    throw InputError("--heat-maps", "expected 0 to " + std::to_string(kMaxHeatMaps) + ", got " +
                                        std::to_string(cmd.heat_maps));
  RenderOptions common;
  common.threads = cmd.threads;
  validate(common);
  // Each ISA the CPU can run, once (`best` is one of them), before anything else is read.
  std::vector<Isa> isas;
  std::string isa_names;
  for (const Isa asked : cmd.isas) {
    const Isa isa = resolve_isa(asked);
    if (std::find(isas.begin(), isas.end(), isa) != isas.end())
      throw InputError("--isa", "'" + std::string(option_name(isa)) + "' is listed twice");
    isas.push_back(isa);
    isa_names += (isa_names.empty() ? "" : ",") + std::string(option_name(isa));
  }
  if (isas.empty()) throw InputError("--isa", "expected at least one ISA");
  std::vector<Plan> plans;
  for (const Isa isa : isas) plans.push_back(plan_configs(cmd, isa));
  const Plan& plan = plans.front();  // the ISAs differ in their options' isa alone
  if (cmd.list_configs) {
    for (const PlannedConfig& p : plan.configs) std::printf("measured  %s\n", p.config.label.c_str());
    for (const SkippedConfig& s : plan.skipped) std::printf("skipped   %s  (%s)\n", s.config.c_str(), s.reason.c_str());
    return 0;
  }

  std::vector<fs::path> inputs(cmd.scenes.begin(), cmd.scenes.end());
  if (inputs.empty()) inputs = default_report_inputs(cmd.models);
  const std::vector<SceneInput> scene_inputs = expand_scene_inputs(inputs);
  if (scene_inputs.empty()) throw InputError("report", "no scene or mesh files in the given directories");
  const fs::path out = cmd.out;
  check_out_dir(out);
  // Every scene is read before anything is rendered or written: a bad one stops the run at once.
  std::vector<Scene> scenes;
  double total_cost = 0;
  for (const SceneInput& in : scene_inputs) {
    scenes.push_back(load_report_scene(in));
    total_cost += (cmd.frames + 1.0) * double(plan.configs.size() * isas.size()) * frame_cost(scenes.back());
  }
  fs::create_directories(out);

  RunInfo run{cpu_model(), isa_names, build_commit(), utc_now(), 0, cmd.frames, load_average()};
  std::vector<ReportRow> rows;
  {
    Progress progress(total_cost, stderr, ::isatty(STDERR_FILENO) != 0);
    for (std::size_t s = 0; s < scenes.size(); ++s)
      for (std::size_t i = 0; i < isas.size(); ++i) {
        const std::string& name = scene_inputs[s].name;
        const std::string isa(option_name(isas[i]));
        std::vector<RenderOptions> options;
        std::vector<std::string> labels;
        for (const PlannedConfig& p : plans[i].configs)
          options.push_back(p.options), labels.push_back(isas.size() > 1 ? p.config.label + " @" + isa : p.config.label);
        const std::vector<Measured> m = measure_in_rounds(name, scenes[s], options, labels, cmd.frames, progress);
        run.threads = m[0].stats.threads;
        std::vector<ReportRow> scene = scene_rows(name, isa, plans[i], m);
        const std::string suffix = isas.size() > 1 ? "--" + isa : "";
        write_heat_maps(out, scenes[s], scene, m, cmd.heat_maps, suffix);
        for (ReportRow& r : scene) r.plot = (fs::path("plots") / (file_stem(name) + suffix + ".png")).string();
        rows.insert(rows.end(), scene.begin(), scene.end());
      }
  }

  run.load_end = load_average();
  write_text_file(out / "results.csv", results_csv(run, rows));
  write_text_file(out / "results.json", results_json(run, rows, plan.skipped));
  std::string plots_note = "not asked for (--no-plots).";
  if (!cmd.no_plots) {
    fs::create_directories(out / "plots");
    plots_note = draw_plots(out);
  }
  if (!plots_note.empty()) {
    for (ReportRow& r : rows) r.plot.clear();
    if (!cmd.no_plots) std::fprintf(stderr, "fastshade: report: no plots: %s\n", plots_note.c_str());
  }
  write_text_file(out / "summary.md", summary_markdown(run, rows, plan.skipped, plots_note));
  std::printf("%s: %zu scenes x %zu configurations (%zu not in this build), median of %d frames, "
              "%d threads, %s\n",
              (out / "summary.md").string().c_str(), scenes.size(), plan.configs.size(),
              plan.skipped.size(), cmd.frames, run.threads, run.isa.c_str());
  return 0;
}

}  // namespace fastshade
