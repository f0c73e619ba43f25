// The same scene gives a byte-identical image for any thread count and any tile size.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "fastshade/render.h"
#include "fastshade/scene.h"

namespace fastshade {
namespace {

void expect_identical_across_threads_and_tiles(const Scene& scene, const std::string& method,
                                               const std::string& name,
                                               const std::string& normals = "normalize") {
  RenderOptions base;
  base.method = parse_option<ShadingMethod>(method, "method");
  base.normals = parse_option<PhongNormals>(normals, "normals");
  base.threads = 1;
  base.tile_px = 64;
  const Image expected = render(scene, base);
  for (int threads : {1, 2, 4})
    for (int tile : {8, 16, 64, 256}) {
      RenderOptions o = base;
      o.threads = threads;
      o.tile_px = tile;
      const Image got = render(scene, o);
      ASSERT_EQ(got.rgb.size(), expected.rgb.size());
      std::size_t first_diff = 0;
      while (first_diff < got.rgb.size() && got.rgb[first_diff] == expected.rgb[first_diff]) ++first_diff;
      EXPECT_EQ(first_diff, got.rgb.size())
          << name << " " << method << ": threads " << threads << " tile " << tile
          << " differs at pixel (" << (first_diff / 3) % got.width << ", "
          << (first_diff / 3) / got.width << ")";
    }
}

TEST(Determinism, SceneFilesAreByteIdenticalForAnyThreadsAndTiles) {
  const std::filesystem::path scenes = std::filesystem::path(FASTSHADE_SOURCE_DIR) / "scenes";
  int count = 0;
  for (const char* file : {"default.json", "spheres.json", "torus_local.json"}) {
    const Scene scene = load_scene(scenes / file);
    for (const char* method : {"auto", "phong", "gouraud", "hybrid", "reference"})
      expect_identical_across_threads_and_tiles(scene, method, file);
    // Sierpinski parts are drawn as separate tasks but must give the parent's image exactly.
    RenderOptions whole, parts;
    whole.method = parts.method = ShadingMethod::Gouraud;
    parts.gouraud = GouraudMode::Sierpinski;
    RenderStats split_stats, whole_stats;
    const Image a = render(scene, whole, 1, &whole_stats), b = render(scene, parts, 1, &split_stats);
    EXPECT_EQ(a.rgb, b.rgb) << file << ": gouraud sierpinski differs from gouraud";
    EXPECT_GE(split_stats.triangles_drawn, whole_stats.triangles_drawn) << file;
    for (const char* normals : {"adaptive", "equal-angle"})
      expect_identical_across_threads_and_tiles(scene, "phong", file, normals);
    ++count;
  }
  EXPECT_EQ(count, 3);
}

// Timed loops render into one buffer: every pixel must be rewritten, whatever it held.
TEST(Determinism, AReusedBufferGivesTheFreshImage) {
  const Scene scene = load_scene(std::filesystem::path(FASTSHADE_SOURCE_DIR) / "scenes" / "spheres.json");
  RenderOptions o;
  o.tile_px = 32;
  Renderer renderer(scene, o);
  const Image fresh = renderer.render_frame();
  Image reused = fresh;
  std::fill(reused.rgb.begin(), reused.rgb.end(), uint8_t{0x5A});  // not the background
  renderer.render_frame(reused);
  EXPECT_EQ(reused.rgb, fresh.rgb);
  Image wrong_size;
  wrong_size.width = wrong_size.height = 3;
  wrong_size.rgb.assign(27, 0x5A);
  renderer.render_frame(wrong_size);
  EXPECT_EQ(wrong_size.width, fresh.width);
  EXPECT_EQ(wrong_size.rgb, fresh.rgb);
}

}  // namespace
}  // namespace fastshade
