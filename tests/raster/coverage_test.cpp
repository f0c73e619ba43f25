// Raster rules: exact coverage of shared-edge meshes (no gaps, no double hits) and pixel-for-
// pixel agreement with a brute-force rasterizer, through the real front end, bins and tiles.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "support/coverage_harness.h"
#include "support/snapped_hit.h"

namespace fastshade::test {
namespace {

using Tri = std::array<glm::vec4, 3>;

// Expects every pixel hit exactly once; names the first failure.
void expect_exactly_once(const CoverageResult& r, const std::string& what) {
  int bad = 0;
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x)
      if (r.at(x, y) != 1 && bad++ == 0)
        ADD_FAILURE() << what << ": pixel (" << x << ", " << y << ") covered " << r.at(x, y)
                      << " times";
  EXPECT_EQ(bad, 0) << what;
}

// A W x H grid of cells over the image, each split along a diagonal; vertices moved by
// `jitter` (sub-pixel, less than half a cell, so nothing folds). Border vertices stay on the
// border so the mesh covers the image exactly. `w_of` gives each vertex its clip w.
std::vector<Tri> grid_mesh(int width, int height, int cells_x, int cells_y, double offset,
                           double jitter, std::mt19937& rng, bool random_w, bool random_diagonal) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), w_dist(0.2, 5.0);
  std::bernoulli_distribution coin(0.5);
  std::vector<glm::vec4> v((cells_x + 1) * (cells_y + 1));
  for (int j = 0; j <= cells_y; ++j)
    for (int i = 0; i <= cells_x; ++i) {
      double x = double(i) * width / cells_x, y = double(j) * height / cells_y;
      if (i > 0 && i < cells_x) x += offset + jitter * u(rng);
      if (j > 0 && j < cells_y) y += offset + jitter * u(rng);
      v[j * (cells_x + 1) + i] = screen_to_clip(x, y, width, height, random_w ? w_dist(rng) : 1.0);
    }
  std::vector<Tri> tris;
  for (int j = 0; j < cells_y; ++j)
    for (int i = 0; i < cells_x; ++i) {
      const glm::vec4 a = v[j * (cells_x + 1) + i], b = v[j * (cells_x + 1) + i + 1];
      const glm::vec4 c = v[(j + 1) * (cells_x + 1) + i], d = v[(j + 1) * (cells_x + 1) + i + 1];
      if (!random_diagonal || coin(rng)) {
        tris.push_back({a, b, d});
        tris.push_back({a, d, c});
      } else {
        tris.push_back({a, b, c});
        tris.push_back({b, d, c});
      }
    }
  return tris;
}

TEST(Coverage, QuadGridOnPixelCentresCoversEveryPixelOnce) {
  std::mt19937 rng(1);
  // Offset 0.5 puts every interior edge of the grid through pixel centres: the top-left rule
  // alone decides who owns them. 12-px cells make diagonals cross centres too.
  for (double offset : {0.0, 0.5})
    for (int tile : {8, 64}) {
      const auto tris = grid_mesh(192, 120, 16, 10, offset, 0.0, rng, false, false);
      expect_exactly_once(rasterize_clip_triangles(tris, 192, 120, tile),
                          "grid offset " + std::to_string(offset) + " tile " + std::to_string(tile));
    }
}

TEST(Coverage, FanAroundSubPixelPointCoversEveryPixelOnce) {
  const int w = 97, h = 61;
  // Centres exactly on a pixel centre, on a pixel corner and at an arbitrary sub-pixel spot.
  for (const glm::dvec2 centre : {glm::dvec2(40.5, 30.5), glm::dvec2(40.0, 30.0), glm::dvec2(40.3, 29.8)}) {
    // Points around the image border, corners included, at uneven sub-pixel spacing.
    std::vector<glm::dvec2> ring;
    const glm::dvec2 corners[5] = {{0, 0}, {double(w), 0}, {double(w), double(h)}, {0, double(h)}, {0, 0}};
    for (int side = 0; side < 4; ++side)
      for (int k = 0; k < 9; ++k)
        ring.push_back(corners[side] + (corners[side + 1] - corners[side]) * (k * k / 81.0));
    const int n = static_cast<int>(ring.size());
    std::vector<Tri> tris;
    for (int i = 0; i < n; ++i) {
      const glm::dvec2 a = ring[i], b = ring[(i + 1) % n];
      tris.push_back({screen_to_clip(centre.x, centre.y, w, h), screen_to_clip(a.x, a.y, w, h),
                      screen_to_clip(b.x, b.y, w, h)});
    }
    const CoverageResult r = rasterize_clip_triangles(tris, w, h, 16);
    expect_exactly_once(r, "fan");
  }
}

