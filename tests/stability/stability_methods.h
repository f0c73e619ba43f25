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

// `extra`'s method and threads are set here.
inline MethodConfig config(std::string label, ShadingMethod method, BoundRule rule, RenderOptions extra = {}) {
  extra.threads = 2;  // the CI machine's cores
  extra.method = method;
  return {std::move(label), extra, rule};
}

// The one method table. `reference` comes first: the others are compared with it.
inline const std::vector<MethodConfig>& method_configs() {
  static const std::vector<MethodConfig> configs = [] {
    using R = BoundRule;
    std::vector<MethodConfig> c = {
        config("reference", ShadingMethod::Reference, R::Yardstick),
        config("phong", ShadingMethod::Phong, R::PerPixelFloat),
        config("phong --normals adaptive", ShadingMethod::Phong, R::ErrorBudget, {.normals = PhongNormals::Adaptive}),
        config("phong --normals equal-angle", ShadingMethod::Phong, R::ErrorBudget, {.normals = PhongNormals::EqualAngle}),
        config("gouraud", ShadingMethod::Gouraud, R::VertexLighting),
        config("gouraud --gouraud sierpinski", ShadingMethod::Gouraud, R::VertexLighting, {.gouraud = GouraudMode::Sierpinski}),
        config("hybrid --max-error 0.5", ShadingMethod::Hybrid, R::ErrorBudget, {.max_error = 0.5}),
        config("hybrid --max-error 1", ShadingMethod::Hybrid, R::ErrorBudget, {.max_error = 1}),
        config("hybrid --max-error 2", ShadingMethod::Hybrid, R::ErrorBudget, {.max_error = 2}),
        config("hybrid --max-error 4", ShadingMethod::Hybrid, R::ErrorBudget, {.max_error = 4}),
        config("auto", ShadingMethod::Auto, R::Classified, {.max_error = 1}),
        config("auto --max-error 2", ShadingMethod::Auto, R::Classified, {.max_error = 2}),
    };
    for (const BrdfChoice& brdf : brdf_choices())
      if (brdf.kind != BrdfKind::Exact)
        c.push_back(config("phong --brdf " + option_name(brdf), ShadingMethod::Phong, R::PerPixelFloat, {.brdf = brdf}));
    return c;
  }();
  return configs;
}

}  // namespace fastshade::stability
