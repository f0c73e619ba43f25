#include "exec/frame_profile.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "core/limits.h"

namespace fastshade {

void FrameProfile::reset(std::size_t chunks, std::size_t tiles, std::size_t vertex_count) {
  vertex_stage_ns = plan_bins_ns = 0;
  stages = {};
  vertices = vertex_count;
  setup_chunk_ns.assign(chunks, 0);
  fill_chunk_ns.assign(chunks, 0);
  tile_ns.assign(tiles, 0);
}

namespace {

constexpr double kMsPerNs = 1e-6;

double median_ms(std::vector<double> ns) {
  std::sort(ns.begin(), ns.end());
  const std::size_t n = ns.size();
  return (n % 2 ? ns[n / 2] : 0.5 * (ns[n / 2 - 1] + ns[n / 2])) * kMsPerNs;
}

// The median over the frames of `value(frame)` (ns), in ms.
template <typename Value>
double median_over(std::span<const FrameProfile> frames, Value&& value) {
  std::vector<double> v;
  v.reserve(frames.size());
  for (const FrameProfile& f : frames) v.push_back(double(value(f)));
  return median_ms(std::move(v));
}

std::vector<double> item_medians(std::span<const FrameProfile> frames,
                                 std::vector<uint64_t> FrameProfile::*list) {
  std::vector<double> ms((frames.front().*list).size());
  for (std::size_t i = 0; i < ms.size(); ++i)
    ms[i] = median_over(frames, [&](const FrameProfile& f) { return (f.*list)[i]; });
  return ms;
}

double sum_ns(const std::vector<uint64_t>& v) { return double(std::accumulate(v.begin(), v.end(), uint64_t(0))); }

// A reported stage: its wall time and the sum of its items' times in one frame.
struct StageAccount {
  const char* stage;
  double StageTimes::*wall_ms;
  double (*items_ns)(const FrameProfile&);
};
constexpr StageAccount kStageAccounts[] = {
    {"front_end", &StageTimes::front_end,
     [](const FrameProfile& f) { return double(f.vertex_stage_ns) + sum_ns(f.setup_chunk_ns); }},
    {"binning", &StageTimes::binning,
     [](const FrameProfile& f) {
       return double(f.plan_bins_ns) + sum_ns(f.fill_chunk_ns);
     }},
    {"raster_shade", &StageTimes::raster_shade, [](const FrameProfile& f) { return sum_ns(f.tile_ns); }},
};

double beyond(double wall_ns, double items_ns) { return std::max(0.0, wall_ns - items_ns); }

}  // namespace

std::vector<SchedulePhase> schedule_phases(std::span<const FrameProfile> frames, bool with_overheads) {
  if (frames.empty()) throw std::invalid_argument("schedule_phases: no profiled frame");
  const FrameProfile& first = frames.front();
  for (const FrameProfile& f : frames)
    if (f.vertices != first.vertices || f.setup_chunk_ns.size() != first.setup_chunk_ns.size() ||
        f.tile_ns.size() != first.tile_ns.size())
      throw std::invalid_argument("schedule_phases: frames of different scenes or tile sizes");

  auto evenly = [](double ms, std::size_t items) { return std::vector<double>(items, items ? ms / items : 0.0); };
  const std::size_t vertex_blocks = (first.vertices + limits::kVerticesPerBlock - 1) / limits::kVerticesPerBlock;
  const std::size_t plan_blocks = (first.tile_ns.size() + limits::kBinPlanTiles - 1) / limits::kBinPlanTiles;
  std::vector<SchedulePhase> phases;
  phases.push_back({"front_end", "vertex blocks",
                    evenly(median_over(frames, [](const FrameProfile& f) { return f.vertex_stage_ns; }), vertex_blocks),
                    true});
  phases.push_back({"front_end", "setup chunks", item_medians(frames, &FrameProfile::setup_chunk_ns)});
  phases.push_back({"binning", "bin plan",
                    evenly(median_over(frames, [](const FrameProfile& f) { return f.plan_bins_ns; }), plan_blocks),
                    true});
  phases.push_back({"binning", "fill chunks", item_medians(frames, &FrameProfile::fill_chunk_ns)});
  phases.push_back({"raster_shade", "tiles", item_medians(frames, &FrameProfile::tile_ns)});

  for (const StageAccount& a : kStageAccounts) {
    if (!with_overheads) break;
    const double overhead_ms = median_over(
        frames, [&](const FrameProfile& f) { return beyond(f.stages.*a.wall_ms / kMsPerNs, a.items_ns(f)); });
    std::size_t items = 0;
    for (const SchedulePhase& p : phases) items += p.stage == a.stage ? p.item_ms.size() : 0;
    for (SchedulePhase& p : phases)
      if (p.stage == a.stage)
        for (double& ms : p.item_ms) ms += overhead_ms / double(items);  // items > 0 here
  }
  const double between_ms = !with_overheads ? 0.0 : median_over(frames, [](const FrameProfile& f) {
    double walls = 0;
    for (const StageAccount& a : kStageAccounts) walls += f.stages.*a.wall_ms;
    return beyond(f.stages.total, walls) / kMsPerNs;
  });
  phases.push_back({"other", "between stages", {between_ms}});
  return phases;
}

}  // namespace fastshade
