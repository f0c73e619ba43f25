// Bounds of x . n over a triangle's interpolated normals n = normalize(sum lambda_i n_i), the
// normals the pipeline draws (linear, then normalised). The classifier and hybrid's step decision
// both rest on these. Double precision: at n = 1e6 a highlight lives where N.H > 1 - 6e-6, finer
// than float's resolution of an angle (docs/PAPER.md, "Peaks of N·H along an edge and inside a
// triangle").
#pragma once
#include <glm/vec3.hpp>

namespace fastshade {

using dvec3 = glm::dvec3;

// Largest x . normalize(lerp(a, b, t)) for t in [0, 1], a and b unit: the endpoints, or the
// interior peak of eq. 3 (docs/PAPER.md, "The numerically stable form of eq. 3") when the great
// circle's closest point to x lies between a and b. Antiparallel a, b: the lerp passes through
// zero, normals flip from a to b.
double arc_max(const dvec3& a, const dvec3& b, const dvec3& x);

// Is x (unit or not) inside the cone spanned by the three normals (then the peak is |x|)?
bool inside_cone(const dvec3 n[3], const dvec3& x);

// max x . n over the triangle, x unit: 1 when x is inside the normals' cone (the interior
// test the paper lacks), the largest edge maximum otherwise.
double max_dot_over_triangle(const dvec3 n[3], const dvec3& x);

// A cone around the normals: axis (their normalised sum) and the cosine and sine of its
// half-angle. Narrower than 90 degrees it is convex, so it holds every interpolated normal too,
// and two cheap bounds follow: max x.n <= cos(max(0, angle(axis, x) - half)), and
// |sum lambda_i n_i| >= cos(half).
struct NormalCone {
  dvec3 axis{0.0};
  double cos_half = -1.0;  // <= 0: too wide (or degenerate) for the cheap bounds
  double sin_half = 0.0;

  explicit NormalCone(const dvec3 n[3]);
  double max_dot(const dvec3& x) const;  // x unit: cos(max(0, angle(axis, x) - half))
};

// min |sum lambda_i n_i| over the barycentric simplex: the shortest interpolated normal before
// normalisation (the closest point of the triangle n0 n1 n2 to the origin).
double min_length_over_triangle(const dvec3 n[3]);

}  // namespace fastshade
