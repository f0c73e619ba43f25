// The RGBA-to-RGB tile copy: SIMD equals its scalar reference on every ISA, for row widths
// 0..2W+1 (W up to 64 bytes of u8 lanes), and writes nothing past each row's width.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "exec/isa.h"
#include "exec/tile_io.h"

namespace fastshade {
namespace {

TEST(TileIo, RgbaRowsToRgbMatchesScalarOnEveryIsaAndWidth) {
  std::mt19937 rng(41);
  const int stride = 160, rows = 3;
  std::vector<uint32_t> src(std::size_t(stride) * rows);
  for (uint32_t& p : src) p = rng();
  for (const std::string& isa : available_isas()) {
    select_isa(isa);
    for (int width = 0; width <= 2 * 64 + 1; ++width) {
      const int dst_stride = 3 * stride + 7;
      std::vector<uint8_t> simd(std::size_t(dst_stride) * rows, 0xAB), scalar = simd;
      rgba_rows_to_rgb(src.data(), stride, simd.data(), dst_stride, width, rows);
      rgba_rows_to_rgb_scalar(src.data(), stride, scalar.data(), dst_stride, width, rows);
      ASSERT_EQ(simd, scalar) << isa << " width " << width;
      for (int y = 0; y < rows; ++y)
        for (int b = 3 * width; b < dst_stride; ++b)
          ASSERT_EQ(simd[std::size_t(y) * dst_stride + b], 0xAB) << isa << " wrote past the row";
    }
  }
  select_isa("best");
}

}  // namespace
}  // namespace fastshade
