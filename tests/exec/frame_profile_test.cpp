// The opt-in per-item timing hook and how its records become the model's phases.
#include <gtest/gtest.h>

#include <numeric>

#include "core/limits.h"
#include "exec/frame_profile.h"
#include "fastshade/render.h"
#include "fastshade/scene.h"

namespace fastshade {
namespace {

void expect_ms(const std::vector<double>& got, const std::vector<double>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], want[i], 1e-12) << "item " << i;
}

FrameProfile hand_made(uint64_t scale) {
  FrameProfile f;
  f.reset(/*chunks=*/2, /*tiles=*/3, /*vertex_count=*/limits::kVerticesPerBlock * 2 + 1);
  f.vertex_stage_ns = 3'000'000 * scale;  // 3 blocks of 1 ms each (times scale)
  f.setup_chunk_ns = {1'000'000 * scale, 2'000'000 * scale};
  f.count_chunk_ns = {100'000 * scale, 200'000 * scale};
  f.plan_bins_ns = 50'000 * scale;
  f.fill_chunk_ns = {300'000 * scale, 400'000 * scale};
  f.tile_ns = {0, 5'000'000 * scale, 7'000'000 * scale};
  f.total_ns = 20'000'000 * scale;  // 19.05 ms covered by items, 0.95 ms "other"
  return f;
}

TEST(FrameProfile, PhasesTakeItemMediansInRendererOrder) {
  const std::vector<FrameProfile> frames = {hand_made(1), hand_made(3), hand_made(2)};
  const std::vector<SchedulePhase> phases = schedule_phases(frames);  // medians: scale 2
  ASSERT_EQ(phases.size(), 7u);
  const char* stages[] = {"front_end", "front_end", "binning", "binning", "binning", "raster_shade", "other"};
  const char* names[] = {"vertex blocks", "setup chunks", "count chunks", "bin plan", "fill chunks", "tiles",
                         "loop start/join"};
  for (std::size_t i = 0; i < phases.size(); ++i) {
    EXPECT_EQ(phases[i].stage, stages[i]) << i;
    EXPECT_EQ(phases[i].name, names[i]) << i;
  }
  expect_ms(phases[0].item_ms, {2, 2, 2});
  expect_ms(phases[1].item_ms, {2, 4});
  expect_ms(phases[2].item_ms, {0.2, 0.4});
  expect_ms(phases[3].item_ms, {0.1});
  expect_ms(phases[4].item_ms, {0.6, 0.8});
  expect_ms(phases[5].item_ms, {0, 10, 14});
  expect_ms(phases[6].item_ms, {1.9});
  // One worker: the frame's median total.
  EXPECT_NEAR(predict_schedule(phases, 1).total_ms, 40.0, 1e-9);
}

TEST(FrameProfile, OtherIsNeverNegativeAndMismatchedFramesAreRefused) {
  FrameProfile f = hand_made(1);
  f.total_ns = 1;  // a clock that ran backwards relative to the items
  expect_ms(schedule_phases(std::vector<FrameProfile>{f}).back().item_ms, {0.0});
  FrameProfile g = hand_made(1);
  g.tile_ns.push_back(1);
  EXPECT_THROW(schedule_phases(std::vector<FrameProfile>{f, g}), std::invalid_argument);
  EXPECT_THROW(schedule_phases(std::vector<FrameProfile>{}), std::invalid_argument);
}

TEST(FrameProfile, TheBinPlanIsSharedByItsTileBlocks) {
  FrameProfile f = hand_made(1);
  f.tile_ns.assign(limits::kBinPlanTiles + 1, 0);
  expect_ms(schedule_phases(std::vector<FrameProfile>{f})[3].item_ms, {0.025, 0.025});
}

TEST(FrameProfile, RendererFillsEveryItemAndDrawsTheSameImage) {
  const Scene scene = parse_scene(default_scene_json(), "<default scene>", ".");
  RenderOptions options;
  options.threads = 1;
  options.tile_px = 32;
  Renderer renderer(scene, options);
  const Image plain = renderer.render_frame();
  FrameProfile profile;
  StageTimes times;
  const Image profiled = renderer.render_frame(&times, &profile);
  EXPECT_EQ(plain.rgb, profiled.rgb);
  const int tiles = ((scene.width + 31) / 32) * ((scene.height + 31) / 32);
  ASSERT_EQ(profile.tile_ns.size(), std::size_t(tiles));
  EXPECT_GT(profile.vertices, 0u);
  EXPECT_GT(profile.vertex_stage_ns, 0u);
  EXPECT_FALSE(profile.setup_chunk_ns.empty());
  EXPECT_EQ(profile.count_chunk_ns.size(), profile.setup_chunk_ns.size());
  EXPECT_EQ(profile.fill_chunk_ns.size(), profile.setup_chunk_ns.size());
  for (const uint64_t ns : profile.setup_chunk_ns) EXPECT_GT(ns, 0u);
  for (const uint64_t ns : profile.tile_ns) EXPECT_GT(ns, 0u);  // even an empty tile is filled
  const uint64_t tiles_ns = std::accumulate(profile.tile_ns.begin(), profile.tile_ns.end(), uint64_t(0));
  EXPECT_LE(tiles_ns, profile.total_ns);
  EXPECT_EQ(profile.total_ns, static_cast<uint64_t>(times.total * 1e6));
}

}  // namespace
}  // namespace fastshade
