// Wall-clock intervals in milliseconds, as stage times and batch records report them.
#pragma once
#include <chrono>

namespace fastshade {

using SteadyClock = std::chrono::steady_clock;

inline double ms_between(SteadyClock::time_point a, SteadyClock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}
inline double ms_since(SteadyClock::time_point t0) { return ms_between(t0, SteadyClock::now()); }

}  // namespace fastshade
