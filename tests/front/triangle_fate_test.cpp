// Triangle setup's decisions in lanes (front/triangle_fate.cpp) against decide_triangle(), its
// scalar reference, on every compiled ISA for block lengths 0..2W+1 and a whole block: tiny
// triangles around pixel centres (the one-candidate test and the top-left rule's ties), zero
// areas, both facings with and without back-face culling, boxes off the image and coordinates
// at the guard band's ends, where products need all 48 bits.
#include <gtest/gtest.h>

#include <random>

#include "core/limits.h"
#include "core/simd_target.h"
#include "front/triangle_fate.h"

namespace fastshade {
namespace {

constexpr int kWidth = 37, kHeight = 23;  // odd sizes: boxes clamped on every side

// Vertex coordinates in fixed point: near pixel centres (offsets of a few sub-pixel steps, so
// that edges pass exactly through centres), anywhere on and off the image, or at the guard band.
int32_t random_coordinate(std::mt19937& rng, int kind, int32_t near_fx) {
  const int32_t one = limits::kSubpixelOne;
  switch (kind) {
    case 0: return near_fx + std::uniform_int_distribution<int32_t>(-3, 3)(rng) * (one / 4);
    case 1: return std::uniform_int_distribution<int32_t>(-4 * one, 44 * one)(rng);
    default: {
      const int32_t guard = limits::kGuardPx * one;
      return std::uniform_int_distribution<int32_t>(-guard, guard - 1)(rng);
    }
  }
}

TriangleColumns random_block(std::mt19937& rng, int count) {
  TriangleColumns in{};
  const int32_t one = limits::kSubpixelOne;
  for (int i = 0; i < count; ++i) {
    const int kind = std::uniform_int_distribution<int>(0, 9)(rng);
    const int k = kind < 6 ? 0 : kind < 9 ? 1 : 2;
    const int32_t cx = std::uniform_int_distribution<int>(-1, kWidth)(rng) * one + one / 2;
    const int32_t cy = std::uniform_int_distribution<int>(-1, kHeight)(rng) * one + one / 2;
    for (int v = 0; v < 3; ++v) {
      in.x_fx[v][i] = random_coordinate(rng, k, cx);
      in.y_fx[v][i] = random_coordinate(rng, k, cy);
    }
    if (kind == 5) {  // collinear: the third vertex on the line through the first two
      in.x_fx[2][i] = 2 * in.x_fx[1][i] - in.x_fx[0][i];
      in.y_fx[2][i] = 2 * in.y_fx[1][i] - in.y_fx[0][i];
    }
  }
  return in;
}

void expect_equal(const TriangleFates& got, const TriangleFates& want, int count, const std::string& what) {
  EXPECT_EQ(got.dropped, want.dropped) << what;
  EXPECT_EQ(got.culled, want.culled) << what;
  for (int w = 0; w < kFateBlock / 64; ++w) {
    ASSERT_EQ(got.kept[w], want.kept[w]) << what << " word " << w;
    ASSERT_EQ(got.back[w], want.back[w]) << what << " word " << w;
  }
  for (int i = 0; i < count; ++i) {
    if (!((want.kept[i / 64] >> (i % 64)) & 1)) continue;
    ASSERT_EQ(got.x0[i], want.x0[i]) << what << " triangle " << i;
    ASSERT_EQ(got.y0[i], want.y0[i]) << what << " triangle " << i;
    ASSERT_EQ(got.x1[i], want.x1[i]) << what << " triangle " << i;
    ASSERT_EQ(got.y1[i], want.y1[i]) << what << " triangle " << i;
  }
}

TEST(TriangleFate, LanesMatchScalarOnEveryIsaAndLength) {
  std::mt19937 rng(12);
  std::vector<int> lengths;
  for (int n = 0; n <= 2 * 8 + 1; ++n) lengths.push_back(n);
  lengths.push_back(kFateBlock);
  int kept = 0, back = 0, dropped = 0, culled = 0;
  for (const Isa isa_id : available_isas()) {
    const std::string isa(option_name(isa_id));
    const SimdTarget simd = simd_target(isa_id);
    for (int round = 0; round < 40; ++round)
      for (int count : lengths)
        for (bool cull_back : {false, true}) {
          const TriangleColumns in = random_block(rng, count);
          TriangleFates got, want;
          decide_triangles(simd, in, count, kWidth, kHeight, cull_back, got);
          decide_triangles_scalar(in, count, kWidth, kHeight, cull_back, want);
          expect_equal(got, want, count, isa + " count " + std::to_string(count) + (cull_back ? " cull" : ""));
          for (int w = 0; w < kFateBlock / 64; ++w) {
            kept += std::popcount(want.kept[w]);
            back += std::popcount(want.back[w]);
          }
          dropped += want.dropped;
          culled += want.culled;
        }
  }
  // Every fate occurs often, so the comparison above exercised each.
  EXPECT_GT(back, 1000);
  EXPECT_GT(kept - back, 1000);
  EXPECT_GT(dropped, 1000);
  EXPECT_GT(culled, 1000);
}

// The definition on hand-made cases: the one candidate centre on a triangle's top edge is
// covered, on its bottom edge it is not (the top-left rule), and the facings and zero area.
TEST(TriangleFate, DecisionsOnKnownTriangles) {
  const int32_t one = limits::kSubpixelOne, c = one / 2;  // pixel (0, 0)'s centre is (c, c)
  auto v = [](int32_t x, int32_t y) { return ScreenVertex{x, y, 0.5f, 1.0f}; };
  // y down: (c - 40, c), (c + 40, c), (c, c + 60) has its top edge through the centre.
  const ScreenVertex top_a = v(c - 40, c), top_b = v(c + 40, c), top_c = v(c, c + 60);
  const TriangleDecision cw = decide_triangle(top_a, top_b, top_c, 8, 8, false);
  EXPECT_EQ(cw.fate, TriangleFate::kBack);  // clockwise on the y-down screen
  EXPECT_EQ(cw.box.x0, 0);
  EXPECT_EQ(cw.box.x1, 0);
  EXPECT_EQ(decide_triangle(top_a, top_c, top_b, 8, 8, false).fate, TriangleFate::kFront);
  EXPECT_EQ(decide_triangle(top_a, top_b, top_c, 8, 8, true).fate, TriangleFate::kCulled);
  EXPECT_EQ(decide_triangle(top_a, top_c, top_b, 8, 8, true).fate, TriangleFate::kFront);
  // Mirrored: the edge through the centre is now the bottom one.
  const ScreenVertex bottom_c = v(c, c - 60);
  EXPECT_EQ(decide_triangle(top_a, bottom_c, top_b, 8, 8, false).fate, TriangleFate::kCulled);
  EXPECT_EQ(decide_triangle(top_a, top_b, v(c + 80, c), 8, 8, false).fate, TriangleFate::kDropped);
  // Off the image: no centre in the clamped box.
  EXPECT_EQ(decide_triangle(v(-9 * one, c), v(-8 * one, c), v(-9 * one, 3 * one), 8, 8, false).fate,
            TriangleFate::kCulled);
}

}  // namespace
}  // namespace fastshade
