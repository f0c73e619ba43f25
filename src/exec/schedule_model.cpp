#include "fastshade/profile.h"

#include <algorithm>
#include <functional>
#include <queue>
#include <stdexcept>

namespace fastshade {

double list_schedule_ms(std::span<const double> item_ms, int workers) {
  if (workers < 1) throw std::invalid_argument("list_schedule_ms: workers must be >= 1");
  if (item_ms.empty()) return 0.0;
  // Times at which each worker becomes free; the earliest on top. Workers beyond the item
  // count would stay idle: do not simulate them.
  const std::size_t busy = std::min<std::size_t>(static_cast<std::size_t>(workers), item_ms.size());
  std::priority_queue<double, std::vector<double>, std::greater<>> free_at;
  for (std::size_t w = 0; w < busy; ++w) free_at.push(0.0);
  double makespan = 0.0;
  for (const double cost : item_ms) {
    const double done = free_at.top() + cost;
    free_at.pop();
    free_at.push(done);
    makespan = std::max(makespan, done);
  }
  return makespan;
}

SchedulePrediction predict_schedule(std::span<const SchedulePhase> phases, int workers) {
  SchedulePrediction p;
  p.workers = workers;
  for (const SchedulePhase& phase : phases) {
    const double ms = list_schedule_ms(phase.item_ms, workers);
    p.total_ms += ms;
    auto it = std::find_if(p.stages.begin(), p.stages.end(),
                           [&](const StagePrediction& s) { return s.stage == phase.stage; });
    if (it == p.stages.end()) it = p.stages.insert(p.stages.end(), {phase.stage, 0.0});
    it->ms += ms;
  }
  return p;
}

double critical_path_ms(std::span<const SchedulePhase> phases) {
  double ms = 0.0;
  for (const SchedulePhase& phase : phases)
    if (!phase.item_ms.empty()) ms += *std::max_element(phase.item_ms.begin(), phase.item_ms.end());
  return ms;
}

}  // namespace fastshade
