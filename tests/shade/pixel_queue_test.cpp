// The pixel queue (shade/pixel_queue.h): SIMD lighting equals its scalar reference on every
// ISA, every BRDF and sRGB or not, for queue lengths 0..2W+1 (W up to 16), colours land in the
// order the entries came (a pixel queued twice keeps the later colour), and lighting whole
// vectors first, then the rest, ends where lighting all at once does.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include <glm/geometric.hpp>

#include "exec/isa.h"
#include "shade/brdf.h"
#include "shade/method.h"
#include "shade/pixel_queue.h"

namespace fastshade {
namespace {

struct QueueCase {
  ShadeConstants k;
  MaterialConstants m;
  std::vector<uint32_t> color = std::vector<uint32_t>(64, 0xDEADBEEFu);
  std::vector<float> depth = std::vector<float>(64, 1.0f);
  TileTarget target() {
    TileTarget t{color.data(), depth.data(), 8, 0, 0, {0, 0, 7, 7}};
    t.alpha_xor = 0x02000000u;
    return t;
  }
};

// `count` random normals (some long, some near zero, some pointing away) at random pixels of
// an 8 x 8 tile: with 64 pixels and up to 33 entries, many pixels are queued twice.
void fill(PixelQueue& q, int count, std::mt19937& rng) {
  std::uniform_real_distribution<float> u(-1.5f, 1.5f);
  std::uniform_int_distribution<int> px(0, 63);
  q.count = count;
  for (int i = 0; i < count; ++i) {
    q.nx[i] = u(rng), q.ny[i] = u(rng), q.nz[i] = u(rng);
    if (i % 7 == 3) q.nx[i] = q.ny[i] = q.nz[i] = 1e-30f;  // below InvSqrt's range: becomes zero
    q.at[i] = px(rng);
  }
}

TEST(PixelQueue, LightingMatchesScalarOnEveryIsaBrdfAndLength) {
  std::mt19937 rng(7);
  QueueCase c;
  c.k.ambient = glm::vec3(0.05f);
  c.k.lights.push_back({glm::normalize(glm::vec3(1, 1, 1)), glm::normalize(glm::vec3(1, 1, 2.732f)), glm::vec3(0.9f)});
  c.k.lights.push_back({glm::normalize(glm::vec3(-1, 0.2f, 0.5f)), glm::vec3(0), glm::vec3(0.4f, 0.5f, 0.6f)});
  c.k.lights[1].h_view = glm::normalize(c.k.lights[1].l_view + glm::vec3(0, 0, 1));
  int checked = 0;
  for (const std::string& isa : available_isas()) {
    select_isa(isa);
    for (const std::string& brdf : brdf_names())
      for (bool srgb : {false, true}) {
        c.k.srgb = srgb;
        c.m = {glm::vec3(0.6f, 0.5f, 0.4f), glm::vec3(0.5f), 40.0f, 40.0, make_brdf(parse_brdf(brdf, "test"), 40.0)};
        for (int count = 0; count <= 2 * 16 + 1; ++count) {
          PixelQueue simd;
          fill(simd, count, rng);
          simd.material = &c.m;
          simd.shade = &c.k;
          PixelQueue scalar = simd;
          QueueCase a = c, b = c;
          light_pixel_queue(simd, a.target(), true);
          light_pixel_queue_scalar(scalar, b.target());
          ASSERT_EQ(simd.count, 0);
          ASSERT_EQ(a.color, b.color) << isa << " " << brdf << " srgb " << srgb << " count " << count;
          ASSERT_EQ(a.depth, c.depth) << "lighting never writes depth";
          ++checked;
        }
      }
  }
  select_isa("best");
  EXPECT_GT(checked, 0);
}

TEST(PixelQueue, LaterEntriesWinAndWholeVectorsFirstEndsTheSame) {
  std::mt19937 rng(8);
  QueueCase c;
  c.k.ambient = glm::vec3(0.1f);
  c.k.lights.push_back({glm::normalize(glm::vec3(1, 1, 1)), glm::normalize(glm::vec3(1, 1, 2.732f)), glm::vec3(1.0f)});
  c.m = {glm::vec3(0.7f), glm::vec3(0.5f), 32.0f, 32.0, make_brdf(parse_brdf("exact", "test"), 32.0)};
  for (const std::string& isa : available_isas()) {
    select_isa(isa);
    for (int count = 0; count <= 2 * 16 + 1; ++count) {
      PixelQueue q;
      fill(q, count, rng);
      q.material = &c.m;
      q.shade = &c.k;
      // The same pixel twice: a normal toward the light, then one away from it.
      if (count >= 2) {
        q.at[0] = q.at[count - 1] = 5;
        q.nx[0] = q.ny[0] = q.nz[0] = 1.0f;
        q.nx[count - 1] = q.ny[count - 1] = q.nz[count - 1] = -1.0f;
      }
      PixelQueue whole = q;
      QueueCase a = c, b = c;
      light_pixel_queue(whole, a.target(), false);
      ASSERT_LT(whole.count, 16) << isa << ": at most a partial vector waits";
      ASSERT_LE(whole.count, count) << isa;
      light_pixel_queue(whole, a.target(), true);
      light_pixel_queue(q, b.target(), true);
      ASSERT_EQ(a.color, b.color) << isa << " count " << count;
      if (count >= 2) {
        // Away from the light: ambient only, 0.1 -> level 26, alpha 0xFF ^ 2.
        EXPECT_EQ(b.color[5], 0xFD1A1A1Au) << isa << " count " << count;
      }
    }
  }
  select_isa("best");
}

}  // namespace
}  // namespace fastshade
