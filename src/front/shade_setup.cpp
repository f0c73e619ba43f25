#include "front/shade_setup.h"

#include <algorithm>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "classify/segment_step.h"
#include "core/limits.h"
#include "light/brdf.h"

namespace fastshade {

namespace {

// The most that the float kernels' rounding of N.H (limits.h kFloatNdotHError) can move this
// material's colour, in 8-bit steps: c^n turns an error e of c into n e at most.
double float_specular_error_lsb(const MaterialConstants& m, const std::vector<LightView>& lights) {
  double ks_light = 0;
  for (const LightView& light : lights)
    ks_light += std::max({light.color.r * m.ks.r, light.color.g * m.ks.g, light.color.b * m.ks.b});
  return 255.0 * ks_light * m.shininess_d * limits::kFloatNdotHError;
}

}  // namespace

ShadeConstants shade_constants(const Scene& scene, const ViewTransform& xf, const RenderOptions& c) {
  ShadeConstants k;
  k.ambient = scene.ambient;
  k.background = scene.background;
  k.local_viewer = scene.viewer == Viewer::Local;
  k.two_sided = scene.two_sided;
  k.srgb = c.srgb;
  k.brdf = c.brdf;
  k.hybrid_tolerance = hybrid_tolerance(c.max_error);
  k.normals = c.normals;
  const glm::mat3 view_rot(xf.view);  // lookAt is a rigid motion: its 3x3 is a rotation
  for (const Light& light : scene.lights) {
    LightView lv;
    lv.l_view = glm::normalize(light.space == LightSpace::World ? view_rot * light.direction
                                                                : light.direction);
    // A light straight behind the infinite viewer has no half vector: no highlight at all.
    const glm::vec3 h = lv.l_view + glm::vec3(0, 0, 1);
    lv.h_view = glm::length(h) > 1e-6f ? glm::normalize(h) : glm::vec3(0.0f);
    lv.color = light.color;
    k.lights.push_back(lv);
  }
  for (const Material& m : scene.materials) {
    MaterialConstants mc{m.diffuse, m.specular, static_cast<float>(m.shininess), m.shininess,
                         make_brdf(c.brdf, m.shininess)};
    // Only exact cos^n falls back: an approximation (--brdf) is the user's choice of error.
    mc.shade_in_double = c.brdf.kind == BrdfKind::Exact &&
                         float_specular_error_lsb(mc, k.lights) > limits::kFloatSpecularBudgetLsb;
    k.materials.push_back(mc);
  }
  return k;
}

}  // namespace fastshade
