// A progress bar on stderr with an ETA: redrawn in place on a terminal, plain lines otherwise
// (logs, CI), so that a long measurement run shows it is alive and when it will end.
#pragma once
#include <chrono>
#include <cstdio>
#include <string>
#include <string_view>

namespace fastshade {

// "45s", "3m07s", "1h02m".
std::string format_duration(double seconds);

// One line: "[#####.....]  50%  ETA 1m10s  what".
std::string progress_line(double done, double total, double eta_s, std::string_view what);

class Progress {
 public:
  // `total`: the work in any unit (the caller's estimate of cost); `out` a terminal or not, or
  // null to show nothing (a bar would only clutter a log of a short run).
  Progress(double total, std::FILE* out, bool terminal);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // Adds `work` done and shows `what` is under way now.
  void advance(double work, std::string_view what);
  // A better estimate of the whole work, once known.
  void set_total(double total) { total_ = total; }
  // Ends the bar (a newline on a terminal).
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  void show(std::string_view what, bool force);

  double total_, done_ = 0;
  std::FILE* out_;
  bool terminal_, finished_ = false;
  Clock::time_point start_, last_shown_;
};

}  // namespace fastshade
