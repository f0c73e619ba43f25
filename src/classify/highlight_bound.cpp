#include "classify/highlight_bound.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace fastshade {

double arc_max(const dvec3& a, const dvec3& b, const dvec3& x) {
  const double ends = std::max(glm::dot(a, x), glm::dot(b, x));
  // The arc lies in the plane through a, b and the origin, with normal k. The great circle's
  // nearest point to x is x's projection x_p onto that plane, direction u, at x . u = |x_p| =
  // |x x k| / |k| (docs/PAPER.md's closed-form peak sqrt((X^2 + Y^2 - 2XYc) / (1 - c^2)), without
  // dividing by 1 - c^2, which vanishes for nearly equal normals; and not as
  // sqrt(|x|^2 - (x . k)^2 / |k|^2), which cancels where x is nearly along k and then
  // understates the peak by up to 1e-8). No square root or division before the tests below:
  // most calls end there.
  const dvec3 k = glm::cross(a, b);
  const double k_len2 = glm::dot(k, k);
  if (!(k_len2 > 0.0)) return ends;  // equal or antiparallel: no arc between them
  // u is between a and b (the short way round k) iff a x u and u x b both point along k; x's
  // part along k changes neither product's component along k, so x stands in for x_p.
  if (glm::dot(glm::cross(a, x), k) <= 0.0 || glm::dot(glm::cross(x, b), k) <= 0.0) return ends;
  const dvec3 x_k = glm::cross(x, k);
  return std::max(ends, std::sqrt(glm::dot(x_k, x_k) / k_len2));
}

bool inside_cone(const dvec3 n[3], const dvec3& x) {
  const double volume = glm::dot(n[0], glm::cross(n[1], n[2]));
  if (volume == 0.0) return false;  // coplanar normals: the edges' arcs cover the region
  // x = sum mu_i n_i with every mu_i >= 0; mu_i has the sign of det(x replacing n_i) / volume.
  for (int i = 0; i < 3; ++i) {
    const double mu = glm::dot(x, glm::cross(n[(i + 1) % 3], n[(i + 2) % 3]));
    if (mu * volume < 0.0) return false;
  }
  return true;
}

double max_dot_over_triangle(const dvec3 n[3], const dvec3& x) {
  if (inside_cone(n, x)) return 1.0;
  double best = -1.0;
  for (int i = 0; i < 3; ++i) best = std::max(best, arc_max(n[i], n[(i + 1) % 3], x));
  return std::min(best, 1.0);
}

NormalCone::NormalCone(const dvec3 n[3]) {
  const dvec3 sum = n[0] + n[1] + n[2];
  const double len = glm::length(sum);
  if (!(len > 0.0)) return;
  axis = sum / len;
  cos_half = std::min({glm::dot(axis, n[0]), glm::dot(axis, n[1]), glm::dot(axis, n[2])});
  sin_half = std::sqrt(std::max(0.0, 1.0 - cos_half * cos_half));
}

double NormalCone::max_dot(const dvec3& x) const {
  const double ca = glm::dot(axis, x);
  if (ca >= cos_half) return 1.0;
  return ca * cos_half + std::sqrt(std::max(0.0, 1.0 - ca * ca)) * sin_half;
}

double min_length_over_triangle(const dvec3 n[3]) {
  // The triangle's closest point to the origin: on an edge (the segments' closest points,
  // robust for the equal or collinear normals of flat and nearly flat triangles), or inside,
  // where it is the origin's projection onto the triangle's plane.
  double best = 1e300;
  for (int i = 0; i < 3; ++i) {
    const dvec3 &a = n[i], &b = n[(i + 1) % 3];
    const dvec3 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(-glm::dot(a, ab) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, glm::length(a + t * ab));
  }
  const dvec3 normal = glm::cross(n[1] - n[0], n[2] - n[0]);
  const double normal2 = glm::dot(normal, normal);
  if (normal2 > 0.0) {
    const dvec3 p = (glm::dot(n[0], normal) / normal2) * normal;
    // Inside iff p is on the inner side of all three edges.
    bool inside = true;
    for (int i = 0; i < 3; ++i)
      inside &= glm::dot(glm::cross(n[(i + 1) % 3] - n[i], p - n[i]), normal) >= 0.0;
    if (inside) best = std::min(best, glm::length(p));
  }
  return best;
}

}  // namespace fastshade
