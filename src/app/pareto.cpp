#include "app/pareto.h"

#include <cmath>

namespace fastshade {

namespace {

bool finite_point(const TimeError& p) { return !std::isnan(p.time_ms) && !std::isnan(p.error); }

bool dominates(const TimeError& a, const TimeError& b) {
  return a.time_ms <= b.time_ms && a.error <= b.error && (a.time_ms < b.time_ms || a.error < b.error);
}

}  // namespace

std::vector<bool> pareto_front(std::span<const TimeError> points) {
  // Quadratic: a report has a few dozen configurations per scene.
  std::vector<bool> front(points.size(), false);
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!finite_point(points[i])) continue;
    bool dominated = false;
    for (std::size_t j = 0; j < points.size() && !dominated; ++j)
      dominated = j != i && finite_point(points[j]) && dominates(points[j], points[i]);
    front[i] = !dominated;
  }
  return front;
}

}  // namespace fastshade
