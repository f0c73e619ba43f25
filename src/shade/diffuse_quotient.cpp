// The diffuse quotient's set-up and its scalar twin (shade/diffuse_quotient.h).
#include "shade/diffuse_quotient.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "light/fast_math.h"
#include "shade/shade_limits.h"
#include "shade/span_kernels_testing.h"

namespace fastshade {

bool set_up_diffuse_quotient(const PhongSpanInput& in, const Barycentrics& bary, const PixelRect& box,
                             const glm::vec3 n_over_w[3], DiffuseQuotient& dq) {
  const ShadeConstants& k = *in.shade;
  if (k.lights.size() > static_cast<std::size_t>(limits::kDiffuseQuotientMaxLights)) return false;
  // The centre pixel and the box's half extents, in offsets from the anchor (exact integers).
  const int x0 = box.x0 - bary.ax, x1 = box.x1 - bary.ax, y0 = box.y0 - bary.ay, y1 = box.y1 - bary.ay;
  const int cx = x0 + (x1 - x0) / 2, cy = y0 + (y1 - y0) / 2;
  const double hx = std::max(cx - x0, x1 - cx), hy = std::max(cy - y0, y1 - cy);
  // m at the centre and its gradients, in double from the float planes: the quotient stands
  // for the very function the normal planes define.
  glm::dvec3 s, gx, gy;
  for (int c = 0; c < 3; ++c) {
    const Plane& p = in.n[c];
    s[c] = (double(p.v0) + double(p.gy) * cy) + double(p.gx) * cx;
    gx[c] = p.gx;
    gy[c] = p.gy;
  }
  double q_min = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) q_min = std::min(q_min, glm::dot(glm::dvec3(n_over_w[i]), glm::dvec3(n_over_w[j])));
  const double t = glm::length(s) + glm::length(gx) * hx + glm::length(gy) * hy;
  if (!(q_min > 0.0) || !(t * t <= limits::kDiffuseQuotientMaxTermRatio * q_min)) return false;
  dq.cx = static_cast<float>(cx);
  dq.cy = static_cast<float>(cy);
  const double q[6] = {glm::dot(s, s),   2.0 * glm::dot(s, gx), glm::dot(gx, gx),
                       2.0 * glm::dot(gx, gy), 2.0 * glm::dot(s, gy), glm::dot(gy, gy)};
  for (int i = 0; i < 6; ++i) dq.q[i] = static_cast<float>(q[i]);
  dq.lights = static_cast<int>(k.lights.size());
  for (int i = 0; i < dq.lights; ++i) {
    const glm::dvec3 l(k.lights[i].l_view);
    dq.l[i][0] = static_cast<float>(glm::dot(l, s));
    dq.l[i][1] = static_cast<float>(glm::dot(l, gx));
    dq.l[i][2] = static_cast<float>(glm::dot(l, gy));
  }
  return true;
}

PhongColor diffuse_quotient_color_scalar(const PhongSpanInput& in, const DiffuseQuotient& dq,
                                         const PixelOffsets& o) {
  const MaterialConstants& m = *in.material;
  const ShadeConstants& k = *in.shade;
  const float x = (o.block_dx + o.k) - dq.cx, y = o.dy - dq.cy;
  const float m2 = (dq.q[0] + x * ((dq.q[1] + dq.q[2] * x) + dq.q[3] * y)) + y * (dq.q[4] + dq.q[5] * y);
  const float inv = m2 >= fast_math::kMinInvSqrtInput ? fast_math::inv_sqrt(m2) : 0.0f;
  PhongColor rgb{{k.ambient.r, k.ambient.g, k.ambient.b}};
  for (int i = 0; i < dq.lights; ++i) {
    const float l_dot_m = (dq.l[i][0] + dq.l[i][1] * x) + dq.l[i][2] * y;
    const float diffuse = std::max(l_dot_m * inv, 0.0f);
    const LightView& light = k.lights[i];
    for (int c = 0; c < 3; ++c) rgb.c[c] = rgb.c[c] + light.color[c] * (m.kd[c] * diffuse);
  }
  return rgb;
}

}  // namespace fastshade
