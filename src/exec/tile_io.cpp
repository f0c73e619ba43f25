#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "exec/tile_io.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "exec/tile_io.h"

HWY_BEFORE_NAMESPACE();
namespace fastshade {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void RgbaRowsToRgb(const uint32_t* src, int src_stride_px, uint8_t* dst, int dst_stride_bytes,
                   int width, int rows) {
  const hn::ScalableTag<uint8_t> d8;
  const int lanes = static_cast<int>(hn::Lanes(d8));
  for (int y = 0; y < rows; ++y) {
    const uint8_t* in = reinterpret_cast<const uint8_t*>(src + std::ptrdiff_t(y) * src_stride_px);
    uint8_t* out = dst + std::ptrdiff_t(y) * dst_stride_bytes;
    int x = 0;
    for (; x + lanes <= width; x += lanes) {
      hn::Vec<decltype(d8)> r, g, b, a;
      hn::LoadInterleaved4(d8, in + 4 * x, r, g, b, a);
      hn::StoreInterleaved3(r, g, b, d8, out + 3 * x);
    }
    for (; x < width; ++x) {  // the row's tail
      out[3 * x] = in[4 * x];
      out[3 * x + 1] = in[4 * x + 1];
      out[3 * x + 2] = in[4 * x + 2];
    }
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace fastshade {

HWY_EXPORT(RgbaRowsToRgb);

void rgba_rows_to_rgb(const uint32_t* src, int src_stride_px, uint8_t* dst, int dst_stride_bytes,
                      int width, int rows) {
  HWY_DYNAMIC_DISPATCH(RgbaRowsToRgb)(src, src_stride_px, dst, dst_stride_bytes, width, rows);
}

void rgba_rows_to_rgb_scalar(const uint32_t* src, int src_stride_px, uint8_t* dst,
                             int dst_stride_bytes, int width, int rows) {
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < width; ++x) {
      const uint32_t p = src[std::ptrdiff_t(y) * src_stride_px + x];
      uint8_t* out = dst + std::ptrdiff_t(y) * dst_stride_bytes + 3 * x;
      out[0] = uint8_t(p), out[1] = uint8_t(p >> 8), out[2] = uint8_t(p >> 16);
    }
}

}  // namespace fastshade
#endif
