// The SIMD row masks (raster/row_masks-inl.h) against the scalar for_each_row_mask, bit for
// bit, on every compiled ISA: small and huge triangles (edge values near 2^51, where a double
// must still be exact), every rectangle width below kNarrowRectPx, rectangles partly outside
// the triangle, and edges through pixel centres (where the top-left rule's threshold decides).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "core/simd_target.h"
#include "raster/row_masks_testing.h"

namespace fastshade {
namespace {

TriangleEdges random_edges(std::mt19937& rng, int64_t extent_fx, bool on_centres) {
  std::uniform_int_distribution<int64_t> coord(-extent_fx, extent_fx);
  int64_t x[3], y[3];
  for (;;) {
    for (int i = 0; i < 3; ++i) {
      // Doubled coordinates around pixel (500, 300); on_centres snaps vertices to pixel centres.
      x[i] = pixel_centre_fx(500) + coord(rng);
      y[i] = pixel_centre_fx(300) + coord(rng);
      if (on_centres) {
        x[i] = pixel_centre_fx(x[i] / kEdgeUnitsPerPixel);
        y[i] = pixel_centre_fx(y[i] / kEdgeUnitsPerPixel);
      }
    }
    const int64_t area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
    if (area == 0) continue;
    if (area < 0) std::swap(x[1], x[2]), std::swap(y[1], y[2]);
    return edges_of(x, y);
  }
}

TEST(RowMasks, SimdEqualsScalarOnEveryIsa) {
  int isas = 0;
  for (const Isa isa_id : available_isas()) {
    const std::string isa(option_name(isa_id));
    const SimdTarget simd = simd_target(isa_id);
    ++isas;
    std::mt19937 rng(7);
    // Triangles from a few pixels to the guard band's 2^24 doubled units.
    const int64_t extents[] = {4 * kEdgeUnitsPerPixel, 20 * kEdgeUnitsPerPixel, int64_t(1) << 24};
    std::uniform_int_distribution<int> offset(-12, 12), height(0, 40);
    long long covered_total = 0;
    for (int64_t extent : extents)
      for (int trial = 0; trial < 400; ++trial) {
        const TriangleEdges te = random_edges(rng, extent, trial % 4 == 0);
        for (int width = 0; width < kNarrowRectPx; ++width) {
          const int x0 = 500 + offset(rng), y0 = 300 + offset(rng);
          const PixelRect rect{x0, y0, x0 + width, y0 + height(rng)};
          uint32_t lanes[64] = {};
          const int covered = row_masks(simd, te, rect, lanes);
          int expected_covered = 0;
          for_each_row_mask(te, rect, [&](int py, uint32_t bits) {
            ASSERT_EQ(lanes[py - rect.y0], bits) << isa << " row " << py - rect.y0 << " width " << width;
            expected_covered += __builtin_popcount(bits);
          });
          ASSERT_EQ(covered, expected_covered) << isa;
          covered_total += covered;
        }
      }
    EXPECT_GT(covered_total, 10000) << isa << ": the cases must cover pixels to test anything";
  }
  EXPECT_GE(isas, 1);
}

// Pixel centres inside the doubled vertices' bounding box, as triangle setup bounds them.
PixelRect centre_box(const int64_t x[3], const int64_t y[3]) {
  auto first = [](int64_t lo) { return static_cast<int>((lo - kEdgeUnitsPerPixel / 2 + kEdgeUnitsPerPixel - 1) / kEdgeUnitsPerPixel); };
  auto last = [](int64_t hi) { return static_cast<int>((hi - kEdgeUnitsPerPixel / 2) / kEdgeUnitsPerPixel); };
  return {first(std::min({x[0], x[1], x[2]})), first(std::min({y[0], y[1], y[2]})),
          last(std::max({x[0], x[1], x[2]})), last(std::max({y[0], y[1], y[2]}))};
}

// BoxCovered's int32 lanes against the scalar masks, on every ISA: triangles whose box spans
// up to kBoxExactSpanPx centres each way (the largest edge values it promises to hold), every
// sub-rectangle shape that fits the ISA's vector.
TEST(BoxMasks, SimdEqualsScalarOnEveryIsa) {
  int isas = 0;
  for (const Isa isa_id : available_isas()) {
    const std::string isa(option_name(isa_id));
    const SimdTarget simd = simd_target(isa_id);
    ++isas;
    std::mt19937 rng(11);
    std::uniform_int_distribution<int64_t> coord(0, (kBoxExactSpanPx + 1) * kEdgeUnitsPerPixel - 1);
    long long covered_total = 0, rects = 0;
    for (int trial = 0; trial < 20000; ++trial) {
      int64_t x[3], y[3];
      for (int i = 0; i < 3; ++i) {
        // The extent shrinks with the trial so that most triangles are a dense mesh's few pixels.
        const int64_t shrink = 1 + trial % 8;
        x[i] = pixel_centre_fx(500) + coord(rng) / shrink;
        y[i] = pixel_centre_fx(300) + coord(rng) / shrink;
        if (trial % 5 == 0) {  // vertices on pixel centres: the top-left rule decides
          x[i] = pixel_centre_fx(x[i] / kEdgeUnitsPerPixel);
          y[i] = pixel_centre_fx(y[i] / kEdgeUnitsPerPixel);
        }
      }
      const int64_t area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
      if (area == 0) continue;
      if (area < 0) std::swap(x[1], x[2]), std::swap(y[1], y[2]);
      const PixelRect box = centre_box(x, y);
      if (box.x0 > box.x1 || box.y0 > box.y1) continue;
      if (box.x1 - box.x0 >= kBoxExactSpanPx || box.y1 - box.y0 >= kBoxExactSpanPx) continue;
      const TriangleEdges te = edges_of(x, y);
      // The whole box and a random part of it (a tile's share).
      std::uniform_int_distribution<int> cx(box.x0, box.x1), cy(box.y0, box.y1);
      const int ax = cx(rng), bx = cx(rng), ay = cy(rng), by = cy(rng);
      for (const PixelRect& rect : {box, PixelRect{std::min(ax, bx), std::min(ay, by), std::max(ax, bx), std::max(ay, by)}}) {
        uint32_t lanes[kBoxExactSpanPx] = {};
        const int covered = box_masks(simd, te, rect, lanes);
        if (covered < 0) continue;  // wider than this ISA's vector
        ++rects;
        int expected_covered = 0;
        for_each_row_mask(te, rect, [&](int py, uint32_t bits) {
          ASSERT_EQ(lanes[py - rect.y0], bits) << isa << " row " << py - rect.y0;
          expected_covered += __builtin_popcount(bits);
        });
        ASSERT_EQ(covered, expected_covered) << isa;
        covered_total += covered;
      }
    }
    EXPECT_GT(rects, 5000) << isa << ": most small rectangles must fit a vector";
    EXPECT_GT(covered_total, 1000) << isa << ": the cases must cover pixels to test anything";
  }
  EXPECT_GE(isas, 1);
}

}  // namespace
}  // namespace fastshade