TEST(Coverage, RandomSubPixelTriangulationsCoverEveryPixelOnce) {
  std::mt19937 rng(7);
  for (int round = 0; round < 12; ++round) {
    const int tile = 8 << (round % 6);
    const bool perspective = round % 2 == 1;
    // Jitter under a quarter cell keeps every quad convex, so either diagonal splits it.
    const double cell = std::min(200.0 / (13 + round), 150.0 / (9 + round));
    const auto tris = grid_mesh(200, 150, 13 + round, 9 + round, 0.0, 0.24 * cell, rng, perspective, true);
    expect_exactly_once(rasterize_clip_triangles(tris, 200, 150, tile, 16 + round * 7),
                        "round " + std::to_string(round) + " tile " + std::to_string(tile));
  }
}

// Sierpinski parts (midpoints on the ninth sub-pixel bit) cover exactly their parent: the same
// pixels, once, for random large triangles and for a mesh of large shared-edge triangles.
TEST(Coverage, SierpinskiPartsCoverExactlyTheirParent) {
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> u(-30.0, 290.0);
  const int w = 256, h = 192;
  for (int n = 0; n < 60; ++n) {
    const Tri t = {screen_to_clip(u(rng) + 0.37, u(rng) * 0.75 + 0.11, w, h),
                   screen_to_clip(u(rng) + 0.61, u(rng) * 0.75 + 0.93, w, h),
                   screen_to_clip(u(rng) + 0.05, u(rng) * 0.75 + 0.49, w, h)};
    const CoverageResult whole = rasterize_clip_triangles({t}, w, h, 16);
    const CoverageResult parts = rasterize_clip_triangles({t}, w, h, 16, 64, Cull::None, true);
    ASSERT_EQ(parts.hits, whole.hits) << "triangle " << n;
  }
  std::mt19937 rng2(32);
  const auto mesh = grid_mesh(w, h, 4, 3, 0.5, 0.2 * 64, rng2, true, true);
  const CoverageResult split = rasterize_clip_triangles(mesh, w, h, 32, 64, Cull::None, true);
  EXPECT_GT(split.drawn, static_cast<long long>(mesh.size()) * 3) << "the triangles were not split";
  expect_exactly_once(split, "sierpinski mesh");
}

TEST(Coverage, DegenerateAndNonFiniteTrianglesAreDroppedNotDrawn) {
  const int w = 64, h = 64;
  const glm::vec4 a = screen_to_clip(10, 10, w, h), b = screen_to_clip(50, 10, w, h);
  const float nan = std::nanf("");
  const std::vector<Tri> tris = {
      {a, b, screen_to_clip(30, 10, w, h)},           // collinear
      {a, a, a},                                      // a point
      {a, b, glm::vec4(nan, 0, 0, 1)},                // NaN
      {a, b, glm::vec4(0, INFINITY, 0, 1)},           // Inf
  };
  const CoverageResult r = rasterize_clip_triangles(tris, w, h, 16);
  EXPECT_EQ(r.dropped, 4);
  EXPECT_EQ(r.drawn, 0);
  for (int hits : r.hits) ASSERT_EQ(hits, 0);
}

// ---- brute force -----------------------------------------------------------------------

// Independent coverage of one clip-space triangle at a screen point (pixels, y down):
// homogeneous barycentrics b = M^-1 (x_ndc, y_ndc, 1) are all >= 0 with a positive sum exactly
// where the ray hits the triangle in front of the eye; z_ndc = sum b_i z_i must lie in [-1, 1].
bool brute_force_hit(const Tri& t, double x_px, double y_px, int width, int height) {
  const double px = x_px / width * 2.0 - 1.0, py = 1.0 - y_px / height * 2.0;
  const glm::dmat3 m(glm::dvec3(t[0].x, t[0].y, t[0].w), glm::dvec3(t[1].x, t[1].y, t[1].w),
                     glm::dvec3(t[2].x, t[2].y, t[2].w));
  if (std::fabs(glm::determinant(m)) < 1e-300) return false;
  const glm::dvec3 b = glm::inverse(m) * glm::dvec3(px, py, 1.0);
  const double sum = b.x + b.y + b.z;
  if (!(sum > 0) || b.x < 0 || b.y < 0 || b.z < 0) return false;
  const double z_ndc = (b.x * t[0].z + b.y * t[1].z + b.z * t[2].z);
  return z_ndc >= -1.0 && z_ndc <= 1.0;
}

