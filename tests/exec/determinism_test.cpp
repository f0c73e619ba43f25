// The same scene gives a byte-identical image for any thread count and any tile size.
#include <gtest/gtest.h>

#include <filesystem>

#include "fastshade/render.h"
#include "fastshade/scene.h"

namespace fastshade {
namespace {

void expect_identical_across_threads_and_tiles(const Scene& scene, const std::string& method,
                                               const std::string& name,
                                               const std::string& normals = "normalize") {
  RenderOptions base;
  base.method = method;
  base.normals = normals;
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
    whole.method = parts.method = "gouraud";
    parts.gouraud = "sierpinski";
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

}  // namespace
}  // namespace fastshade
