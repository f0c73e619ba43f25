// The program's subcommands; main.cpp only parses and dispatches.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "fastshade/render.h"

namespace CLI {
class App;
}

namespace fastshade {

// Reads render flags ("--method", "hybrid", "--max-error", "2") into RenderOptions exactly as
// `fastshade render` would (--config included), so `report` knows every flag `render` knows.
// Throws InputError naming the flags for an unknown flag or a bad value; does not validate().
using RenderFlagsParser = std::function<RenderOptions(const std::vector<std::string>& flags)>;

struct RenderCommand {
  std::string scene;  // empty: the embedded default scene
  std::string output;
  std::string stats_path;
  int frames = 1;
  bool explain = false;  // print the classifier's plan and what was left out
  std::string aov;       // --aov list (app/aov_list.h); empty: colour only
  // --max-error without --method: render with the fastest configuration measured within
  // options.max_error on this scene (app/calibration.h), whose candidates `parse_render_flags` reads.
  bool calibrate = false;
  RenderFlagsParser parse_render_flags;
  RenderOptions options;
};
int run_render(const RenderCommand& cmd);

// fastshade batch (docs/BATCH.md): exit 0 if every image was rendered or skipped, 1 if some
// failed, 128 + signal if stopped by SIGINT/SIGTERM; InputError (exit 2) for bad usage.
struct BatchCommand {
  std::vector<std::string> inputs;  // mesh files, directories, list files
  std::string outdir;
  std::string scene;       // template scene file; empty: the embedded default template
  std::string size;        // "WxH"; empty: the template's image size
  int views = 1;
  std::string shard = "0/1";
  std::string format = "png";
  std::string aov;         // --aov list (app/aov_list.h); empty: colour only
  RenderOptions options;   // threads and method are the batch's flags
};
int run_batch(const BatchCommand& cmd);

int run_compare(const std::string& a, const std::string& b, bool json);
int run_info(const std::string& mesh, bool json);
int run_brdf_table(Isa isa);

// The options `render` runs with once `render_cli` has parsed: the flags given on the command
// line (bound to `from_flags`) over its --config file's options over the defaults. A --method
// given without classifying drops the config's auto-only keys. Throws InputError naming the
// config file and key for a bad config.
RenderOptions resolve_render_options(const CLI::App& render_cli, const RenderOptions& from_flags);

// Whether `render` was asked for error-budget rendering: --max-error given without --method or
// --config (either of which chooses the method, and --max-error then keeps its meaning for it).
// Throws InputError for a method option given with it (--brdf, --spec-threshold...: the
// calibration chooses those).
bool calibration_requested(const CLI::App& render_cli);

// The parser of the `render` subcommand, whose options are bound to `bound`.
RenderFlagsParser render_flags_parser(CLI::App& render_cli, RenderOptions& bound);

struct ReportCommand {
  std::vector<std::string> scenes;   // files or directories; empty: scenes/ and shared meshes
  std::string out = "report";        // output directory
  std::string models;                // shared meshes' directory for the default set
  std::vector<std::string> configs;  // "METHOD [FLAGS]"; empty: the whole table
  int threads = 0, frames = 5, heat_maps = 3;
  std::vector<Isa> isas = {Isa::Best};  // each measured in turn, phong's speed-up per ISA
  bool list_configs = false, no_plots = false;
  RenderFlagsParser parse_render_flags;
};
int run_report(const ReportCommand& cmd);

struct TuneCommand {
  std::vector<std::string> scenes;  // files or directories; empty: the repository's scenes/
  std::string output;               // the config file written
  double max_error = 1.0;           // budget: worst max error against reference, 8-bit steps
  double max_pct_over_1lsb = 100;   // budget: worst share of covered pixels > 1 LSB (100: none)
  double min_gain_pct = 3;          // the defaults are kept unless beaten by more (tune_rule.h)
  std::vector<std::string> methods = {"auto", "phong", "gouraud", "hybrid"};
  std::vector<int> tiles = {8, 16, 32, 64, 128, 256};
  std::vector<double> thresholds;   // auto's --spec-threshold values; empty: from max_error
  std::vector<std::string> spec_methods = {"hybrid", "phong"};
  std::vector<std::string> classifiers = {"cost"};
  std::vector<double> classify_min_pxs = {RenderOptions{}.classify_min_px};
  int threads = 0, frames = 20;
  Isa isa = Isa::Best;
};
// Prints the table; exit 0 with the config written, 1 if no candidate is within the budget.
int run_tune(const TuneCommand& cmd);

// `fastshade bench scaling` (app/scaling.h): thread and tile sweep plus the load-balance model.
struct ScalingCommand {
  std::string scene;                   // empty: the embedded default scene
  int max_threads = 0;                 // 0: the hardware's threads and one more (oversubscribed)
  std::string tiles = "16,32,64,128";  // tile sizes, comma-separated
  int frames = 10;                     // timed frames per point, after one warm-up
  ShadingMethod method = ShadingMethod::Phong;
  std::string out_dir = ".";           // scaling.csv, scaling.json, scaling.png
  bool no_plot = false;                // skip scaling.png
};
int run_bench_scaling(const ScalingCommand& cmd);

}  // namespace fastshade
