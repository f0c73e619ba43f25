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
  bool explain = false;  // print the classifier's plan and what was left out
  RenderOptions options;
};
int run_render(const RenderCommand& cmd);

int run_compare(const std::string& a, const std::string& b, bool json);
int run_info(const std::string& mesh, bool json);
int run_brdf_table(const std::string& isa);

}  // namespace fastshade
