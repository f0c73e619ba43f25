// Attribute plane equations from exact barycentrics: what every shading method interpolates.
#pragma once
#include <algorithm>
#include <cstdint>

#include "frame/edge_function.h"

namespace fastshade {

// q(px, py) = v0 + gx (px - ax) + gy (py - ay) at pixel centres, clamped to [lo, hi], the range
// of the three vertex values: the clamp keeps slivers, whose float gradients may be far off
// (docs/PAPER.md, "Plane evaluation precision"), inside what the triangle can actually take.
struct Plane {
  float v0, gx, gy, lo, hi;
};

// Screen-space barycentric gradients of one triangle, exact from the integer edge functions
// of its whole shape (shape_edges: a Sierpinski part interpolates over its parent).
struct Barycentrics {
  int ax, ay;               // anchor pixel: the bounding box's first pixel centre
  double at_anchor[3];      // lambda_k at the anchor
  double d_dx[3], d_dy[3];  // per pixel
};

// Written in place: returned by value into an existing TriangleInTile, GCC built the struct in
// a temporary with scalar stores and copied it with one 64-byte load, which cannot be forwarded
// from those stores: a tenth of dragon_871k's per-triangle body (perf; 465a2dc).
FASTSHADE_FORCE_INLINE void set_barycentrics(const SetupTriangle& t, const TriangleEdges& te, Barycentrics& b) {
  // The anchor: the first pixel centre of the whole triangle's box (as triangle setup bounds
  // it, so a whole triangle's record holds it already), so that the parts of a split triangle
  // evaluate their parent's planes bit for bit.
  if (sierpinski_part(t) == 0) {
    b.ax = t.px_min[0];
    b.ay = t.px_min[1];
  } else {
    const int32_t half = limits::kSubpixelOne / 2, round_up = limits::kSubpixelOne - 1;
    b.ax = std::max((std::min({t.x_fx[0], t.x_fx[1], t.x_fx[2]}) - half + round_up) >> limits::kSubpixelBits, 0);
    b.ay = std::max((std::min({t.y_fx[0], t.y_fx[1], t.y_fx[2]}) - half + round_up) >> limits::kSubpixelBits, 0);
  }
  const double inv_area = 1.0 / (4.0 * static_cast<double>(doubled_area(t)));  // edge units
  const int64_t x = pixel_centre_fx(b.ax), y = pixel_centre_fx(b.ay);
  for (int k = 0; k < 3; ++k) {
    b.at_anchor[k] = static_cast<double>(te.e[k].at(x, y)) * inv_area;
    b.d_dx[k] = static_cast<double>(te.e[k].a * kEdgeUnitsPerPixel) * inv_area;
    b.d_dy[k] = static_cast<double>(te.e[k].b * kEdgeUnitsPerPixel) * inv_area;
  }
}
inline Barycentrics barycentrics(const SetupTriangle& t, const TriangleEdges& te) {
  Barycentrics b;
  set_barycentrics(t, te, b);
  return b;
}

FASTSHADE_FORCE_INLINE Plane make_plane(const Barycentrics& b, double q0, double q1, double q2) {
  Plane p;
  p.v0 = static_cast<float>(q0 * b.at_anchor[0] + q1 * b.at_anchor[1] + q2 * b.at_anchor[2]);
  p.gx = static_cast<float>(q0 * b.d_dx[0] + q1 * b.d_dx[1] + q2 * b.d_dx[2]);
  p.gy = static_cast<float>(q0 * b.d_dy[0] + q1 * b.d_dy[1] + q2 * b.d_dy[2]);
  p.lo = static_cast<float>(std::min({q0, q1, q2}));
  p.hi = static_cast<float>(std::max({q0, q1, q2}));
  return p;
}

// A pixel's offsets as the kernels use them: from the anchor to its seed block's origin, from
// the block origin to the pixel, and the row's offset.
struct PixelOffsets {
  float block_dx, k, dy;
};
inline PixelOffsets pixel_offsets(const Barycentrics& b, int px, int py) {
  const int xb = px & ~(limits::kSeedBlockPx - 1);
  return {static_cast<float>(xb - b.ax), static_cast<float>(px - xb), static_cast<float>(py - b.ay)};
}

// The value at a pixel: seeded from the plane at its block origin (limits::kSeedBlockPx),
// plus k constant increments gx, clamped. The exact sequence of float operations every SIMD
// kernel performs (no FMA), so scalar and vector paths agree bit for bit.
inline float plane_at_unclamped(const Plane& p, const PixelOffsets& o) {
  const float seed = (p.v0 + p.gy * o.dy) + p.gx * o.block_dx;
  return seed + p.gx * o.k;
}
inline float plane_at(const Plane& p, const PixelOffsets& o) {
  return std::clamp(plane_at_unclamped(p, o), p.lo, p.hi);
}

}  // namespace fastshade
