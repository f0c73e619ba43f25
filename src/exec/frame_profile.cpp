#include "exec/frame_profile.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "core/limits.h"

namespace fastshade {

void FrameProfile::reset(std::size_t chunks, std::size_t tiles, std::size_t vertex_count) {
  vertex_stage_ns = plan_bins_ns = total_ns = 0;
  vertices = vertex_count;
  setup_chunk_ns.assign(chunks, 0);
  count_chunk_ns.assign(chunks, 0);
  fill_chunk_ns.assign(chunks, 0);
  tile_ns.assign(tiles, 0);
}

namespace {

constexpr double kMsPerNs = 1e-6;

double median_ms(std::vector<uint64_t> ns) {
  std::sort(ns.begin(), ns.end());
  const std::size_t n = ns.size();
  return (n % 2 ? double(ns[n / 2]) : 0.5 * (double(ns[n / 2 - 1]) + double(ns[n / 2]))) * kMsPerNs;
}

// Item by item, the median of `value(frame)` over the frames.
template <typename Value>
double median_over(std::span<const FrameProfile> frames, Value&& value) {
  std::vector<uint64_t> v;
  v.reserve(frames.size());
  for (const FrameProfile& f : frames) v.push_back(value(f));
  return median_ms(std::move(v));
}

std::vector<double> item_medians(std::span<const FrameProfile> frames,
                                 std::vector<uint64_t> FrameProfile::*list) {
  std::vector<double> ms((frames.front().*list).size());
  for (std::size_t i = 0; i < ms.size(); ++i)
    ms[i] = median_over(frames, [&](const FrameProfile& f) { return (f.*list)[i]; });
  return ms;
}

uint64_t covered_ns(const FrameProfile& f) {
  auto sum = [](const std::vector<uint64_t>& v) { return std::accumulate(v.begin(), v.end(), uint64_t(0)); };
  return f.vertex_stage_ns + sum(f.setup_chunk_ns) + sum(f.count_chunk_ns) + f.plan_bins_ns +
         sum(f.fill_chunk_ns) + sum(f.tile_ns);
}

}  // namespace

std::vector<SchedulePhase> schedule_phases(std::span<const FrameProfile> frames) {
  if (frames.empty()) throw std::invalid_argument("schedule_phases: no profiled frame");
  const FrameProfile& first = frames.front();
  for (const FrameProfile& f : frames)
    if (f.vertices != first.vertices || f.setup_chunk_ns.size() != first.setup_chunk_ns.size() ||
        f.tile_ns.size() != first.tile_ns.size())
      throw std::invalid_argument("schedule_phases: frames of different scenes or tile sizes");

  const std::size_t blocks = (first.vertices + limits::kVerticesPerBlock - 1) / limits::kVerticesPerBlock;
  const std::size_t plan_blocks = (first.tile_ns.size() + limits::kBinPlanTiles - 1) / limits::kBinPlanTiles;
  const double vertex_ms = median_over(frames, [](const FrameProfile& f) { return f.vertex_stage_ns; });
  const double other_ms = median_over(frames, [](const FrameProfile& f) {
    const uint64_t covered = covered_ns(f);
    return f.total_ns > covered ? f.total_ns - covered : uint64_t(0);
  });
  const double plan_ms = median_over(frames, [](const FrameProfile& f) { return f.plan_bins_ns; });
  std::vector<SchedulePhase> phases;
  phases.push_back({"front_end", "vertex blocks", std::vector<double>(blocks, blocks ? vertex_ms / blocks : 0.0)});
  phases.push_back({"front_end", "setup chunks", item_medians(frames, &FrameProfile::setup_chunk_ns)});
  phases.push_back({"binning", "count chunks", item_medians(frames, &FrameProfile::count_chunk_ns)});
  phases.push_back({"binning", "bin plan", std::vector<double>(plan_blocks, plan_ms / plan_blocks)});
  phases.push_back({"binning", "fill chunks", item_medians(frames, &FrameProfile::fill_chunk_ns)});
  phases.push_back({"raster_shade", "tiles", item_medians(frames, &FrameProfile::tile_ns)});
  phases.push_back({"other", "loop start/join", {other_ms}});
  return phases;
}

}  // namespace fastshade
