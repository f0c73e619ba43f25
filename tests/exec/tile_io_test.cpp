// The RGBA-to-RGB tile copy: SIMD equals its scalar reference on every ISA, for row widths
// 0..2W+1 (W up to 64 bytes of u8 lanes), and writes nothing past each row's width.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "core/limits.h"
#include "core/simd_target.h"
#include "exec/tile_io_testing.h"
#include "fastshade/image.h"

namespace fastshade {
namespace {

TEST(TileIo, RgbaRowsToRgbMatchesScalarOnEveryIsaAndWidth) {
  std::mt19937 rng(41);
  const int stride = 160, rows = 3;
  std::vector<uint32_t> src(std::size_t(stride) * rows);
  for (uint32_t& p : src) p = rng();
  for (const Isa isa_id : available_isas()) {
    const std::string isa(option_name(isa_id));
    const SimdTarget simd = simd_target(isa_id);
    for (int width = 0; width <= 2 * 64 + 1; ++width) {
      const int dst_stride = 3 * stride + 7;
      std::vector<uint8_t> lanes(std::size_t(dst_stride) * rows, 0xAB), scalar = lanes;
      rgba_rows_to_rgb(simd, src.data(), stride, lanes.data(), dst_stride, width, rows);
      rgba_rows_to_rgb_scalar(src.data(), stride, scalar.data(), dst_stride, width, rows);
      ASSERT_EQ(lanes, scalar) << isa << " width " << width;
      for (int y = 0; y < rows; ++y)
        for (int b = 3 * width; b < dst_stride; ++b)
          ASSERT_EQ(lanes[std::size_t(y) * dst_stride + b], 0xAB) << isa << " wrote past the row";
    }
  }
}

// The empty-tile fill: one source row (stride 0) or several into framebuffer rows at every
// alignment to a cache line (whole lines are streamed, partial ones stored), byte for byte what
// memcpy writes, and nothing past each row.
TEST(TileIo, StreamRowsCopiesEveryRowAtEveryAlignment) {
  std::mt19937 rng(47);
  const int rows = 3, dst_stride = 3 * 256 + 13;
  std::vector<uint8_t> src(std::size_t(3 * 256) * rows);
  for (uint8_t& b : src) b = static_cast<uint8_t>(rng());
  for (const Isa isa_id : available_isas()) {
    const std::string isa(option_name(isa_id));
    const SimdTarget simd = simd_target(isa_id);
    for (int src_stride : {0, 3 * 256})
      for (int offset = 0; offset < 64; ++offset)
        for (int bytes = 0; bytes <= 3 * 256; bytes += (bytes < 200 ? 1 : 61)) {
          std::vector<uint8_t> dst(std::size_t(dst_stride) * rows + offset, 0xAB), expected = dst;
          stream_rows(simd, src.data(), src_stride, dst.data() + offset, dst_stride, bytes, rows);
          for (int y = 0; y < rows; ++y)
            std::copy_n(src.begin() + std::ptrdiff_t(y) * src_stride, bytes,
                        expected.begin() + offset + std::ptrdiff_t(y) * dst_stride);
          ASSERT_EQ(dst, expected) << isa << " src stride " << src_stride << " offset " << offset << " bytes " << bytes;
        }
  }
}

// Counting a tile's drawn pixels, per path: SIMD equals scalar on every ISA for widths 0..2W+1
// (W up to 16 float lanes), with depths at, below and above the cleared 1.0, every path tag and
// untagged pixels; pixels past the width never count.
TEST(TileIo, CountTilePixelsMatchesScalarOnEveryIsaAndWidth) {
  std::mt19937 rng(43);
  const int stride = 48, rows = 5;
  std::vector<float> depth(std::size_t(stride) * rows + 64);
  std::vector<uint32_t> color(depth.size());
  const float depths[] = {0.0f, 0.5f, 0.99999994f, 1.0f, 1.0f, 2.0f};
  const uint32_t alphas[] = {0, 1, 2, 3, 0xFF, 0xFF, 0x80};
  for (std::size_t i = 0; i < depth.size(); ++i) {
    depth[i] = depths[rng() % 6];
    color[i] = (alphas[rng() % 7] << 24) | (rng() & 0xFFFFFF);
  }
  long long any_path = 0;
  for (const Isa isa_id : available_isas()) {
    const std::string isa(option_name(isa_id));
    const SimdTarget simd = simd_target(isa_id);
    for (bool by_path : {false, true})
      for (int width = 0; width <= 2 * 16 + 1; ++width) {
        const TilePixelCounts lanes = count_tile_pixels(simd, depth.data(), color.data(), stride, width, rows, by_path);
        const TilePixelCounts scalar = count_tile_pixels_scalar(depth.data(), color.data(), stride, width, rows, by_path);
        ASSERT_EQ(lanes.covered, scalar.covered) << isa << " width " << width;
        for (int p = 0; p < kShadePathCount; ++p) {
          ASSERT_EQ(lanes.path[p], scalar.path[p]) << isa << " width " << width << " path " << p;
          any_path += scalar.path[p];
        }
      }
  }
  EXPECT_GT(any_path, 0);
}

// Clearing a tile: SIMD equals its scalar reference on every ISA for widths 0..2W+1 (W up to 16
// lanes), and nothing past a row's width changes.
TEST(TileIo, ClearTileMatchesScalarOnEveryIsaAndWidth) {
  const int stride = 48, rows = 3;
  for (const Isa isa_id : available_isas()) {
    const std::string isa(option_name(isa_id));
    const SimdTarget simd = simd_target(isa_id);
    for (int width = 0; width <= 2 * 16 + 1; ++width) {
      std::vector<uint32_t> color(std::size_t(stride) * rows, 0xABABABABu), color_scalar = color;
      std::vector<float> depth(color.size(), -3.0f), depth_scalar = depth;
      clear_tile(simd, color.data(), depth.data(), stride, 0xFF102030u, width, rows);
      clear_tile_scalar(color_scalar.data(), depth_scalar.data(), stride, 0xFF102030u, width, rows);
      ASSERT_EQ(color, color_scalar) << isa << " width " << width;
      ASSERT_EQ(depth, depth_scalar) << isa << " width " << width;
      for (int y = 0; y < rows; ++y)
        for (int x = 0; x < stride; ++x) {
          const std::size_t i = std::size_t(y) * stride + x;
          ASSERT_EQ(color[i], x < width ? 0xFF102030u : 0xABABABABu) << isa << " width " << width;
          ASSERT_EQ(depth[i], x < width ? 1.0f : -3.0f) << isa << " width " << width;
        }
    }
  }
}

// The framebuffer starts on a cache line whatever its size (malloc's large blocks start 16
// bytes into a page), so 64-pixel tile rows are whole lines for StreamRows.
TEST(TileIo, ImageBytesStartOnACacheLine) {
  for (std::size_t bytes : {std::size_t(1), std::size_t(3 * 1280 * 720), std::size_t(3 * 3840 * 2160)}) {
    const ImageBytes rgb(bytes);
    EXPECT_EQ(reinterpret_cast<uintptr_t>(rgb.data()) % limits::kCacheLineBytes, 0u) << bytes << " bytes";
  }
}

}  // namespace
}  // namespace fastshade
