// `fastshade bench scaling`: what one run measured and modelled, and how it is reported.
// The measuring is in scaling_command.cpp, the reports in scaling_report.cpp, the plot in
// scaling_plot.cpp.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "fastshade/profile.h"
#include "fastshade/render.h"

namespace fastshade {

// One tile size and thread count: per-stage medians over the timed frames.
struct ScalingPoint {
  int tile_px = 0, threads = 0;
  bool oversubscribed = false;  // more threads than the machine has
  StageTimes median;
  // CPU time the process got per wall-clock time over the timed frames: below `threads` when
  // other programs held the cores (the machine was not ours) or the threads waited.
  double cpus_used = 0;
  // Item costs of profiled frames at this thread count as measured, without overheads
  // (exec/frame_profile.h). Against the 1-thread costs they show contention: items that got
  // slower because others ran beside them.
  std::vector<SchedulePhase> phases;
};

// The load-balance model for one tile size (include/fastshade/profile.h).
struct ScalingModel {
  int tile_px = 0;
  std::size_t tiles = 0, chunks = 0;  // items of the largest phases
  double serial_ms = 0;               // the bin plan and "other": no worker shares them
  double critical_path_ms = 0;        // unboundedly many workers
  std::vector<SchedulePhase> phases;            // the measured item costs
  std::vector<SchedulePrediction> predictions;  // for kModelWorkers
};

// A point whose process got fewer CPUs than this share of min(threads, hardware threads) was
// measured while other programs held the cores: flagged in the table and the plot. 0.9
// leaves room for the serial parts of a frame, which keep one thread waiting.
inline constexpr double kBusyCpuShare = 0.9;
// A point (within the hardware's threads) whose measured items took this much longer in sum
// than on 1 thread ran on slowed cores: on a virtual machine, a host that shares our cores
// with others; invisible to CPU time. Flagged alike. Quiet runs of the dragon here stay at
// 1.00-1.03 (the bunny, whose tiles fit two L2 caches better than one, at 0.91-0.97), while
// runs at 1.07-1.09 already lost 5-10 % of speed-up.
inline constexpr double kSlowedItemRatio = 1.05;

// Workers the model predicts for: the hardware of today's and tomorrow's desktops and servers.
inline constexpr int kModelWorkers[] = {1, 2, 4, 8, 16, 32, 64};

struct ScalingRun {
  std::string scene, method, isa;
  int width = 0, height = 0;
  long long triangles = 0;
  int hardware_threads = 0, frames = 0;
  std::vector<ScalingPoint> points;  // tile-major, threads ascending, the first with 1 thread
  std::vector<ScalingModel> models;  // one per tile size
};

// Sum of p's measured item costs (phases timed item by item) over the same at 1 thread.
double item_cost_ratio(const ScalingRun& run, const ScalingPoint& p);
// Whether p was measured on a busy machine or slowed cores (kBusyCpuShare, kSlowedItemRatio).
bool untrustworthy(const ScalingRun& run, const ScalingPoint& p);

// Speed-up of `stage` at `p` against the same tile size's 1-thread point.
double speedup(const ScalingRun& run, const ScalingPoint& p, double StageTimes::*stage);
// The model's total at `workers` for `tile_px` (0 if that was not modelled).
double model_total_ms(const ScalingRun& run, int tile_px, int workers);

std::string scaling_csv(const ScalingRun& run);
std::string scaling_json(const ScalingRun& run);
void print_scaling_tables(const ScalingRun& run);

// Draws scaling.png from scaling.json with python3 + matplotlib. Returns false, having said
// why on stderr, if no python3 with matplotlib is found; throws if the script fails.
bool plot_scaling(const std::filesystem::path& json, const std::filesystem::path& png);

}  // namespace fastshade