// The pipeline snaps vertices to 1/256 px; a centre within that of an edge may go either way.
bool ambiguous(const Tri& t, int x, int y, int width, int height) {
  const double c = brute_force_hit(t, x + 0.5, y + 0.5, width, height);
  const double e = 1.0 / 64;
  for (const auto& [dx, dy] : {std::pair{e, 0.0}, {-e, 0.0}, {0.0, e}, {0.0, -e}})
    if (brute_force_hit(t, x + 0.5 + dx, y + 0.5 + dy, width, height) != c) return true;
  return false;
}

TEST(Coverage, TopLeftRuleOwnsCentresOnTopAndLeftEdgesOnly) {
  // A square from (10.5, 20.5) to (30.5, 44.5): its border runs through pixel centres. The
  // top-left rule keeps the top row and left column, drops the bottom row and right column.
  const int w = 64, h = 64;
  for (int diagonal = 0; diagonal < 2; ++diagonal) {
    const glm::vec4 a = screen_to_clip(10.5, 20.5, w, h), b = screen_to_clip(30.5, 20.5, w, h);
    const glm::vec4 c = screen_to_clip(10.5, 44.5, w, h), d = screen_to_clip(30.5, 44.5, w, h);
    const std::vector<Tri> tris = diagonal ? std::vector<Tri>{{a, b, d}, {a, d, c}}
                                           : std::vector<Tri>{{a, b, c}, {b, d, c}};
    const CoverageResult r = rasterize_clip_triangles(tris, w, h, 16);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        ASSERT_EQ(r.at(x, y), (x >= 10 && x < 30 && y >= 20 && y < 44) ? 1 : 0)
            << "pixel (" << x << ", " << y << ") diagonal " << diagonal;
  }
}

TEST(Coverage, AgreesWithBruteForceOnRandomTriangles) {
  std::mt19937 rng(2024);
  const int w = 120, h = 90;
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  int checked_exact = 0, checked_clipped = 0;
  for (int n = 0; n < 400; ++n) {
    const int kind = n % 4;  // 0: inside, 1: crossing near/far, 2: guard band, 3: behind the eye
    Tri t;
    for (auto& v : t) {
      float w_clip = 0.5f + 1.5f * (u(rng) + 1.0f);
      float reach = kind == 2 ? 2000.0f : 1.3f;
      float z = 0.9f * u(rng);
      if (kind == 1) z = 1.6f * u(rng);
      if (kind == 3) w_clip = 2.0f * u(rng);
      v = glm::vec4(reach * u(rng) * std::fabs(w_clip), reach * u(rng) * std::fabs(w_clip), z * std::fabs(w_clip), w_clip);
    }
    if (kind == 0 && n % 8 == 0)  // vertices on pixel centres: edges through centres, ties
      for (auto& v : t)
        v = screen_to_clip(std::floor((u(rng) + 1.0f) * w * 0.6f) + 0.5,
                           std::floor((u(rng) + 1.0f) * h * 0.6f) + 0.5, w, h, v.w);
    if (kind == 0 && n % 8 == 4) {  // small triangles take the narrow-rectangle path
      const float cx = u(rng) * 0.8f, cy = u(rng) * 0.8f;
      for (auto& v : t) v = glm::vec4(cx + 0.1f * u(rng), cy + 0.1f * u(rng), 0.5f * u(rng), 1.0f);
    }
    bool needs_clip = false;
    for (const auto& v : t)
      needs_clip |= !(v.w > 0 && v.z >= -v.w && v.z <= v.w && std::fabs(v.x) <= 100 * v.w &&
                      std::fabs(v.y) <= 100 * v.w);
    const CoverageResult r = rasterize_clip_triangles({t}, w, h, 32);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const int got = r.at(x, y);
        if (!needs_clip) {
          ASSERT_EQ(got, snapped_hit(t, x, y, w, h) ? 1 : 0)
              << "triangle " << n << " pixel (" << x << ", " << y << ")";
          ++checked_exact;
        } else if (!ambiguous(t, x, y, w, h)) {
          ASSERT_EQ(got, brute_force_hit(t, x + 0.5, y + 0.5, w, h) ? 1 : 0)
              << "clipped triangle " << n << " kind " << kind << " pixel (" << x << ", " << y << ")";
          ++checked_clipped;
        }
      }
  }
  EXPECT_GT(checked_exact, 100000);
  EXPECT_GT(checked_clipped, 100000);
}

}  // namespace
}  // namespace fastshade::test
