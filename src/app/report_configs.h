// The configurations `fastshade report` measures: ONE table, one line each, written as typed
// after `fastshade render --method` (the method's name, then its flags).
#pragma once
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "app/commands.h"
#include "fastshade/render.h"

namespace fastshade {

// A line whose method is not in list_methods() or whose flags `render` does not know is
// skipped and listed as such, so lines for methods still being built wait here and are measured
// as soon as the build has them. tests/app/report_test.cpp checks the table covers every
// --brdf and --normals and that only such lines are skipped.
inline constexpr std::string_view kReportConfigs[] = {
    "reference",  // the yardstick: every error is measured against it (always measured)
    "phong",      // the baseline of every speed-up (always measured)
    "phong --brdf cosk:1",
    "phong --brdf cosk:3",
    "phong --brdf schlick",
    "phong --brdf schlick-pow2",
    "phong --brdf quadratic",
    "phong --brdf quadratic-fit",
    "phong --brdf poly2",
    "phong --brdf poly3",
    "phong --normals adaptive",
    "phong --normals equal-angle",
    "gouraud",
    "gouraud --gouraud sierpinski",
    "hybrid --max-error 0.5",
    "hybrid --max-error 1",
    "hybrid --max-error 2",
    "hybrid --max-error 4",
    // The default, as its cost model decides per frame and ISA; then the classifier itself on
    // every frame (issue 4), at thresholds on ks max(N.H)^n of the default (half an 8-bit
    // step, 1/510), 0 (specular path everywhere), then 1, 2 and 4 steps.
    "auto",
    "auto --classifier bound",
    "auto --classifier bound --spec-threshold 0",
    "auto --classifier bound --spec-threshold 0.0039",
    "auto --classifier bound --spec-threshold 0.0078",
    "auto --classifier bound --spec-threshold 0.0157",
    "auto --classifier bound --spec-method phong",
    "auto --classifier paper",
};

inline constexpr std::string_view kReferenceConfig = "reference";
inline constexpr std::string_view kBaselineConfig = "phong";

struct ReportConfig {
  std::string label;               // the line as written, spaces normalised
  std::string method;              // its first word
  std::vector<std::string> flags;  // the rest, one argument each
};

// The method a configuration's first word names; none if this build has no such method.
std::optional<MethodDescription> find_method(std::string_view name);

// Splits a line at whitespace; throws InputError naming `where` if it is empty.
ReportConfig parse_config(std::string_view line, const std::string& where);

// The options `config` renders with: its flags read by `parse` exactly as `render` reads them
// after `--method`, then `run_settings` (what every configuration of a run shares: threads,
// ISA...), validated. Throws InputError saying why this build cannot run it: a method it does
// not have, a flag it does not know, a value it refuses.
RenderOptions config_options(const ReportConfig& config, const RenderFlagsParser& parse,
                             const std::function<void(RenderOptions&)>& run_settings);

// `chosen` (from --config) or else the whole table, with the reference and the baseline put
// first whether listed or not, and repeats dropped.
std::vector<ReportConfig> configs_to_measure(std::span<const std::string> chosen);

}  // namespace fastshade
