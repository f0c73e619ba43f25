// Render flags read through the `render` subcommand's own parser, and its --config file
// (see commands.h).
#include <algorithm>

#include <CLI/CLI.hpp>

#include "app/calibration.h"
#include "app/commands.h"
#include "fastshade/error.h"
#include "fastshade/render_config.h"

namespace fastshade {

RenderOptions resolve_render_options(const CLI::App& render_cli, const RenderOptions& from_flags) {
  const CLI::Option* config_flag = render_cli.get_option("--config");
  if (config_flag->count() == 0) return from_flags;
  const RenderConfig config = load_render_config(config_flag->as<std::string>());
  const auto given = [&](const RenderConfigKey& key) {
    return render_cli.get_option(std::string(key.flag))->count() > 0;
  };
  RenderOptions options = config.options;
  for (const RenderConfigKey& key : kRenderConfigKeys)
    if (given(key)) copy_option(key, from_flags, options);
  // `--config tuned.json --method phong` compares the tuned frame with phong: the config's
  // keys for the classifier would make validate() refuse phong, so they go with its method.
  if (!method_classifies(options.method))
    for (const RenderConfigKey& key : kRenderConfigKeys)
      if (key.classifying_only && !given(key)) copy_option(key, RenderOptions{}, options);
  return options;
}

bool calibration_requested(const CLI::App& render_cli) {
  const auto given = [&](std::string_view flag) { return render_cli.get_option(std::string(flag))->count() > 0; };
  if (!given("--max-error") || given("--method") || given("--config")) return false;
  for (const RenderConfigKey& key : kRenderConfigKeys) {
    if (!is_calibration_run_key(key.key) && given(key.flag))
      throw InputError(std::string(key.flag), "chosen by the calibration that --max-error without --method runs; "
                                              "give --method to set it");
  }
  return true;
}

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
    return resolve_render_options(render_cli, bound);
  };
}

}  // namespace fastshade
