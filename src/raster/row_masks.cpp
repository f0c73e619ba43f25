#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/row_masks.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <algorithm>

#include <hwy/highway.h>

#include "core/dispatch.h"
#include "raster/row_masks-inl.h"
#include "raster/row_masks_testing.h"

HWY_BEFORE_NAMESPACE();
namespace fastshade {
namespace HWY_NAMESPACE {

int RowMasksFn(const TriangleEdges& te, const PixelRect& rect, uint32_t* bits) {
  return RowMasks(te, rect, bits);
}

int BoxMasksFn(const TriangleEdges& te, const PixelRect& rect, uint32_t* bits) {
  const hn::ScalableTag<int32_t> di;
  const BoxLayout layout = box_layout(rect);
  if (layout.lanes > static_cast<int>(hn::Lanes(di))) return -1;
  const auto box = BoxPixels(di, layout);
  const auto covered = BoxCovered(di, te, rect, box);
  alignas(64) int32_t col[HWY_MAX_BYTES / 4], row[HWY_MAX_BYTES / 4];
  hn::Store(box.col, di, col);
  hn::Store(box.row, di, row);
  std::fill(bits, bits + (rect.y1 - rect.y0 + 1), 0u);
  for (uint64_t lanes = MaskBits(di, covered); lanes; lanes &= lanes - 1) {
    const int lane = std::countr_zero(lanes);
    bits[row[lane]] |= 1u << col[lane];
  }
  return static_cast<int>(hn::CountTrue(di, covered));
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace fastshade {

HWY_EXPORT(RowMasksFn);
HWY_EXPORT(BoxMasksFn);

int row_masks(SimdTarget simd, const TriangleEdges& te, const PixelRect& rect, uint32_t* bits) {
  return FASTSHADE_DISPATCH(simd, RowMasksFn)(te, rect, bits);
}

int box_masks(SimdTarget simd, const TriangleEdges& te, const PixelRect& rect, uint32_t* bits) {
  return FASTSHADE_DISPATCH(simd, BoxMasksFn)(te, rect, bits);
}

}  // namespace fastshade
#endif
