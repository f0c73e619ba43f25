#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "exec/tile_io.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <algorithm>
#include <cstdint>
#include <cstring>

#include <hwy/cache_control.h>
#include <hwy/highway.h>

#include "core/dispatch.h"
#include "core/limits.h"
#include "exec/tile_io_testing.h"

HWY_BEFORE_NAMESPACE();
namespace fastshade {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// One framebuffer row part from a buffer in cache: its whole cache lines with non-temporal
// stores (a 4K frame writes 25 MB that will not be read back before it leaves the cache, and
// an ordinary store first reads the line it writes: read for ownership), the partial lines at
// its ends with ordinary ones. The split is at cache lines, not vectors: a line written partly
// by streaming and partly by ordinary stores costs a trip to memory, once per row (with the
// head aligned to 32-byte vectors on AVX2, that doubled a 1-thread 4K gouraud frame of
// `render --frames` on a Zen 3 guest; acfa2b1).
void StreamRow(const uint8_t* src, uint8_t* dst, std::size_t bytes) {
  constexpr std::size_t kLineBytes = limits::kCacheLineBytes;
  static_assert(kLineBytes % HWY_MAX_BYTES == 0, "the body loop steps whole vectors through whole lines");
  const hn::ScalableTag<uint8_t> d8;
  const std::size_t lanes = hn::Lanes(d8);
  const std::size_t head =
      std::min(bytes, (kLineBytes - reinterpret_cast<uintptr_t>(dst) % kLineBytes) % kLineBytes);
  const std::size_t body_end = head + (bytes - head) / kLineBytes * kLineBytes;
  // The partial lines are tested for: in a line-aligned framebuffer (include/fastshade/image.h)
  // a 64-pixel tile's rows have none, and a memcpy of nothing still costs a call.
  if (head != 0) std::memcpy(dst, src, head);
  for (std::size_t i = head; i < body_end; i += lanes) hn::Stream(hn::LoadU(d8, src + i), d8, dst + i);
  if (body_end != bytes) std::memcpy(dst + body_end, src + body_end, bytes - body_end);
}

void StreamRows(const uint8_t* src, int src_stride_bytes, uint8_t* dst, int dst_stride_bytes,
                int row_bytes, int rows) {
  for (int y = 0; y < rows; ++y)
    StreamRow(src + std::ptrdiff_t(y) * src_stride_bytes, dst + std::ptrdiff_t(y) * dst_stride_bytes,
              static_cast<std::size_t>(row_bytes));
  hwy::FlushStream();  // the frame's reader, on another thread, must see the stores
}

// Four bytes a pixel to three, a vector of pixels at a time: within each 16-byte block a byte
// shuffle puts its four pixels' colour bytes first, then a lane permutation packs those 12-byte
// groups together; the vector is stored whole and the next store overwrites its last quarter.
// (With Highway's LoadInterleaved4/StoreInterleaved3 a 64-pixel row took 183 instructions,
// the streamed store included; now 149: callgrind, spot 4K, AVX2.)
void RgbaRowsToRgb(const uint32_t* src, int src_stride_px, uint8_t* dst, int dst_stride_bytes,
                   int width, int rows) {
  alignas(64) uint8_t row_rgb[limits::kMaxTilePx * 3 + HWY_MAX_BYTES];  // the row in cache, then streamed out
#if HWY_TARGET != HWY_SCALAR  // the shuffle needs whole 16-byte blocks
  const hn::ScalableTag<uint32_t> du;
  const hn::Repartition<uint8_t, decltype(du)> d8;
  const int lanes = static_cast<int>(hn::Lanes(du));
  alignas(16) static constexpr uint8_t kColourBytes[16] = {0, 1, 2, 4, 5, 6, 8, 9, 10, 12, 13, 14, 15, 15, 15, 15};
  // Lane i of the packed vector is lane (i / 3) * 4 + i % 3 of the shuffled one; the last
  // quarter of the lanes is overwritten by the next store, so any lane in range will do.
  static constexpr int32_t kPackLanes[16] = {0, 1, 2, 4, 5, 6, 8, 9, 10, 12, 13, 14, 0, 0, 0, 0};
  alignas(64) int32_t pack_lanes[16];
  for (int i = 0; i < 16; ++i) pack_lanes[i] = std::min(kPackLanes[i], lanes - 1);
  const auto colour_bytes = hn::LoadDup128(d8, kColourBytes);
  const auto pack = hn::SetTableIndices(du, pack_lanes);
#endif
  for (int y = 0; y < rows; ++y) {
    const uint32_t* in = src + std::ptrdiff_t(y) * src_stride_px;
    int x = 0;
#if HWY_TARGET != HWY_SCALAR
    for (; x + lanes <= width; x += lanes) {
      const auto shuffled = hn::TableLookupBytes(hn::BitCast(d8, hn::LoadU(du, in + x)), colour_bytes);
      hn::StoreU(hn::BitCast(d8, hn::TableLookupLanes(hn::BitCast(du, shuffled), pack)), d8, row_rgb + 3 * x);
    }
#endif
    for (; x < width; ++x) {  // the row's tail
      row_rgb[3 * x] = static_cast<uint8_t>(in[x]);
      row_rgb[3 * x + 1] = static_cast<uint8_t>(in[x] >> 8);
      row_rgb[3 * x + 2] = static_cast<uint8_t>(in[x] >> 16);
    }
    StreamRow(row_rgb, dst + std::ptrdiff_t(y) * dst_stride_bytes, static_cast<std::size_t>(width) * 3);
  }
  hwy::FlushStream();
}

void ClearTile(uint32_t* color, float* depth, int stride_px, uint32_t background, int width, int rows) {
  const hn::ScalableTag<uint32_t> du;
  const hn::ScalableTag<float> d;
  const int lanes = static_cast<int>(hn::Lanes(du));
  const auto background_px = hn::Set(du, background);
  const auto cleared = hn::Set(d, 1.0f);
  for (int y = 0; y < rows; ++y) {
    uint32_t* c = color + std::ptrdiff_t(y) * stride_px;
    float* z = depth + std::ptrdiff_t(y) * stride_px;
    int x = 0;
    for (; x + lanes <= width; x += lanes) {
      hn::StoreU(background_px, du, c + x);
      hn::StoreU(cleared, d, z + x);
    }
    for (; x < width; ++x) c[x] = background, z[x] = 1.0f;
  }
}

TilePixelCounts CountTilePixels(const float* depth, const uint32_t* color, int stride_px, int width,
                                int rows, bool by_path) {
  const hn::ScalableTag<float> d;
  const hn::RebindToUnsigned<decltype(d)> du;
  const int lanes = static_cast<int>(hn::Lanes(d));
  const auto cleared = hn::Set(d, 1.0f);
  TilePixelCounts counts;
  for (int y = 0; y < rows; ++y) {
    const float* z = depth + std::ptrdiff_t(y) * stride_px;
    const uint32_t* c = color + std::ptrdiff_t(y) * stride_px;
    for (int x = 0; x < width; x += lanes) {
      const auto hit = hn::And(hn::FirstN(d, static_cast<size_t>(width - x)), hn::Lt(hn::LoadU(d, z + x), cleared));
      counts.covered += static_cast<long long>(hn::CountTrue(d, hit));
      if (!by_path) continue;
      const auto alpha = hn::ShiftRight<24>(hn::LoadU(du, c + x));
      for (uint32_t p = 0; p < kShadePathCount; ++p)
        counts.path[p] += static_cast<long long>(
            hn::CountTrue(d, hn::And(hit, hn::RebindMask(d, hn::Eq(alpha, hn::Set(du, p))))));
    }
  }
  return counts;
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace fastshade {

HWY_EXPORT(StreamRows);
HWY_EXPORT(RgbaRowsToRgb);
HWY_EXPORT(CountTilePixels);
HWY_EXPORT(ClearTile);

void clear_tile(SimdTarget simd, uint32_t* color, float* depth, int stride_px, uint32_t background, int width, int rows) {
  FASTSHADE_DISPATCH(simd, ClearTile)(color, depth, stride_px, background, width, rows);
}

void clear_tile_scalar(uint32_t* color, float* depth, int stride_px, uint32_t background, int width,
                       int rows) {
  for (int y = 0; y < rows; ++y) {
    std::fill_n(color + std::ptrdiff_t(y) * stride_px, width, background);
    std::fill_n(depth + std::ptrdiff_t(y) * stride_px, width, 1.0f);
  }
}

TilePixelCounts count_tile_pixels(SimdTarget simd, const float* depth, const uint32_t* color, int stride_px, int width,
                                  int rows, bool by_path) {
  return FASTSHADE_DISPATCH(simd, CountTilePixels)(depth, color, stride_px, width, rows, by_path);
}

TilePixelCounts count_tile_pixels_scalar(const float* depth, const uint32_t* color, int stride_px,
                                         int width, int rows, bool by_path) {
  TilePixelCounts counts;
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < width; ++x) {
      const std::ptrdiff_t i = std::ptrdiff_t(y) * stride_px + x;
      const bool hit = depth[i] < 1.0f;
      counts.covered += hit;
      if (by_path && hit && (color[i] >> 24) < kShadePathCount) ++counts.path[color[i] >> 24];
    }
  return counts;
}

void stream_rows(SimdTarget simd, const uint8_t* src, int src_stride_bytes, uint8_t* dst, int dst_stride_bytes,
                 int row_bytes, int rows) {
  FASTSHADE_DISPATCH(simd, StreamRows)(src, src_stride_bytes, dst, dst_stride_bytes, row_bytes, rows);
}

void rgba_rows_to_rgb(SimdTarget simd, const uint32_t* src, int src_stride_px, uint8_t* dst, int dst_stride_bytes,
                      int width, int rows) {
  FASTSHADE_DISPATCH(simd, RgbaRowsToRgb)(src, src_stride_px, dst, dst_stride_bytes, width, rows);
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
