// Hybrid Gouraud/Phong segments (the paper, section II; NOTES.md section 6): inside each
// 16-pixel seed block, Phong at segment ends 2^m pixels apart and linear in between, with m
// chosen per block so that linear interpolation stays within the error budget.
#pragma once
#include <algorithm>

#include "shade/span_kernels.h"

namespace fastshade {

// Segment ends never leave the triangle: on a row whose whole covered run (in the triangle,
// not just this tile) is [xl, xr], the ends xb + j step are clamped to [xl, xr], so Phong is
// only ever evaluated inside, and a pixel's value does not depend on the tiles.
inline int segment_end(int xb, int j, int step, int xl, int xr) {
  return std::clamp(xb + j * step, xl, xr);
}

// The segment length (16, 8, 4, 2 or 1 px) for the seed block starting at xb on row py, whose
// covered run is [xl, xr].
//
// Along a block the normal turns through an angle theta (between its ends); a segment of L
// pixels spans theta L / 16. Linear interpolation of f over a segment errs by at most
// (segment angle)^2 / 8 * max |d^2 f / d angle^2|. For the Blinn-Phong colour, with
// c = N.H in [c_min, c_max] on the block,
//   |d^2/d angle^2 (kd max(N.L, 0))| <= kd,
//   |d^2/d angle^2 c^n| <= n c_max^(n-2) (n (1 - c_min^2) + 1),
// c_max from the closed-form peak of normalize(lerp(Na, Nb)).H (NOTES.md section 2) when the
// peak is inside the block, else the larger end; summed over lights weighted by |colour|.
// The longest L whose bound is within tol wins. A fixed length per object fails (NOTES: 19
// LSB seen); this adapts to curvature and to how near the block is to a highlight.
// Depends only on the block's position and the triangle: tile size never changes it.
int hybrid_step(const PhongSpanInput& in, int xb, int py, int xl, int xr, float tol);

// --max-error in LSB to the interpolation tolerance in colour units: half an LSB goes to the
// final rounding, so that the rounded result stays within max_error of exact Phong.
inline float hybrid_tolerance(double max_error_lsb) {
  return static_cast<float>(std::max(max_error_lsb - 0.5, 0.0) / 255.0);
}

}  // namespace fastshade
