// --tile 0: large tiles on few workers (fewer per-tile passes over each triangle), smaller
// as workers multiply (the largest tile is the frame's critical path).
#include "exec/tile_size.h"

#include <gtest/gtest.h>

#include "core/limits.h"
#include "fastshade/render.h"
#include "fastshade/scene.h"

namespace fastshade {
namespace {

TEST(TileSize, ShrinksAsWorkersMultiply) {
  // 1080p: 135 tiles of 128 px, 510 of 64, 2040 of 32, 8160 of 16.
  EXPECT_EQ(sized_tile_px(1920, 1080, 1), 128);
  EXPECT_EQ(sized_tile_px(1920, 1080, 2), 128);
  EXPECT_EQ(sized_tile_px(1920, 1080, 4), 128);
  EXPECT_EQ(sized_tile_px(1920, 1080, 5), 64);
  EXPECT_EQ(sized_tile_px(1920, 1080, 8), 64);
  EXPECT_EQ(sized_tile_px(1920, 1080, 16), 32);
  EXPECT_EQ(sized_tile_px(1920, 1080, 63), 32);
  EXPECT_EQ(sized_tile_px(1920, 1080, 64), 16);
  // 4K: 510 tiles of 128 px.
  EXPECT_EQ(sized_tile_px(3840, 2160, 2), 128);
  EXPECT_EQ(sized_tile_px(3840, 2160, 15), 128);
  EXPECT_EQ(sized_tile_px(3840, 2160, 16), 64);
}

TEST(TileSize, StaysWithinItsRangeForAnyImage) {
  EXPECT_EQ(sized_tile_px(1, 1, 1), limits::kSizedTileMinPx);
  EXPECT_EQ(sized_tile_px(kMaxImageSide, kMaxImageSide, 1), limits::kSizedTileMaxPx);
  EXPECT_EQ(sized_tile_px(kMaxImageSide, kMaxImageSide, 1024), 64);  // 65536 tiles
  EXPECT_EQ(sized_tile_px(64, 64, 0), 16);  // no workers counts as one: 16 tiles < 32
}

TEST(TileSize, AnExplicitTileIsKept) {
  EXPECT_EQ(resolve_tile_px(8, 3840, 2160, 2), 8);
  EXPECT_EQ(resolve_tile_px(256, 64, 64, 64), 256);
  EXPECT_EQ(resolve_tile_px(0, 3840, 2160, 2), 128);
}

TEST(TileSize, TheRendererSizesTileZeroAndReportsIt) {
  const Scene scene = parse_scene(default_scene_json(), "<default scene>", ".");
  for (int threads : {1, 2, 8}) {
    RenderOptions options;
    options.tile_px = 0;
    options.threads = threads;
    RenderStats stats;
    render(scene, options, 1, &stats);
    EXPECT_EQ(stats.tile, sized_tile_px(scene.width, scene.height, threads)) << threads << " threads";
  }
  RenderOptions explicit_tile;
  explicit_tile.tile_px = 16;
  RenderStats stats;
  render(scene, explicit_tile, 1, &stats);
  EXPECT_EQ(stats.tile, 16);
  RenderOptions sized;
  sized.tile_px = 0;
  EXPECT_NE(sized.to_string().find("tile=auto"), std::string::npos);
  EXPECT_NE(RenderOptions{}.to_string().find("tile=64"), std::string::npos);
}

}  // namespace
}  // namespace fastshade
