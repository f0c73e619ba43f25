// Render flags read through the `render` subcommand's own parser (see commands.h).
#include <algorithm>

#include <CLI/CLI.hpp>

#include "app/commands.h"
#include "fastshade/error.h"

namespace fastshade {

RenderFlagsParser render_flags_parser(CLI::App& render_cli, RenderOptions& bound) {
  return [&render_cli, &bound](const std::vector<std::string>& flags) {
    bound = RenderOptions{};  // flags not given keep their defaults, not a previous line's
    // `render` requires an output; CLI11 reads its argument vector back to front.
    std::vector<std::string> args = {"--output", "unused.png"};
    args.insert(args.end(), flags.begin(), flags.end());
    std::reverse(args.begin(), args.end());
    try {
      render_cli.parse(args);
    } catch (const CLI::ParseError& e) {
      throw InputError("fastshade render", e.what());
    }
    return bound;
  };
}

}  // namespace fastshade
