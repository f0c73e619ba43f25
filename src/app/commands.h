// The program's subcommands; main.cpp only parses and dispatches.
#pragma once
#include <string>

#include "fastshade/render.h"

namespace fastshade {

struct RenderCommand {
  std::string scene;  // empty: the embedded default scene
  std::string output;
  std::string stats_path;
  int frames = 1;
  RenderOptions options;
};
int run_render(const RenderCommand& cmd);

int run_compare(const std::string& a, const std::string& b, bool json);
int run_info(const std::string& mesh, bool json);
int run_brdf_table(const std::string& isa);

// `fastshade bench scaling` (app/scaling.h): thread and tile sweep plus the load-balance model.
struct ScalingCommand {
  std::string scene;                   // empty: the embedded default scene
  int max_threads = 0;                 // 0: the hardware's threads and one more (oversubscribed)
  std::string tiles = "16,32,64,128";  // tile sizes, comma-separated
  int frames = 10;                     // timed frames per point, after one warm-up
  std::string method = "phong";
  std::string out_dir = ".";           // scaling.csv, scaling.json, scaling.png
  bool no_plot = false;                // skip scaling.png
};
int run_bench_scaling(const ScalingCommand& cmd);

}  // namespace fastshade
