// The task arena a Renderer runs its frames in, with the threads it was asked for even beyond
// the hardware's. TBB caps every arena by a process-wide limit (max_allowed_parallelism: the
// hardware's threads unless a tbb::global_control says otherwise), so a plain
// tbb::task_arena(8) on a 2-thread machine runs 2 threads while claiming 8. An arena asked for
// more than the hardware has raises the limit for as long as it lives: per frame, the workers
// would leave and be woken again at every frame, a cost that would land in the timed frames.
#pragma once
#include <algorithm>
#include <optional>
#include <utility>

#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/task_arena.h>

namespace fastshade {

class WorkerArena {
 public:
  // `threads` 0: the hardware's. Beyond those, holds a global_control at `threads` or at the
  // limit in force if that is higher (batch's, bench scaling's): a new control never lowers a
  // limit another caller relies on (TBB applies the lowest control in force).
  explicit WorkerArena(int threads)
      : threads_(threads > 0 ? threads : tbb::info::default_concurrency()), arena_(threads_) {
    using tbb::global_control;
    if (threads_ > tbb::info::default_concurrency())
      raise_.emplace(global_control::max_allowed_parallelism,
                     std::max(std::size_t(threads_), global_control::active_value(global_control::max_allowed_parallelism)));
  }

  int threads() const { return threads_; }
  // The threads the last execute() could run on: threads(), unless someone else's lower
  // global_control held TBB below that (the lowest wins, and none can be overruled).
  int threads_available() const { return threads_available_; }

  template <typename F>
  void execute(F&& f) {
    using tbb::global_control;
    threads_available_ = static_cast<int>(
        std::min(std::size_t(threads_), global_control::active_value(global_control::max_allowed_parallelism)));
    arena_.execute(std::forward<F>(f));
  }

 private:
  int threads_;
  int threads_available_ = 0;
  std::optional<tbb::global_control> raise_;  // destroyed after the arena
  tbb::task_arena arena_;
};

}  // namespace fastshade
