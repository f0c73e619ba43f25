#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/limits.h"
#include "shade/fast_math.h"
#include "shade/hybrid.h"

namespace fastshade {

namespace {

// When n/w gets shorter than this share of its shortest vertex value inside the triangle, the
// sampled turn rate no longer bounds the rate (it peaks where n/w is shortest): bounded exactly
// instead. Normals less than 120 degrees apart keep the lerp of unit vectors above
// cos(60 deg) = 0.5 of their length, so ordinary meshes never take the exact bound.
constexpr float kFoldShrink = 0.5f;

// Largest N.H on the arc from na to nb (normalised lerp), NOTES.md section 2: an interior
// maximum where X + Y > 0 and 0 < t < 1, with peak sqrt((X^2 + Y^2 - 2XYc) / (1 - c^2)).
float arc_max(float x, float y, float c) {
  float best = std::max(x, y);
  const float one_minus_c = 1.0f - c;
  if (x + y > 0.0f && one_minus_c > 1e-6f) {
    const float t = (y - x * c) / (one_minus_c * (x + y));
    if (t > 0.0f && t < 1.0f)
      best = std::max(best, std::sqrt(std::max(0.0f, (x * x + y * y - 2.0f * x * y * c) /
                                                          (one_minus_c * (1.0f + c)))));
  }
  return std::min(best, 1.0f);
}

// Is h inside the spherical triangle of the unit normals (then N.H reaches 1 inside)?
bool inside_cone(const glm::vec3 n[3], const glm::vec3& h) {
  int positive = 0, negative = 0;
  for (int i = 0; i < 3; ++i) {
    const glm::vec3 plane = glm::cross(n[i], n[(i + 1) % 3]);
    const float side = glm::dot(plane, h) * glm::dot(plane, n[(i + 2) % 3]);
    positive += side > 0.0f;
    negative += side < 0.0f;
  }
  return negative == 0 && positive > 0;
}

// max N.H over the triangle's interpolated normals: edges' closed-form maxima, or 1 when the
// highlight's centre is inside (the interior test the paper lacks, NOTES.md section 2).
float triangle_max(const glm::vec3 n[3], const glm::vec3& h) {
  if (inside_cone(n, h)) return 1.0f;
  float best = -1.0f;
  for (int i = 0; i < 3; ++i) {
    const glm::vec3& a = n[i];
    const glm::vec3& b = n[(i + 1) % 3];
    best = std::max(best, arc_max(glm::dot(a, h), glm::dot(b, h), glm::dot(a, b)));
  }
  return best;
}

// The shortest n/w over the triangle: the distance from the origin to the triangle of the
// vertices' q (interior point or edge point, whichever is nearer).
float shortest_on_triangle(const glm::vec3 q[3]) {
  float best = HUGE_VALF;
  for (int i = 0; i < 3; ++i) {
    const glm::vec3& a = q[i];
    const glm::vec3 ab = q[(i + 1) % 3] - a;
    const float ab2 = glm::dot(ab, ab);
    const float t = ab2 > 0.0f ? std::clamp(-glm::dot(a, ab) / ab2, 0.0f, 1.0f) : 0.0f;
    best = std::min(best, glm::length(a + t * ab));
  }
  const glm::vec3 e1 = q[1] - q[0], e2 = q[2] - q[0], normal = glm::cross(e1, e2);
  const float d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
  const float det = d11 * d22 - d12 * d12;
  if (det > 0.0f) {  // the origin's foot on the plane, in barycentrics
    const float p1 = -glm::dot(q[0], e1), p2 = -glm::dot(q[0], e2);
    const float u = (d22 * p1 - d12 * p2) / det, v = (d11 * p2 - d12 * p1) / det;
    if (u >= 0.0f && v >= 0.0f && u + v <= 1.0f)
      best = std::min(best, std::fabs(glm::dot(q[0], normal)) / std::sqrt(glm::dot(normal, normal)));
  }
  return best;
}

// How a local viewer's V (towards the eye) moves over the triangle: V_i at the vertices, the
// centre's, the largest angle from the centre's to a vertex's (the directions to a planar
// triangle's points form the spherical triangle of the V_i, so a vertex is farthest), and its
// turn along x: |q x dq/dx| / |q|^2 for q = p/w, affine like n/w, with |q| = |p| / w >= 1
// (w = -z), so at most max_i |q_i x dq/dx| (the affine cross product peaks at a vertex).
struct ViewMotion {
  glm::vec3 v[3], centre;
  float spread = 0, turn_per_px = 0;
};
ViewMotion view_motion(const PhongSpanInput& in, const TriangleNormals& tri) {
  ViewMotion m;
  const glm::vec3 dq_dx(in.p[0].gx, in.p[1].gx, in.p[2].gx);
  glm::vec3 centre(0.0f);
  for (int i = 0; i < 3; ++i) {
    m.v[i] = glm::normalize(-tri.pos_view[i]);
    centre += tri.pos_view[i] / 3.0f;
    const glm::vec3 q = tri.pos_view[i] * tri.inv_w[i];
    m.turn_per_px = std::max(m.turn_per_px, glm::length(glm::cross(q, dq_dx)));
  }
  m.centre = glm::normalize(-centre);
  for (const glm::vec3& v : m.v)
    m.spread = std::max(m.spread, std::acos(std::clamp(glm::dot(m.centre, v), -1.0f, 1.0f)));
  return m;
}

// Below this |L + V| the half vector turns faster than any segment can follow (it is undefined
// where the light sits exactly behind the viewer): per-pixel Phong.
constexpr float kMinHalfVectorLength = 1e-3f;

}  // namespace

int hybrid_triangle_step(const PhongSpanInput& in, const TriangleNormals& tri, float tol) {
  constexpr int kBlock = limits::kSeedBlockPx;
  if (!(tol > 0)) return 1;
  // The interpolated vector q = n/w is affine in screen space; its direction turns along x at
  // |q x dq/dx| / |q|^2 radians per pixel (only the part of dq/dx across q turns it: w alone
  // changes q's length, not its direction). The rate is smooth over a triangle: its value at
  // the vertices and the centre, with 25 % margin, stands for its maximum.
  const glm::vec3 dq_dx(in.n[0].gx, in.n[1].gx, in.n[2].gx);
  glm::vec3 q[4];
  for (int i = 0; i < 3; ++i) q[i] = tri.n[i] * tri.inv_w[i];
  q[3] = (q[0] + q[1] + q[2]) / 3.0f;
  float turn_per_px = 0.0f, shortest_vertex = HUGE_VALF;
  for (const glm::vec3& qi : q) {
    const float len = glm::length(qi);
    if (!(len > 0.0f)) return 1;
    shortest_vertex = std::min(shortest_vertex, len);
    const glm::vec3 dir = qi / len;
    turn_per_px = std::max(turn_per_px, glm::length(dq_dx - glm::dot(dq_dx, dir) * dir) / len);
  }
  turn_per_px *= 1.25f;
  // ... unless q shrinks well below its vertex lengths inside (vertex normals more than 120
  // degrees apart, up to antiparallel: a fold, where the normal flips). Then the rate peaks
  // where q is shortest, and is bounded there exactly: q x dq/dx is affine, so its largest
  // length is at a vertex, over the shortest |q|^2 (docs/STABILITY.md, "Fallbacks").
  const float shortest = shortest_on_triangle(q);
  if (shortest < kFoldShrink * shortest_vertex) {
    if (!(shortest > 0.0f)) return 1;
    float across = 0.0f;
    for (int i = 0; i < 3; ++i) across = std::max(across, glm::length(glm::cross(q[i], dq_dx)));
    turn_per_px = std::max(turn_per_px, across / (shortest * shortest));
  }
  if (!(turn_per_px > 0.0f)) return kBlock;
  // The colour along a segment, as a function of the normal's angle a: smooth parts err by
  // a^2 / 8 times their curvature (shade/hybrid.h), kinks linearly in a: kd max(N.L, 0) bends
  // where N.L = 0 (the lerp across it errs by kd a / 4), and for n < 2 the lobe max(c, 0)^n
  // has no bounded curvature near c = 0: it is Lipschitz with constant <= 1 in the angle, so
  // the lerp errs by at most ks a / 2.
  const MaterialConstants& m = *in.material;
  const float kd = std::max({m.kd.r, m.kd.g, m.kd.b}), ks = std::max({m.ks.r, m.ks.g, m.ks.b});
  const float n = m.shininess;
  float curvature = 0.0f, kink = 0.0f, h_turn_per_px = 0.0f;
  ViewMotion view;
  if (in.shade->local_viewer) view = view_motion(in, tri);
  for (const LightView& light : in.shade->lights) {
    const float weight = std::max({light.color.r, light.color.g, light.color.b});
    glm::vec3 h = light.h_view;
    float h_spread = 0.0f;
    if (in.shade->local_viewer) {
      // H = (L + V) / |L + V| moves by at most V's motion over |L + V|, smallest where L.V is.
      const float lv_min = -triangle_max(view.v, -light.l_view);
      const float half_length = std::sqrt(std::max(0.0f, 2.0f + 2.0f * lv_min));
      if (!(half_length > kMinHalfVectorLength)) return 1;
      h = glm::normalize(light.l_view + view.centre);
      h_spread = view.spread / half_length;
      h_turn_per_px = std::max(h_turn_per_px, view.turn_per_px / half_length);
    }
    // The largest N.H with H at the centre's, then brought nearer by H's spread.
    const float c_centre = triangle_max(tri.n, h);
    const float c_max = std::cos(std::max(0.0f, std::acos(std::clamp(c_centre, -1.0f, 1.0f)) - h_spread));
    float spec = 0.0f;
    if (n < 2.0f)
      kink += weight * ks * 0.5f;
    else if (c_max > 0.0f)
      spec = n * fast_math::exp2((n - 2.0f) * fast_math::log2(c_max)) * (n + 1.0f);
    curvature += weight * (kd + ks * spec);
    const float nl_max = triangle_max(tri.n, light.l_view), nl_min = -triangle_max(tri.n, -light.l_view);
    if (nl_max > 0.0f && nl_min < 0.0f) kink += weight * kd * 0.25f;
  }
  // A segment of `step` pixels turns N against H by (turn_per_px + h_turn_per_px) * step.
  turn_per_px += h_turn_per_px;
  for (int step = kBlock; step >= 2; step /= 2) {
    const float angle = turn_per_px * float(step);
    if (angle * angle / 8.0f * curvature + angle * kink <= tol) return step;
  }
  return 1;
}

}  // namespace fastshade
