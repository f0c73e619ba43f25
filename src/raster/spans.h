// Coverage as row spans: for each pixel row of a rectangle, the exact run of pixel centres
// that all three edge functions accept. Every shading method walks a triangle through this,
// so coverage is the same whatever the method, tile size or thread.
#pragma once
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "frame/edge_function.h"

namespace fastshade {

struct PixelRect {  // inclusive pixel bounds
  int x0, y0, x1, y1;
};

namespace detail {

// floor(n / d) for d > 0. |n| < 2^50 here, so the double quotient is within one of the
// answer and the integer checks settle it; cheaper than a 64-bit division.
inline int64_t floor_div(int64_t n, int64_t d) {
  int64_t q = static_cast<int64_t>(std::floor(static_cast<double>(n) / static_cast<double>(d)));
  if (q * d > n) --q;
  else if ((q + 1) * d <= n) ++q;
  return q;
}

// One edge's limit on a row's run of pixel offsets k (from the rectangle's left column),
// stepped from row to row exactly in integers, like a Bresenham line: no division per row.
// With E(k) = e + s k the edge accepts E(k) >= t, which for s > 0 is k >= ceil((t - e) / s)
// and for s < 0 is k <= floor((e - t) / -s). The bound is kept as quotient and remainder.
// No default member initialisers: init() sets every field, and a wide triangle's three bounds
// are made in every tile it touches (zeroing them first was a 216-byte rep stos each time,
// 3 % of a 4K gouraud frame's samples).
struct EdgeBound {
  int64_t q, rem;         // bound and remainder in [0, |s|)
  int64_t dq, drem;       // the per-row change, split the same way
  int64_t abs_s;
  int64_t e, e_step, t;   // s == 0: the edge value itself decides the whole row
  int sign;               // sign of s: +1 lower bound, -1 upper bound

  void init(int64_t e_row, int64_t s, int64_t row_step, int64_t threshold) {
    sign = s > 0 ? 1 : (s < 0 ? -1 : 0);
    e = e_row;
    e_step = row_step;
    t = threshold;
    q = rem = dq = drem = abs_s = 0;
    if (sign == 0) return;
    abs_s = s > 0 ? s : -s;
    // Lower bound: ceil(n / s) with n = t - e, held as n = q s - rem. Moving down a row adds
    // row_step to e, i.e. subtracts it from n. Upper bound: floor(n / |s|) with n = e - t,
    // held as n = q |s| + rem; moving down adds row_step to n.
    if (sign > 0) {
      const int64_t n = threshold - e_row;
      q = -floor_div(-n, abs_s);
      rem = q * abs_s - n;
      // row_step = a s + b with b in [0, s): n' = n - row_step = (q - a) s - (rem + b).
      const int64_t a = floor_div(row_step, abs_s);
      dq = -a;
      drem = row_step - a * abs_s;
    } else {
      const int64_t n = e_row - threshold;
      q = floor_div(n, abs_s);
      rem = n - q * abs_s;
      dq = floor_div(row_step, abs_s);
      drem = row_step - dq * abs_s;
    }
  }

  // rem + b may reach s: for a lower bound (q - a) s - r = (q - a - 1) s - (r - s), for an
  // upper bound q moves up instead. The carry is taken without a branch: it follows the
  // edge's slope row by row, a pattern branch predictors miss often (measured: the row walk
  // was the hottest part of the hybrid frame).
  void next_row() {
    if (sign == 0) {
      e += e_step;
      return;
    }
    q += dq;
    rem += drem;
    const int64_t carry = rem >= abs_s;
    rem -= carry * abs_s;
    q -= carry * sign;
  }

