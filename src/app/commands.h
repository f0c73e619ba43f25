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

struct RenderCommand {
  std::string scene;  // empty: the embedded default scene
  std::string output;
  std::string stats_path;
  int frames = 1;
  bool explain = false;  // print the classifier's plan and what was left out
  RenderOptions options;
};
int run_render(const RenderCommand& cmd);

int run_compare(const std::string& a, const std::string& b, bool json);
int run_info(const std::string& mesh, bool json);
int run_brdf_table(const std::string& isa);

// Reads render flags ("--method", "hybrid", "--max-error", "2") into RenderOptions exactly as
// `fastshade render` would, so `report` knows every flag `render` knows. Throws InputError
// naming the flags for an unknown flag or a bad value; does not validate().
using RenderFlagsParser = std::function<RenderOptions(const std::vector<std::string>& flags)>;
// The parser of the `render` subcommand, whose options are bound to `bound`.
RenderFlagsParser render_flags_parser(CLI::App& render_cli, RenderOptions& bound);

struct ReportCommand {
  std::vector<std::string> scenes;   // files or directories; empty: scenes/ and shared meshes
  std::string out = "report";        // output directory
  std::string models;                // shared meshes' directory for the default set
  std::vector<std::string> configs;  // "METHOD [FLAGS]"; empty: the whole table
  int threads = 0, frames = 5, heat_maps = 3;
  std::string isa = "best";
  bool list_configs = false, no_plots = false;
  RenderFlagsParser parse_render_flags;
};
int run_report(const ReportCommand& cmd);

}  // namespace fastshade
