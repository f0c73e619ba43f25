#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "classify/highlight_bound.h"
#include "core/limits.h"
#include "shade/hybrid.h"

namespace fastshade {

int hybrid_triangle_step(const PhongSpanInput& in, const TriangleNormals& tri, float tol) {
  constexpr int kBlock = limits::kSeedBlockPx;
  if (!(tol > 0)) return 1;
  // Along a row the interpolated q = n/w is affine, q(x) = q0 + g x, and the drawn normal is
  // u = q / |q|: u' = P_u g / |q| and u'' = -[u' (u.g) + u (u'.g) + u' (u.g)] / |q|, so
  // |u''| <= 3 |u'| |g| / |q|. Writing q = (sum beta_i / w_i) m with m = sum lambda_i n_i
  // (lambda: perspective-correct barycentrics), |q| >= min_i(1 / w_i) min |m|, a bound for
  // the whole triangle that holds where the normals nearly cancel too. Only g's part across
  // u turns u: with g = s a + r (a the normals' cone axis, half-angle h, r across a),
  // |P_u g| <= |s| sin h + |r|.
  const dvec3 n_d[3] = {dvec3(tri.n[0]), dvec3(tri.n[1]), dvec3(tri.n[2])};
  const double q_min = std::min({tri.inv_w[0], tri.inv_w[1], tri.inv_w[2]}) * min_length_over_triangle(n_d);
  if (!(q_min > 0.0)) return 1;
  const dvec3 g(in.n[0].gx, in.n[1].gx, in.n[2].gx);
  double g_across = glm::length(g);
  const dvec3 sum = n_d[0] + n_d[1] + n_d[2];
  if (glm::length(sum) > 0.0) {
    const dvec3 axis = glm::normalize(sum);
    const double cos_h = std::min({glm::dot(axis, n_d[0]), glm::dot(axis, n_d[1]), glm::dot(axis, n_d[2])});
    if (cos_h > 0.0) {
      const double s_axis = glm::dot(g, axis);
      g_across = std::min(g_across, std::abs(s_axis) * std::sqrt(std::max(0.0, 1.0 - cos_h * cos_h)) +
                                        glm::length(g - s_axis * axis));
    }
  }
  const double turn = g_across / q_min;          // |u'|, radians per pixel, at most
  const double stretch = glm::length(g) / q_min;  // |g| / |q|, at most
  if (!(turn > 0.0)) return kBlock;
  // The colour's second derivative along x: f = C(u), f'' = u'^T (d2C) u' + dC . u''.
  // Diffuse kd max(u.L, 0): |dC| <= kd, d2C = 0, plus a kink where the terminator crosses,
  // which linear interpolation misses by at most kd |u'| L / 4 (first order in L). Specular
  // ks c^n, c = u.H <= c_max: |dC| <= ks n c^(n-1), |d2C| <= ks n (n-1) c^(n-2); below
  // n = 2, c^n has unbounded curvature at c = 0: per pixel there.
  const MaterialConstants& m = *in.material;
  const double kd = std::max({m.kd.r, m.kd.g, m.kd.b}), ks = std::max({m.ks.r, m.ks.g, m.ks.b});
  const double n = m.shininess_d;
  double bend = 0.0, slope = 0.0, kink = 0.0;  // weights of |u'|^2, |dC| and the kink
  for (const LightView& light : in.shade->lights) {
    const double weight = std::max({light.color.r, light.color.g, light.color.b});
    glm::vec3 h = light.h_view;
    // A local viewer's H at the triangle's centre stands for all of it (H turns far less
    // than the normal across a triangle: it follows the view direction).
    if (in.shade->local_viewer) h = glm::normalize(light.l_view + glm::normalize(-tri.centre_view));
    const double c_max = std::min(max_dot_over_triangle(n_d, dvec3(h)), 1.0);
    if (ks > 0.0 && c_max > 0.0) {
      if (n < 2.0) return 1;
      bend += weight * ks * n * (n - 1.0) * std::pow(c_max, n - 2.0);
      slope += weight * ks * n * std::pow(c_max, n - 1.0);
    }
    slope += weight * kd;
    double lo = 1.0, hi = -1.0;
    for (const dvec3& ni : n_d) {
      lo = std::min(lo, glm::dot(ni, dvec3(light.l_view)));
      hi = std::max(hi, glm::dot(ni, dvec3(light.l_view)));
    }
    if (lo < 0.0 && hi > 0.0) kink += weight * kd;
  }
  const double second = bend * turn * turn + slope * 3.0 * turn * stretch;  // |f''| per px^2
  // A segment of L pixels errs by at most |f''| L^2 / 8 + kink |u'| L / 4.
  for (int step = kBlock; step >= 2; step /= 2)
    if (second * step * step / 8.0 + kink * turn * step / 4.0 <= tol) return step;
  return 1;
}

}  // namespace fastshade
