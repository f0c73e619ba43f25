// Hybrid Gouraud/Phong segments (the paper, section II; NOTES.md section 6): inside each
// 16-pixel seed block, Phong at segment ends 2^m pixels apart and linear in between, with m
// chosen per block so that linear interpolation stays within the error budget.
#pragma once
#include <algorithm>

#include <glm/vec3.hpp>

#include "shade/span_kernels.h"

namespace fastshade {

// Segment ends never leave the triangle: on a row whose whole covered run (in the triangle,
// not just this tile) is [xl, xr], the ends xb + j step are clamped to [xl, xr], so Phong is
// only ever evaluated inside, and a pixel's value does not depend on the tiles.
inline int segment_end(int xb, int j, int step, int xl, int xr) {
  return std::clamp(xb + j * step, xl, xr);
}

// What the step decision needs of a triangle beyond its planes: unit vertex normals (view
// space, flipped for two-sided back faces), 1/w at the vertices and, for a local viewer, their
// view-space positions.
struct TriangleNormals {
  glm::vec3 n[3];
  float inv_w[3];
  glm::vec3 pos_view[3];
};

// The segment length (16, 8, 4, 2 or 1 px) for a whole triangle, decided once at setup.
//
// A segment of L pixels whose normal turns through an angle a errs, linearly interpolated,
// by at most a^2 / 8 * max |d^2 f / d angle^2|. The normal turns by the part of d(n/w)/dx
// across n/w, over |n/w|, per pixel (n/w is affine in screen space), estimated from the
// vertices and the centre with 25 % margin, or exactly where n/w shrinks inside the triangle
// (a fold of antiparallel normals: then per-pixel Phong). For the Blinn-Phong colour with
// c = N.H <= c_max on the triangle,
//   |d^2/d angle^2 (kd max(N.L, 0))| <= kd,   |d^2/d angle^2 c^n| <= n c_max^(n-2) (n + 1),
// with c_max from the edges' closed-form maxima (NOTES.md section 2) or 1 when H lies inside
// the cone of the vertex normals; summed over lights weighted by |colour|. A local viewer's H
// moves too: by the view direction's spread over the triangle (lowering the angle to H that
// c_max comes from) and turn along x (added to the normal's). Kinks add errors linear in the
// angle: kd a / 4 where N.L crosses 0 on the triangle, ks a / 2 for n < 2 (docs/STABILITY.md,
// "B2"). The longest L whose bound is within tol wins. One fixed length per object fails badly (NOTES.md: 19 LSB seen);
// this adapts to the triangle's curvature and to how near it is to a highlight. A decision
// per 16-px block was measured first and cost more than the Phong evaluations it saved on
// small triangles (3x phong's time on the 4K spot frame).
int hybrid_triangle_step(const PhongSpanInput& in, const TriangleNormals& tri, float tol);

// --max-error in LSB to the interpolation tolerance in colour units: half an LSB goes to the
// final rounding, so that the rounded result stays within max_error of exact Phong.
inline float hybrid_tolerance(double max_error_lsb) {
  return static_cast<float>(std::max(max_error_lsb - 0.5, 0.0) / 255.0);
}

}  // namespace fastshade
