// Coverage of a narrow rectangle as one bit mask per row, in SIMD lanes (per-target, Highway
// "-inl.h"): for_each_row_mask() in raster/spans.h is the scalar reference, bit for bit.
#if defined(FASTSHADE_RASTER_ROW_MASKS_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FASTSHADE_RASTER_ROW_MASKS_INL_H_
#undef FASTSHADE_RASTER_ROW_MASKS_INL_H_
#else
#define FASTSHADE_RASTER_ROW_MASKS_INL_H_
#endif

#include <bit>
#include <cstdint>

#include <hwy/highway.h>

#include "core/mask_bits-inl.h"

#include "raster/spans.h"

HWY_BEFORE_NAMESPACE();
namespace fastshade {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Edge values are integers below 2^51 (frame/edge_function.h), so double lanes hold, add and
// compare them exactly; int64 lanes would need a multiply AVX2 lacks. bits[r] gets row rect.y0 + r, bit k for column rect.x0 + k; the
// return value is the number of covered pixels. rect must be narrower than kNarrowRectPx.
HWY_INLINE int RowMasks(const TriangleEdges& te, const PixelRect& rect, uint32_t* bits) {
  const hn::ScalableTag<double> d;
  const int lanes = static_cast<int>(hn::Lanes(d));
  const int columns = rect.x1 - rect.x0 + 1;
  const auto iota = hn::Iota(d, 0.0);
  // Rows and vectors are stepped in double too: every sum is an edge value, so exact.
  double e_row[3], step_x[3], step_y[3];
  hn::Vec<decltype(d)> lane_step[3], threshold[3];
  for (int k = 0; k < 3; ++k) {
    e_row[k] = static_cast<double>(te.e[k].at(pixel_centre_fx(rect.x0), pixel_centre_fx(rect.y0)));
    step_x[k] = static_cast<double>(te.e[k].a * kEdgeUnitsPerPixel);
    step_y[k] = static_cast<double>(te.e[k].b * kEdgeUnitsPerPixel);
    lane_step[k] = hn::Mul(iota, hn::Set(d, step_x[k]));
    threshold[k] = hn::Set(d, static_cast<double>(te.e[k].threshold));
  }
  int covered = 0;
  for (int row = 0; row <= rect.y1 - rect.y0; ++row) {
    uint32_t row_bits = 0;
    double e_first[3] = {e_row[0], e_row[1], e_row[2]};  // at the vector's first column
    for (int first = 0; first < columns; first += lanes) {
      auto in = hn::Lt(iota, hn::Set(d, static_cast<double>(columns - first)));
      for (int k = 0; k < 3; ++k) {
        in = hn::And(in, hn::Ge(hn::Add(hn::Set(d, e_first[k]), lane_step[k]), threshold[k]));
        e_first[k] += lanes * step_x[k];
      }
      row_bits |= static_cast<uint32_t>(MaskBits(d, in)) << first;
    }
    bits[row] = row_bits;
    covered += std::popcount(row_bits);
    for (int k = 0; k < 3; ++k) e_row[k] += step_y[k];
  }
  return covered;
}

// A small rectangle's pixels in one vector of int32 lanes, row after row, width lanes per row
// (raster/spans.h kBoxLaneOffsets). A dense mesh's boxes are 1-16 pixels, and one vector settles
// their coverage without a loop over rows.
struct BoxLayout {
  int width;  // pixels per row, 1..kNarrowRectPx
  int lanes;  // lanes the box takes: width * rows
};
HWY_INLINE BoxLayout box_layout(const PixelRect& rect) {
  const int width = rect.x1 - rect.x0 + 1;
  return {width, (rect.y1 - rect.y0 + 1) * width};
}

template <class DI>
struct BoxLanes {
  hn::Vec<DI> col, row;  // offsets from the rectangle's first pixel
  hn::Mask<DI> inside;   // the lane is a pixel of the rectangle
};

// The lanes' pixels of `rect` (box_layout(rect).lanes <= Lanes(di) <= kBoxMaxLanes).
template <class DI>
HWY_INLINE BoxLanes<DI> BoxPixels(DI di, BoxLayout layout) {
  static_assert(hn::MaxLanes(DI()) <= kBoxMaxLanes);
  return {hn::Load(di, kBoxLaneOffsets.col[layout.width - 1]), hn::Load(di, kBoxLaneOffsets.row[layout.width - 1]),
          hn::FirstN(di, static_cast<size_t>(layout.lanes))};
}

// The lanes of `box` whose pixel centre the triangle covers (the triangle box_lanes_exact(), so
// its edge values fit int32 lanes): the same pixels as for_each_row_mask.
template <class DI>
HWY_INLINE hn::Mask<DI> BoxCovered(DI di, const TriangleEdges& te, const PixelRect& rect, const BoxLanes<DI>& box) {
  auto covered = box.inside;
  for (const Edge& e : te.e) {
    // The rectangle's first centre lies in the triangle's box, so its value fits int32 too.
    const auto at_origin = static_cast<int32_t>(e.at(pixel_centre_fx(rect.x0), pixel_centre_fx(rect.y0)));
    const auto value = hn::Add(hn::Add(hn::Set(di, at_origin), hn::Mul(box.col, hn::Set(di, static_cast<int32_t>(e.a * kEdgeUnitsPerPixel)))),
                               hn::Mul(box.row, hn::Set(di, static_cast<int32_t>(e.b * kEdgeUnitsPerPixel))));
    // E >= threshold as E > threshold - 1: int32 lanes have no >= before Highway 1.1.
    covered = hn::And(covered, hn::Gt(value, hn::Set(di, static_cast<int32_t>(e.threshold - 1))));
  }
  return covered;
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#endif  // include guard toggle
