// The pixel queue (shade/pixel_queue.h): SIMD lighting equals its scalar reference on every
// ISA, every BRDF and sRGB or not, for queue lengths 0..2W+1 (W up to 16), colours land in the
// order the entries came (a pixel queued twice keeps the later colour), and lighting whole
// vectors first, then the rest, ends where lighting all at once does; in whole frames, pixels
// that wait are never left over a later triangle's (draw order with row spans, materials and
// the double-precision fallback in one tile).
#include <gtest/gtest.h>

#include <random>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "core/simd_target.h"
#include "fastshade/compare.h"
#include "fastshade/render.h"
#include "fastshade/scene.h"
#include "light/brdf.h"
#include "shade/method.h"
#include "shade/span_kernels_testing.h"

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
  q.alpha_xor = 0x02000000u;  // as QueueCase::target()
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
  for (const Isa isa_id : available_isas()) {
    const std::string isa(option_name(isa_id));
    const SimdTarget simd = simd_target(isa_id);
    for (const BrdfChoice& brdf : brdf_choices())
      for (bool srgb : {false, true}) {
        c.k.srgb = srgb;
        c.m = {glm::vec3(0.6f, 0.5f, 0.4f), glm::vec3(0.5f), 40.0f, 40.0, make_brdf(brdf, 40.0)};
        for (int count = 0; count <= 2 * 16 + 1; ++count) {
          PixelQueue lanes;
          fill(lanes, count, rng);
          lanes.material = &c.m;
          lanes.shade = &c.k;
          PixelQueue scalar = lanes;
          QueueCase a = c, b = c;
          light_pixel_queue(simd, lanes, a.target(), true);
          light_pixel_queue_scalar(scalar, b.target());
          ASSERT_EQ(lanes.count, 0);
          ASSERT_EQ(a.color, b.color) << isa << " " << option_name(brdf) << " srgb " << srgb << " count " << count;
          ASSERT_EQ(a.depth, c.depth) << "lighting never writes depth";
          ++checked;
        }
      }
  }
  EXPECT_GT(checked, 0);
}

TEST(PixelQueue, LaterEntriesWinAndWholeVectorsFirstEndsTheSame) {
  std::mt19937 rng(8);
  QueueCase c;
  c.k.ambient = glm::vec3(0.1f);
  c.k.lights.push_back({glm::normalize(glm::vec3(1, 1, 1)), glm::normalize(glm::vec3(1, 1, 2.732f)), glm::vec3(1.0f)});
  c.m = {glm::vec3(0.7f), glm::vec3(0.5f), 32.0f, 32.0, make_brdf(parse_option<BrdfChoice>("exact", "test"), 32.0)};
  for (const Isa isa_id : available_isas()) {
    const std::string isa(option_name(isa_id));
    const SimdTarget simd = simd_target(isa_id);
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
      light_pixel_queue(simd, whole, a.target(), false);
      ASSERT_LT(whole.count, 16) << isa << ": at most a partial vector waits";
      ASSERT_LE(whole.count, count) << isa;
      light_pixel_queue(simd, whole, a.target(), true);
      // Lit through another path's target (auto does), the entries keep the tag they came with.
      TileTarget untagged = b.target();
      untagged.alpha_xor = 0;
      light_pixel_queue(simd, q, untagged, true);
      ASSERT_EQ(a.color, b.color) << isa << " count " << count;
      if (count >= 2) {
        // Away from the light: ambient only, 0.1 -> level 26, alpha 0xFF ^ 2.
        EXPECT_EQ(b.color[5], 0xFD1A1A1Au) << isa << " count " << count;
      }
    }
  }
}


// Sub-pixel triangles (queued) under a large matte quad drawn after them (row spans, stored at
// once; in auto, diffuse-only Gouraud) under a second fine sphere of another material, and a
// material shaded in double:
// were a waiting pixel lit after a later triangle stored its colour, the quad would show the
// sphere's colour, tens of LSB from `reference`. phong's own bound is 1 LSB; hybrid queues its
// narrow triangles and stores its wide ones at once, and auto mixes both with its diffuse
// paths, which store at once: 2 LSB (auto's bound anywhere) for those.
TEST(PixelQueue, WholeFramesKeepDrawOrderAgainstReference) {
  const Scene scene = parse_scene(R"({
    "image": {"width": 256, "height": 192, "background": [0, 0, 0]},
    "camera": {"eye": [0, 0, 4], "target": [0, 0, 0], "up": [0, 1, 0], "fovy_deg": 45, "near": 0.5, "far": 20},
    "ambient": [0.05, 0.05, 0.05],
    "lights": [{"direction": [0.3, 0.5, 1], "color": [1, 1, 1], "space": "view"}],
    "materials": {
      "red": {"diffuse": [0.8, 0.1, 0.1], "specular": 0.4, "shininess": 20},
      "matte": {"diffuse": [0.1, 0.2, 0.9], "specular": 0},
      "sharp": {"diffuse": [0.2, 0.7, 0.2], "specular": 0.5, "shininess": 100000}
    },
    "objects": [
      {"primitive": "icosphere", "subdivisions": 6, "radius": 1, "material": "red"},
      {"primitive": "plane", "size": 1.2, "material": "matte",
       "transform": {"rotate_deg": [90, 0, 0], "translate": [0.4, 0, 1.2]}},
      {"primitive": "icosphere", "subdivisions": 5, "radius": 0.25, "material": "sharp",
       "transform": {"translate": [0.3, 0.3, 1.5]}},
      {"primitive": "icosphere", "subdivisions": 5, "radius": 0.3, "material": "red",
       "transform": {"translate": [-0.6, -0.4, 1.3]}}
    ]
  })", "pixel queue order", ".");
  RenderOptions ref_options;
  ref_options.method = ShadingMethod::Reference;
  const ImageF reference = to_float(render(scene, ref_options));
  for (const auto& [method, bound] : {std::pair{ShadingMethod::Phong, 1.0}, std::pair{ShadingMethod::Hybrid, 2.0},
                                     std::pair{ShadingMethod::Auto, 2.0}})
    for (int threads : {1, 2})
      for (int tile : {8, 64, 256}) {
        RenderOptions o;
        o.method = method;
        o.threads = threads;
        o.tile_px = tile;
        const ImageDiff diff = compare_images(to_float(render(scene, o)), reference);
        EXPECT_LE(diff.max_abs_lsb, bound) << option_name(method) << " threads " << threads << " tile " << tile
                                           << ": worst at (" << diff.worst_x << ", " << diff.worst_y << ")";
      }
}

}  // namespace
}  // namespace fastshade
