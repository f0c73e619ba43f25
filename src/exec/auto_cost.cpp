#include "exec/auto_cost.h"

#include <algorithm>
#include <cmath>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "exec/exec_limits.h"

namespace fastshade {

bool auto_cost_applies(const Method& method, const Scene& scene, const RenderOptions& o) {
  return method.id == ShadingMethod::Auto && !scene.lights.empty() && o.classifier == ClassifierRule::Cost;
}

double sampled_triangle_px(const SceneGeometry& g, const ViewTransform& xf, const Viewport& vp) {
  const std::size_t total = g.triangles.size();
  if (total == 0) return 0.0;
  const std::size_t stride = std::max<std::size_t>(1, total / limits::kAutoCostSampleTriangles);
  double area_px = 0.0;
  std::size_t counted = 0;
  for (const ObjectRange& o : g.objects) {
    const glm::mat4 model_to_clip = xf.proj * xf.view * o.model;
    for (std::size_t t = o.first_triangle; t < std::size_t(o.first_triangle) + o.triangle_count; t += stride) {
      glm::dvec2 px[3];
      bool usable = true;
      for (int k = 0; k < 3 && usable; ++k) {
        const glm::vec4 clip = model_to_clip * glm::vec4(g.positions[g.triangles[t][k]], 1.0f);
        // Behind or at the eye (or not finite): the clipper's business, not an estimate's.
        usable = clip.w > 0.0f && std::isfinite(clip.x) && std::isfinite(clip.y);
        if (usable) {
          const WindowPx at = window_px(clip, 1.0 / static_cast<double>(clip.w), vp);
          px[k] = {at.x, at.y};
        }
      }
      if (!usable) continue;
      const double x_lo = std::min({px[0].x, px[1].x, px[2].x}), x_hi = std::max({px[0].x, px[1].x, px[2].x});
      const double y_lo = std::min({px[0].y, px[1].y, px[2].y}), y_hi = std::max({px[0].y, px[1].y, px[2].y});
      if (x_hi < 0.0 || y_hi < 0.0 || x_lo > vp.width || y_lo > vp.height) continue;
      // Either winding: a closed mesh's back faces are skipped, and its front faces have the
      // same spread of areas.
      const glm::dvec2 e1 = px[1] - px[0], e2 = px[2] - px[0];
      area_px += 0.5 * std::fabs(e1.x * e2.y - e1.y * e2.x);
      ++counted;
    }
  }
  return counted ? area_px / static_cast<double>(counted) : 0.0;
}

bool auto_classifies(Isa isa, double triangle_px) {
  for (const auto& [at, min_px] : limits::kAutoClassifyMinPx)
    if (at == isa) return triangle_px >= min_px;
  return true;  // an ISA without a measurement: the paper's way
}

}  // namespace fastshade
