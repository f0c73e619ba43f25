// The program's subcommands; main.cpp only parses and dispatches.
#pragma once
#include <string>
#include <vector>

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
  RenderOptions options;   // threads and method are the batch's flags
};
int run_batch(const BatchCommand& cmd);

int run_compare(const std::string& a, const std::string& b, bool json);
int run_info(const std::string& mesh, bool json);
int run_brdf_table(const std::string& isa);

}  // namespace fastshade
