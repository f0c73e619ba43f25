// Measuring frames for load-balance studies (`fastshade bench scaling`, docs/SCALING.md): the
// per-item costs a frame records when Renderer::render_frame is given a FrameProfile, the
// model that replays them as a schedule on P simulated workers, and the medians fastshade
// reports. The model is pure functions of numbers; docs/SCALING.md states what it assumes.
#pragma once
#include <algorithm>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "fastshade/render.h"

namespace fastshade {

// One frame's item costs. Off (a null profile) recording costs one predictable branch per item
// and reads no clock.
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

// One step of a frame: its items may run on any worker, in the order given, and the next phase
// starts only when all of them are done (a tbb::parallel_for ends in a barrier). A serial step
// is a phase of one item.
struct SchedulePhase {
  std::string stage;            // which reported stage it belongs to ("front_end", ...)
  std::string name;             // what its items are ("setup chunks", ...)
  std::vector<double> item_ms;  // in hand-out order
  bool timed_whole = false;     // timed as a whole (wall time) and split evenly into its items
};

// Greedy list schedule: each item, in order, goes to the worker that becomes free first.
// This is what dynamic hand-out of single items (TBB's simple_partitioner with work stealing)
// approaches when items are many; it is within one largest item of the optimum (Graham).
// workers >= 1; an empty list takes 0 ms.
double list_schedule_ms(std::span<const double> item_ms, int workers);

struct StagePrediction {
  std::string stage;
  double ms = 0;
};

struct SchedulePrediction {
  int workers = 0;
  double total_ms = 0;
  std::vector<StagePrediction> stages;  // in the order stages first appear in the phases
};

// The frame's time on `workers` workers: the sum over phases of their list schedules.
SchedulePrediction predict_schedule(std::span<const SchedulePhase> phases, int workers);

// The frame's time on unboundedly many workers: every phase takes its largest item.
double critical_path_ms(std::span<const SchedulePhase> phases);

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

// The median every timing in fastshade reports (medians resist the one-off stalls of a shared
// machine; docs/PERFORMANCE.md, "The machines, and why only ratios count"). 0 for no values.
inline double median(std::vector<double> values) {
  const std::size_t n = values.size();
  if (n == 0) return 0.0;
  std::sort(values.begin(), values.end());
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// Stage times over many frames, reduced to the medians fastshade reports.
StageTimes median_stages(std::span<const StageTimes> frames);

}  // namespace fastshade
