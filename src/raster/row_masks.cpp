#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/row_masks.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "raster/row_masks-inl.h"
#include "raster/row_masks.h"

HWY_BEFORE_NAMESPACE();
namespace fastshade {
namespace HWY_NAMESPACE {

int RowMasksFn(const TriangleEdges& te, const PixelRect& rect, uint32_t* bits) {
  return RowMasks(te, rect, bits);
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace fastshade {

HWY_EXPORT(RowMasksFn);

int row_masks(const TriangleEdges& te, const PixelRect& rect, uint32_t* bits) {
  return HWY_DYNAMIC_DISPATCH(RowMasksFn)(te, rect, bits);
}

}  // namespace fastshade
#endif
