// The Pareto front of measured configurations: those no other configuration beats on both
// time and error at once.
#pragma once
#include <span>
#include <vector>

namespace fastshade {

struct TimeError {
  double time_ms = 0;
  double error = 0;  // any error measure where smaller is better
};

// front[i] is true iff no point j is at least as good in both coordinates and strictly better
// in one. Equal points are all on the front; a NaN coordinate is never on it and dominates
// nothing.
std::vector<bool> pareto_front(std::span<const TimeError> points);

}  // namespace fastshade
