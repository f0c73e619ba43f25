#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "classify/highlight_bound.h"
#include "core/limits.h"
#include "shade/fast_math.h"
#include "shade/hybrid.h"

namespace fastshade {

int hybrid_triangle_step(const PhongSpanInput& in, const TriangleNormals& tri, float tol) {
  constexpr int kBlock = limits::kSeedBlockPx;
  if (!(tol > 0)) return 1;
  // The interpolated vector q = n/w is affine in screen space; its direction turns along x at
  // |dq/dx - (dq/dx . q^) q^| / |q| radians per pixel (only the part of dq/dx across q turns
  // it: w alone changes q's length, not its direction). The rate is smooth over a triangle:
  // its value at the vertices and the centre, with 25 % margin, stands for its maximum.
  const glm::vec3 dq_dx(in.n[0].gx, in.n[1].gx, in.n[2].gx);
  glm::vec3 q[4];
  for (int i = 0; i < 3; ++i) q[i] = tri.n[i] * tri.inv_w[i];
  q[3] = (q[0] + q[1] + q[2]) / 3.0f;
  float turn_per_px = 0.0f;
  for (const glm::vec3& qi : q) {
    const float len = glm::length(qi);
    if (!(len > 0.0f)) return 1;
    const glm::vec3 dir = qi / len;
    turn_per_px = std::max(turn_per_px, glm::length(dq_dx - glm::dot(dq_dx, dir) * dir) / len);
  }
  turn_per_px *= 1.25f;
  if (!(turn_per_px > 0.0f)) return kBlock;
  // Curvature of the colour in the normal's angle (shade/hybrid.h), over the triangle.
  const MaterialConstants& m = *in.material;
  const float kd = std::max({m.kd.r, m.kd.g, m.kd.b}), ks = std::max({m.ks.r, m.ks.g, m.ks.b});
  const float n = m.shininess;
  float curvature = 0.0f;
  for (const LightView& light : in.shade->lights) {
    const float weight = std::max({light.color.r, light.color.g, light.color.b});
    glm::vec3 h = light.h_view;
    // A local viewer's H at the triangle's centre stands for all of it (H turns far less
    // than the normal across a triangle: it follows the view direction).
    if (in.shade->local_viewer) h = glm::normalize(light.l_view + glm::normalize(-tri.centre_view));
    const dvec3 n_d[3] = {dvec3(tri.n[0]), dvec3(tri.n[1]), dvec3(tri.n[2])};
    const float c_max = static_cast<float>(max_dot_over_triangle(n_d, dvec3(h)));
    const float spec = c_max > 0.0f
                           ? n * fast_math::exp2(std::max(n - 2.0f, 0.0f) * fast_math::log2(c_max)) * (n + 1.0f)
                           : 0.0f;
    curvature += weight * (kd + ks * spec);
  }
  // A segment of `step` pixels turns by turn_per_px * step; its error is that squared / 8
  // times the curvature.
  for (int step = kBlock; step >= 2; step /= 2) {
    const float angle = turn_per_px * float(step);
    if (angle * angle / 8.0f * curvature <= tol) return step;
  }
  return 1;
}

}  // namespace fastshade
