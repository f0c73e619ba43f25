#include "app/tune_grid.h"

#include <algorithm>
#include <string_view>
#include <utility>
#include <vector>

#include "app/format.h"
#include "fastshade/error.h"

namespace fastshade {

namespace {

// The largest --spec-threshold: a specular term is a colour, at most 1, so a threshold of 1
// already leaves every one out (validate() refuses more). Large budgets' thresholds stop here.
constexpr double kMaxSpecThreshold = 1.0;

// validate()'s flag, and the tune flag that lists its values.
constexpr std::pair<std::string_view, std::string_view> kListFlags[] = {
    {"--method", "--methods"},       {"--tile", "--tiles"},
    {"--spec-threshold", "--thresholds"}, {"--spec-method", "--spec-methods"},
    {"--classifier", "--classifiers"},   {"--classify-min-px", "--classify-min-pxs"}};

void validate_candidate(const Candidate& c) {
  try {
    validate(c.options);
  } catch (const InputError& e) {
    const std::string message = e.what();
    const std::size_t colon = message.find(": ");
    for (const auto& [flag, list] : kListFlags)
      if (message.compare(0, colon, flag) == 0)
        throw InputError(std::string(list), message.substr(colon + 2) + " (in \"" + c.label + "\")");
    throw;
  }
}

// The tile is named when the candidates differ in it.
std::string label_of(const RenderOptions& o, bool tiles_vary) {
  std::string label = std::string(option_name(o.method)) + (tiles_vary ? " --tile " + std::to_string(o.tile_px) : "");
  if (!method_classifies(o.method)) return label;
  label += " --spec-threshold " + format_double("%.4g", o.spec_threshold) + " --spec-method " +
           std::string(option_name(o.spec_method));
  if (o.classifier != RenderOptions{}.classifier) label += " --classifier " + std::string(option_name(o.classifier));
  if (o.classify_min_px != RenderOptions{}.classify_min_px)
    label += " --classify-min-px " + format_double("%.4g", o.classify_min_px);
  return label;
}

}  // namespace

std::size_t plan_candidates(const TuneCommand& cmd, const RenderOptions& base, std::vector<Candidate>& out) {
  std::vector<double> thresholds = cmd.thresholds;
  if (thresholds.empty())
    for (double k : kThresholdsPerBudget) thresholds.push_back(std::min(k * base.max_error / 255.0, kMaxSpecThreshold));
  const std::size_t first = out.size();
  const auto add = [&](const RenderOptions& o) {
    const bool seen = std::any_of(out.begin(), out.end(), [&](const Candidate& c) { return c.options == o; });
    if (!seen) out.push_back({"", o});
  };
  std::vector<ShadingMethod> methods;
  for (const std::string& name : cmd.methods) methods.push_back(parse_option<ShadingMethod>(name, "--methods"));
  // The classifier's lists are read only if a method classifies, as only such a method uses them.
  std::vector<SpecMethod> spec_methods;
  std::vector<ClassifierRule> classifiers;
  if (std::any_of(methods.begin(), methods.end(), method_classifies)) {
    for (const std::string& name : cmd.spec_methods)
      spec_methods.push_back(parse_option<SpecMethod>(name, "--spec-methods"));
    for (const std::string& name : cmd.classifiers)
      classifiers.push_back(parse_option<ClassifierRule>(name, "--classifiers"));
  }
  for (const ShadingMethod method : methods) {
    for (int tile : cmd.tiles) {
      RenderOptions o = base;
      o.method = method;
      o.tile_px = tile;
      if (!method_classifies(method)) {
        add(o);
        continue;
      }
      for (double threshold : thresholds)
        for (const SpecMethod spec_method : spec_methods)
          for (const ClassifierRule classifier : classifiers)
            for (double classify_min_px : cmd.classify_min_pxs) {
              // The paper's rule classifies every triangle whatever the bound: one candidate.
              if (classifier == ClassifierRule::Paper && classify_min_px != cmd.classify_min_pxs.front()) continue;
              o.spec_threshold = threshold;
              o.spec_method = spec_method;
              o.classifier = classifier;
              o.classify_min_px = classify_min_px;
              add(o);
            }
    }
  }
  add(base);
  const bool tiles_vary = std::any_of(out.begin() + first, out.end(),
                                      [&](const Candidate& c) { return c.options.tile_px != base.tile_px; });
  for (auto c = out.begin() + first; c != out.end(); ++c) {
    c->label = label_of(c->options, tiles_vary);
    validate_candidate(*c);
  }
  return static_cast<std::size_t>(
      std::find_if(out.begin(), out.end(), [&](const Candidate& c) { return c.options == base; }) - out.begin());
}

}  // namespace fastshade
