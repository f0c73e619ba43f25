// The configurations the stability suite renders, one row each, and the rule that gives each
// its error bound against `reference` (docs/STABILITY.md, "Bounds"). Every case of the suite
// runs every row: a new method joins with one line in method_configs().
#pragma once
#include <string>
#include <vector>

#include "fastshade/render.h"
#include "light/brdf.h"

namespace fastshade::stability {

enum class BoundRule {
  Yardstick,       // reference: the comparison itself; analytic cases check it against closed forms
  PerPixelFloat,   // Blinn-Phong per pixel in float (phong, any --brdf): STABILITY.md "B1"
  ErrorBudget,     // honours --max-error E (hybrid, phong --normals adaptive | equal-angle): "B2"
  VertexLighting,  // lit vertices interpolated (gouraud): Lipschitz over the normals' spread, "B3"
  Classified,      // auto: its diffuse paths within E before rounding (docs/CLASSIFIER.md), its
                   // specular path B2; "B4"
};

struct MethodConfig {
  std::string label;  // as the table prints it: the command-line options
  RenderOptions options;
  BoundRule rule;
};

struct ConfigOptions {
  std::string brdf = "exact";
  std::string normals = "normalize";
  double max_error = 1.0;
  std::string gouraud = "increments";
};

inline MethodConfig config(std::string label, std::string method, BoundRule rule,
                           const ConfigOptions& extra = {}) {
  RenderOptions o;
  o.threads = 2;  // the CI machine's cores
  o.method = std::move(method);
  o.brdf = extra.brdf;
  o.normals = extra.normals;
  o.max_error = extra.max_error;
  o.gouraud = extra.gouraud;
  return {std::move(label), o, rule};
}

// The one method table. `reference` comes first: the others are compared with it.
inline const std::vector<MethodConfig>& method_configs() {
  static const std::vector<MethodConfig> configs = [] {
    using R = BoundRule;
    std::vector<MethodConfig> c = {
        config("reference", "reference", R::Yardstick),
        config("phong", "phong", R::PerPixelFloat),
        config("phong --normals adaptive", "phong", R::ErrorBudget, {.normals = "adaptive"}),
        config("phong --normals equal-angle", "phong", R::ErrorBudget, {.normals = "equal-angle"}),
        config("gouraud", "gouraud", R::VertexLighting),
        config("gouraud --gouraud sierpinski", "gouraud", R::VertexLighting, {.gouraud = "sierpinski"}),
        config("hybrid --max-error 0.5", "hybrid", R::ErrorBudget, {.max_error = 0.5}),
        config("hybrid --max-error 1", "hybrid", R::ErrorBudget, {.max_error = 1}),
        config("hybrid --max-error 2", "hybrid", R::ErrorBudget, {.max_error = 2}),
        config("hybrid --max-error 4", "hybrid", R::ErrorBudget, {.max_error = 4}),
        config("auto", "auto", R::Classified, {.max_error = 1}),
        config("auto --max-error 2", "auto", R::Classified, {.max_error = 2}),
    };
    for (const std::string& brdf : brdf_names())
      if (brdf != "exact") c.push_back(config("phong --brdf " + brdf, "phong", R::PerPixelFloat, {.brdf = brdf}));
    return c;
  }();
  return configs;
}

}  // namespace fastshade::stability
