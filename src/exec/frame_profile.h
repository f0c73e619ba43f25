// How the renderer records a FrameProfile (include/fastshade/profile.h): a timer per item that
// reads no clock when the profile is null.
#pragma once
#include <chrono>
#include <cstdint>
#include <vector>

#include "fastshade/profile.h"

namespace fastshade {

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

}  // namespace fastshade
