// Coverage as row spans: for each pixel row of a rectangle, the exact run of pixel centres
// that all three edge functions accept. Every shading method walks a triangle through this,
// so coverage is the same whatever the method, tile size or thread.
#pragma once
#include <algorithm>
#include <cstdint>

#include "frame/edge_function.h"

namespace fastshade {

struct PixelRect {  // inclusive pixel bounds
  int x0, y0, x1, y1;
};

namespace detail {

// Shrinks [lo, hi] (offsets k from the row's first pixel) to where e_row + step*k >= threshold.
// The double quotient is within one of the exact bound (|values| < 2^49, exact in a double),
// and the integer loops settle it exactly.
inline void clip_run(int64_t e_row, int64_t step, int64_t threshold, int& lo, int& hi) {
  if (step == 0) {
    if (e_row < threshold) hi = lo - 1;
    return;
  }
  const int64_t need = threshold - e_row;  // step * k >= need
  if (step > 0) {
    if (need <= 0) return;  // the whole row, since k >= 0
    int64_t k = static_cast<int64_t>(static_cast<double>(need) / static_cast<double>(step));
    k = std::clamp<int64_t>(k, 0, hi + 1);
    while (k > 0 && step * (k - 1) >= need) --k;
    while (k <= hi && step * k < need) ++k;
    lo = std::max<int>(lo, static_cast<int>(k));
  } else {
    if (need > 0) {  // even k = 0 fails, and it only gets worse
      hi = lo - 1;
      return;
    }
    int64_t k = static_cast<int64_t>(static_cast<double>(need) / static_cast<double>(step));
    k = std::clamp<int64_t>(k, -1, hi);
    while (k < hi && step * (k + 1) >= need) ++k;
    while (k >= 0 && step * k < need) --k;
    hi = std::min<int>(hi, static_cast<int>(k));
  }
}

}  // namespace detail

// Calls span(py, x_first, x_last) for every row of `rect` with covered pixels, top to bottom.
template <typename SpanFn>
inline void for_each_span(const TriangleEdges& te, const PixelRect& rect, SpanFn&& span) {
  const int width = rect.x1 - rect.x0;
  int64_t e_row[3], step_x[3], step_y[3];
  for (int k = 0; k < 3; ++k) {
    const Edge& e = te.e[k];
    e_row[k] = e.at(pixel_centre_fx(rect.x0), pixel_centre_fx(rect.y0));
    step_x[k] = e.a * limits::kSubpixelOne;
    step_y[k] = e.b * limits::kSubpixelOne;
  }
  for (int py = rect.y0; py <= rect.y1; ++py) {
    int lo = 0, hi = width;
    for (int k = 0; k < 3 && lo <= hi; ++k)
      detail::clip_run(e_row[k], step_x[k], te.e[k].threshold, lo, hi);
    if (lo <= hi) span(py, rect.x0 + lo, rect.x0 + hi);
    for (int k = 0; k < 3; ++k) e_row[k] += step_y[k];
  }
}

}  // namespace fastshade
