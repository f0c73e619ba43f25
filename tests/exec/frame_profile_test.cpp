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
  const double s = double(scale);
  FrameProfile f;
  f.reset(/*chunks=*/2, /*tiles=*/3, /*vertex_count=*/limits::kVerticesPerBlock * 2 + 1);
  f.vertex_stage_ns = 3'000'000 * scale;  // 3 blocks of 1 ms each (times scale)
  f.setup_chunk_ns = {1'000'000 * scale, 2'000'000 * scale};
  f.plan_bins_ns = 50'000 * scale;
  f.fill_chunk_ns = {300'000 * scale, 400'000 * scale};
  f.tile_ns = {0, 5'000'000 * scale, 7'000'000 * scale};
  // Walls beyond the items: front end 0.5 ms over 5 items, binning 0.06 ms over 3, raster
  // 0.3 ms over 3; the frame 0.1 ms beyond its stages.
  f.stages = {6.5 * s, 0.81 * s, 12.3 * s, 19.71 * s};
  return f;
}

TEST(FrameProfile, PhasesTakeItemMediansInRendererOrder) {
  const std::vector<FrameProfile> frames = {hand_made(1), hand_made(3), hand_made(2)};
  const std::vector<SchedulePhase> phases = schedule_phases(frames);  // medians: scale 2
  ASSERT_EQ(phases.size(), 6u);
  const char* stages[] = {"front_end", "front_end", "binning", "binning", "raster_shade", "other"};
  const char* names[] = {"vertex blocks", "setup chunks", "bin plan", "fill chunks", "tiles", "between stages"};
  for (std::size_t i = 0; i < phases.size(); ++i) {
    EXPECT_EQ(phases[i].stage, stages[i]) << i;
    EXPECT_EQ(phases[i].name, names[i]) << i;
    EXPECT_EQ(phases[i].timed_whole, i == 0 || i == 2) << i;
  }
  expect_ms(phases[0].item_ms, {2.2, 2.2, 2.2});
  expect_ms(phases[1].item_ms, {2.2, 4.2});
  expect_ms(phases[2].item_ms, {0.14});
  expect_ms(phases[3].item_ms, {0.64, 0.84});
  expect_ms(phases[4].item_ms, {0.2, 10.2, 14.2});
  expect_ms(phases[5].item_ms, {0.2});
  // One worker: the frame's median total.
  EXPECT_NEAR(predict_schedule(phases, 1).total_ms, 39.42, 1e-9);
  // Items as measured: no overheads spread, nothing between stages.
  const std::vector<SchedulePhase> raw = schedule_phases(frames, /*with_overheads=*/false);
  expect_ms(raw[0].item_ms, {2, 2, 2});
  expect_ms(raw[1].item_ms, {2, 4});
  expect_ms(raw[4].item_ms, {0, 10, 14});
  expect_ms(raw[5].item_ms, {0.0});
}

TEST(FrameProfile, NothingBeyondTheItemsIsNeverNegativeAndMismatchedFramesAreRefused) {
  FrameProfile f = hand_made(1);
  f.stages = {};  // clocks that ran short of the items
  const std::vector<SchedulePhase> phases = schedule_phases(std::vector<FrameProfile>{f});
  expect_ms(phases[4].item_ms, {0, 5, 7});
  expect_ms(phases.back().item_ms, {0.0});
  FrameProfile g = hand_made(1);
  g.tile_ns.push_back(1);
  EXPECT_THROW(schedule_phases(std::vector<FrameProfile>{f, g}), std::invalid_argument);
  EXPECT_THROW(schedule_phases(std::vector<FrameProfile>{}), std::invalid_argument);
}

TEST(FrameProfile, TheBinPlanIsSharedByItsTileBlocks) {
  FrameProfile f = hand_made(1);
  f.tile_ns.assign(limits::kBinPlanTiles + 1, 0);
  f.stages = {};
  expect_ms(schedule_phases(std::vector<FrameProfile>{f})[2].item_ms, {0.025, 0.025});
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
  EXPECT_EQ(profile.fill_chunk_ns.size(), profile.setup_chunk_ns.size());
  for (const uint64_t ns : profile.setup_chunk_ns) EXPECT_GT(ns, 0u);
  for (const uint64_t ns : profile.tile_ns) EXPECT_GT(ns, 0u);  // even an empty tile is filled
  const uint64_t tiles_ns = std::accumulate(profile.tile_ns.begin(), profile.tile_ns.end(), uint64_t(0));
  EXPECT_LE(double(tiles_ns) * 1e-6, times.raster_shade);
  EXPECT_EQ(profile.stages.total, times.total);
}

}  // namespace
}  // namespace fastshade
