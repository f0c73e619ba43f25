#include "app/report_configs.h"

#include <algorithm>
#include <optional>
#include <sstream>

#include "fastshade/error.h"

namespace fastshade {

std::optional<MethodDescription> find_method(std::string_view name) {
  for (const MethodDescription& m : list_methods())
    if (m.name == name) return m;
  return std::nullopt;
}

ReportConfig parse_config(std::string_view line, const std::string& where) {
  std::istringstream words{std::string(line)};
  ReportConfig c;
  for (std::string w; words >> w;) (c.method.empty() ? c.method : c.flags.emplace_back()) = w;
  if (c.method.empty()) throw InputError(where, "empty configuration (expected e.g. \"hybrid --max-error 2\")");
  c.label = c.method;
  for (const std::string& f : c.flags) c.label += " " + f;
  return c;
}

RenderOptions config_options(const ReportConfig& config, const RenderFlagsParser& parse,
                             const std::function<void(RenderOptions&)>& run_settings) {
  if (!find_method(config.method)) throw InputError("--method", "no method '" + config.method + "' in this build");
  std::vector<std::string> flags = {"--method", config.method};
  flags.insert(flags.end(), config.flags.begin(), config.flags.end());
  RenderOptions options = parse(flags);
  run_settings(options);
  validate(options);
  return options;
}

std::vector<ReportConfig> configs_to_measure(std::span<const std::string> chosen) {
  std::vector<ReportConfig> out;
  const auto add = [&](std::string_view line) {
    ReportConfig c = parse_config(line, "--config");
    const bool seen = std::any_of(out.begin(), out.end(),
                                  [&](const ReportConfig& o) { return o.label == c.label; });
    if (!seen) out.push_back(std::move(c));
  };
  add(kReferenceConfig);
  add(kBaselineConfig);
  if (chosen.empty())
    for (std::string_view line : kReportConfigs) add(line);
  for (const std::string& line : chosen) add(line);
  return out;
}

}  // namespace fastshade
