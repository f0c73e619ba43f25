#include "classify/segment_step.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/limits.h"
#include "frame/frame.h"

namespace fastshade {

namespace {

// How a local viewer's V (towards the eye) moves over the triangle: V_i at the vertices, the
// centre's, the largest angle from the centre's to a vertex's (the directions to a planar
// triangle's points form the spherical triangle of the V_i, so a vertex is farthest), and its
// turn along x: |q x dq/dx| / |q|^2 for q = p/w, affine like n/w, with |q| = |p| / w >= 1
// (w = -z), so at most max_i |q_i x dq/dx| (the affine cross product peaks at a vertex).
struct ViewMotion {
  dvec3 v[3], centre;
  double spread = 0, turn_per_px = 0;
};

ViewMotion view_motion(const SegmentStepInput& tri) {
  ViewMotion m;
  const dvec3& dq_dx = tri.pos_over_w_dx;
  dvec3 centre(0.0);
  for (int i = 0; i < 3; ++i) {
    m.v[i] = glm::normalize(-dvec3(tri.pos_view[i]));
    centre += dvec3(tri.pos_view[i]) / 3.0;
    const dvec3 q = dvec3(tri.pos_view[i]) * double(tri.inv_w[i]);
    m.turn_per_px = std::max(m.turn_per_px, glm::length(glm::cross(q, dq_dx)));
  }
  m.centre = glm::normalize(-centre);
  for (const dvec3& v : m.v)
    m.spread = std::max(m.spread, std::acos(std::clamp(glm::dot(m.centre, v), -1.0, 1.0)));
  return m;
}


}  // namespace

SegmentPlan hybrid_triangle_step(const SegmentStepInput& tri, float tol) {
  constexpr int kBlock = limits::kSeedBlockPx;
  if (!(tol > 0)) return {};
  // Along a row the interpolated q = n/w is affine, q(x) = q0 + g x, and the drawn normal is
  // u = q / |q|: u' = P_u g / |q| and u'' = -[2 u' (u.g) + u (u'.g)] / |q|. As u' is across u
  // and u'.g = |P_u g|^2 / |q| = |u'|^2 |q|, |u''| = |u'| sqrt(4 (u.g / |q|)^2 + |u'|^2): the
  // normal's turn, and the rate |q| changes at. Writing q = (sum beta_i / w_i) m with
  // m = sum lambda_i n_i (lambda: perspective-correct barycentrics), |q| >= min_i(1 / w_i)
  // min |m|, a bound for the whole triangle that holds at folds of antiparallel normals too,
  // where q shrinks. With g = s a + r (a the normals' cone axis, half-angle h, r across a) and
  // u inside the cone, g's part across u is |P_u g| <= |s| sin h + |r|, and its part along u
  // |u.g| <= |s| + |r| sin h (f5bb8f3: the old |u''| <= 3 |u'| |g| / |q| took |g| for both).
  const dvec3 n_d[3] = {dvec3(tri.n[0]), dvec3(tri.n[1]), dvec3(tri.n[2])};
  const double q_min = std::min({tri.inv_w[0], tri.inv_w[1], tri.inv_w[2]}) * min_length_over_triangle(n_d);
  if (!(q_min > 0.0)) return {};
  const dvec3& g = tri.n_over_w_dx;
  double g_across = glm::length(g), g_along = g_across;
  if (const NormalCone cone(n_d); cone.cos_half > 0.0) {
    const double s_axis = glm::dot(g, cone.axis), r_length = glm::length(g - s_axis * cone.axis);
    g_across = std::min(g_across, std::abs(s_axis) * cone.sin_half + r_length);
    g_along = std::min(g_along, std::abs(s_axis) + r_length * cone.sin_half);
  }
  const double turn = g_across / q_min;    // |u'|, radians per pixel, at most
  const double shrink = g_along / q_min;   // |u.g| / |q|, per pixel, at most
  const double rate_change = turn * std::sqrt(4.0 * shrink * shrink + turn * turn);  // |u''|, at most
  // The colour's second derivative along x: f = C(u), f'' = u'^T (d2C) u' + dC . u''.
  // Diffuse kd max(u.L, 0): |dC| <= kd, d2C = 0, plus a kink where the terminator crosses,
  // which linear interpolation misses by at most kd a / 4 for a segment turning by a (first
  // order). Specular ks c^n, c = u.H <= c_max: |dC| <= ks n c^(n-1), |d2C| <= ks n (n-1)
  // c^(n-2); below n = 2, c^n has no bounded curvature at c = 0 but is Lipschitz with
  // constant <= 1 in the angle: a kink term ks a / 2. A local viewer's H moves too: by V's
  // spread over the triangle (lowering the angle c_max comes from) and by its turn along x,
  // which adds to the angle N turns against H (docs/STABILITY.md, "B2").
  // With H fixed (a viewer at infinity) the lobe's curvature term is tighter: u' is
  // perpendicular to u, so |u'.H| <= |u'| sqrt(1 - c^2), and u'^T (d2C) u' = ks n (n-1)
  // c^(n-2) (u'.H)^2 <= ks n (n-1) c^(n-2) (1 - c^2) |u'|^2, whose c-factor rises up to
  // c* = sqrt((n-2)/n) and falls after it. At the highlight's peak (c = 1) the lobe is flat;
  // for n = 100 the factor is at most 0.0074 instead of 1 (segments up to 11x longer there).
  const MaterialConstants& m = *tri.material;
  const double kd = std::max({m.kd.r, m.kd.g, m.kd.b}), ks = std::max({m.ks.r, m.ks.g, m.ks.b});
  const double n = m.shininess_d;
  double bend = 0.0, slope = 0.0, kink = 0.0, h_turn = 0.0;  // weights of |u'|^2, |dC|, kinks
  double specular_max = 0.0;  // the largest sum of the lights' ks c^n anywhere on the triangle
  double split_kink = 0.0;  // the heaviest terminator kink of a light that can be split, not in `kink`
  int split_light = -1;
  ViewMotion view;
  if (tri.shade->local_viewer) view = view_motion(tri);
  for (int index = 0; index < int(tri.shade->lights.size()); ++index) {
    const LightView& light = tri.shade->lights[index];
    const double weight = std::max({light.color.r, light.color.g, light.color.b});
    const dvec3 l(light.l_view);
    dvec3 h(light.h_view);
    double h_spread = 0.0;
    if (tri.shade->local_viewer) {
      // H = (L + V) / |L + V| moves by at most V's motion over |L + V|, smallest where L.V is.
      const double lv_min = -max_dot_over_triangle(view.v, -l);
      const double half_length = std::sqrt(std::max(0.0, 2.0 + 2.0 * lv_min));
      if (!(half_length > limits::kMinHalfVectorLength)) return {};
      h = glm::normalize(l + view.centre);
      h_spread = view.spread / half_length;
      h_turn = std::max(h_turn, view.turn_per_px / half_length);
    }
    const double c_centre = std::clamp(max_dot_over_triangle(n_d, h), -1.0, 1.0);
    // An infinite viewer's H is fixed (h_spread = 0): c_centre itself, without acos and cos.
    const double c_max = h_spread > 0.0 ? std::cos(std::max(0.0, std::acos(c_centre) - h_spread)) : c_centre;
    if (ks > 0.0 && c_max > 0.0) {
      if (n < 2.0) {
        specular_max += weight * ks * std::pow(c_max, n);
        kink += weight * ks * 0.5;
      } else {
        const double c_pow = std::pow(c_max, n - 2.0);
        specular_max += weight * ks * c_pow * c_max * c_max;
        double lobe_bend = c_pow;  // the largest c^(n-2), times 1 - c^2 with H fixed, over c <= c_max
        if (!tri.shade->local_viewer) {
          const double c_bend = std::min(c_max, std::sqrt((n - 2.0) / n));
          lobe_bend = (c_bend == c_max ? c_pow : std::pow(c_bend, n - 2.0)) * (1.0 - c_bend * c_bend);
        }
        bend += weight * ks * n * (n - 1.0) * lobe_bend;
        slope += weight * ks * n * c_pow * c_max;
      }
    }
    slope += weight * kd;
    double lo = 1.0, hi = -1.0;  // the lit hemisphere is convex: vertices decide
    for (const dvec3& ni : n_d) {
      lo = std::min(lo, glm::dot(ni, l));
      hi = std::max(hi, glm::dot(ni, l));
    }
    if (lo < 0.0 && hi > 0.0) {
      double terminator = weight * kd * 0.25;
      if (index <= kMaxSplitLight && terminator > split_kink) {
        std::swap(terminator, split_kink);
        split_light = index;
      }
      kink += terminator;
    }
  }
  // Left out, the specular terms err by specular_max at most, which the segments' budget pays.
  const bool specular = !(specular_max < limits::kNegligibleSpecular);
  const double budget = specular ? tol : tol - specular_max;
  const double rel_turn = turn + h_turn;  // N against H, radians per pixel
  if (!(rel_turn > 0.0)) return {kBlock, -1, specular};
  const double second = bend * rel_turn * rel_turn + slope * rate_change;  // |f''|
  // A segment of L pixels errs by at most |f''| L^2 / 8 + kinks * (its turn).
  auto longest = [&](double kinks) {
    for (int step = kBlock; step >= 2; step /= 2)
      if (second * step * step / 8.0 + kinks * rel_turn * step <= budget) return step;
    return 1;
  };
  const int charged = longest(kink + split_kink);
  if (split_light >= 0)
    if (const int split = longest(kink); split > charged) return {split, split_light, specular};
  return {charged, -1, specular};
}

}  // namespace fastshade
