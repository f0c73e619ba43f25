// Ctrl-C (SIGINT) and kill (SIGTERM) as a request to stop: while a StopSignals lives, the first
// of them only sets a flag that long-running work polls, so it can finish or drop what it is
// doing and leave no partial file; a second one kills the process as usual.
#pragma once

namespace fastshade {

class StopSignals {
 public:
  StopSignals();   // installs the handlers
  ~StopSignals();  // restores the previous ones
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  // The signal received (SIGINT or SIGTERM), or 0. Async-signal-safe to set, cheap to poll.
  static int received();
};

}  // namespace fastshade
