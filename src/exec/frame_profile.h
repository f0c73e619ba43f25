// Opt-in per-item costs of one frame, recorded when Renderer::render_frame is given a profile:
// what the load-balance model (exec/schedule_model.h) replays. Off (a null profile) it costs
// one predictable branch per item and reads no clock.
#pragma once
#include <chrono>
#include <cstdint>
#include <span>
#include <vector>

#include "exec/schedule_model.h"
#include "fastshade/render.h"

namespace fastshade {

struct FrameProfile {
  uint64_t vertex_stage_ns = 0;          // the whole vertex stage (its blocks cost alike)
  std::size_t vertices = 0;              // ... over this many vertices
  std::vector<uint64_t> setup_chunk_ns;  // triangle setup and its count into tiles, per chunk
  uint64_t plan_bins_ns = 0;             // binning's plan (its blocks cost alike)
  std::vector<uint64_t> fill_chunk_ns;   // binning's fill pass, per chunk
  std::vector<uint64_t> tile_ns;         // raster+shade, per tile in tile order, empty ones too
  StageTimes stages;                     // the frame's stage times (wall clock, ms)

  void reset(std::size_t chunks, std::size_t tiles, std::size_t vertex_count);
};

// Writes its lifetime in ns to *slot when it ends; with a null slot it does nothing.
class ItemTimer {
 public:
  explicit ItemTimer(uint64_t* slot) : slot_(slot) {
    if (slot_) t0_ = Clock::now();
  }
  ~ItemTimer() {
    if (slot_)
      *slot_ = static_cast<uint64_t>(
          std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - t0_).count());
  }
  ItemTimer(const ItemTimer&) = delete;
  ItemTimer& operator=(const ItemTimer&) = delete;

 private:
  using Clock = std::chrono::steady_clock;
  uint64_t* slot_;
  Clock::time_point t0_{};
};

// Item i of a per-item list, or null when not profiling.
inline uint64_t* profile_slot(FrameProfile* profile, std::vector<uint64_t> FrameProfile::*list,
                              std::size_t i) {
  return profile ? &(profile->*list)[i] : nullptr;
}

// The frame's phases in the order the renderer runs them (exec/renderer.cpp), each item's cost
// the median over `frames` (all of one scene and tile size): vertex blocks of
// limits::kVerticesPerBlock sharing the vertex stage's time equally, setup chunks, count
// chunks, the bin plan's blocks of limits::kBinPlanTiles tiles sharing its time equally (its
// short serial prefix sum included), fill chunks, tiles. What a stage's wall time holds beyond
// its items (handing items out, clock reads: paid per item, in parallel) is spread evenly over
// the stage's items; what the frame holds beyond its stages becomes one serial item, "between
// stages". Without `with_overheads` (for comparing item costs across thread counts, where
// items overlap and the walls say nothing about them) both are left out: items as measured,
// and "between stages" 0.
std::vector<SchedulePhase> schedule_phases(std::span<const FrameProfile> frames,
                                           bool with_overheads = true);

}  // namespace fastshade