  void clip(int64_t& lo, int64_t& hi) const {
    if (sign > 0) lo = std::max(lo, q);
    else if (sign < 0) hi = std::min(hi, q);
    else if (e < t) hi = lo - 1;
  }
};

}  // namespace detail

// Below this width a row is tested pixel by pixel, cheaper than stepping three bounds (the
// kernels test a row's pixels in SIMD lanes, raster/row_masks-inl.h, and pack them, shade/
// span_loop-inl.h); at 16 a row's bits fit the kernels' uint32 masks with room to spare.
inline constexpr int kNarrowRectPx = 16;

// Edge values fit int32 lanes (raster/row_masks-inl.h BoxCovered) when the whole triangle's
// box spans at most kBoxExactSpanPx pixel centres each way: its vertices then lie within
// kBoxExactSpanPx + 1 pixels of any centre of the box, so |a|, |b| and every offset are below
// 18 * 512 edge units and |E| <= 2 * 9216^2 ~ 1.7e8 < 2^31.
inline constexpr int kBoxExactSpanPx = 16;
inline bool box_lanes_exact(const SetupTriangle& t) {
  return t.px_max[0] - t.px_min[0] < kBoxExactSpanPx && t.px_max[1] - t.px_min[1] < kBoxExactSpanPx;
}

// Lane i of a box w pixels wide lies kBoxLaneOffsets.col[w - 1][i] columns and
// kBoxLaneOffsets.row[w - 1][i] rows from its first pixel: one vector holds a box of
// w x h <= lanes pixels (raster/row_masks-inl.h BoxPixels), with no division in the lanes.
inline constexpr int kBoxMaxLanes = 16;  // int32 lanes of the widest vector (AVX-512)
struct BoxLaneTable {
  alignas(64) int32_t col[kNarrowRectPx][kBoxMaxLanes];
  alignas(64) int32_t row[kNarrowRectPx][kBoxMaxLanes];
};
inline constexpr BoxLaneTable kBoxLaneOffsets = [] {
  BoxLaneTable t{};
  for (int w = 1; w <= kNarrowRectPx; ++w)
    for (int i = 0; i < kBoxMaxLanes; ++i) t.col[w - 1][i] = i % w, t.row[w - 1][i] = i / w;
  return t;
}();

// For a rectangle narrower than kNarrowRectPx: calls row(py, bits) for every row, bit k set
// where pixel rect.x0 + k is covered. Branch-free per pixel; a row's bits are one run since
// triangles are convex.
template <typename RowFn>
inline void for_each_row_mask(const TriangleEdges& te, const PixelRect& rect, RowFn&& row) {
  const int width = rect.x1 - rect.x0;
  int64_t e_row[3], step_x[3], step_y[3];
  for (int k = 0; k < 3; ++k) {
    e_row[k] = te.e[k].at(pixel_centre_fx(rect.x0), pixel_centre_fx(rect.y0));
    step_x[k] = te.e[k].a * kEdgeUnitsPerPixel;
    step_y[k] = te.e[k].b * kEdgeUnitsPerPixel;
  }
  for (int py = rect.y0; py <= rect.y1; ++py) {
    uint32_t covered = 0;
    int64_t e0 = e_row[0], e1 = e_row[1], e2 = e_row[2];
    for (int k = 0; k <= width; ++k) {
      covered |= uint32_t((e0 >= te.e[0].threshold) & (e1 >= te.e[1].threshold) &
                          (e2 >= te.e[2].threshold))
                 << k;
      e0 += step_x[0];
      e1 += step_x[1];
      e2 += step_x[2];
    }
    row(py, covered);
    for (int k = 0; k < 3; ++k) e_row[k] += step_y[k];
  }
}

// Calls span(py, x_first, x_last) for every row of `rect` with covered pixels, top to bottom.
// Exact: the same pixels as testing every centre against the three edge functions.
template <typename SpanFn>
inline void for_each_span(const TriangleEdges& te, const PixelRect& rect, SpanFn&& span) {
  if (rect.x1 - rect.x0 < kNarrowRectPx) {
    for_each_row_mask(te, rect, [&](int py, uint32_t covered) {
      if (covered)
        span(py, rect.x0 + std::countr_zero(covered), rect.x0 + 31 - std::countl_zero(covered));
    });
    return;
  }
  const int64_t width = rect.x1 - rect.x0;
  detail::EdgeBound bound[3];
  for (int k = 0; k < 3; ++k) {
    const Edge& e = te.e[k];
    bound[k].init(e.at(pixel_centre_fx(rect.x0), pixel_centre_fx(rect.y0)),
                  e.a * kEdgeUnitsPerPixel, e.b * kEdgeUnitsPerPixel, e.threshold);
  }
  for (int py = rect.y0; py <= rect.y1; ++py) {
    int64_t lo = 0, hi = width;
    for (const detail::EdgeBound& b : bound) b.clip(lo, hi);
    if (lo <= hi) span(py, rect.x0 + static_cast<int>(lo), rect.x0 + static_cast<int>(hi));
    for (detail::EdgeBound& b : bound) b.next_row();
  }
}

}  // namespace fastshade
