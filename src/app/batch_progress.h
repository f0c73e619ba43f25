// Progress of a batch on stderr: on a terminal one bar redrawn in place (count, rate, ETA,
// failures); otherwise (a log file, a pipe, a cluster job) one plain line per image.
#pragma once
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <mutex>
#include <string>

namespace fastshade {

class BatchProgress {
 public:
  BatchProgress(std::size_t total_images, bool terminal, std::FILE* out = stderr);

  // One image finished; `what` describes it for the plain lines. Thread-safe.
  void image_done(bool ok, const std::string& what);
  // Draws the bar a last time and ends its line (terminal mode).
  void finish();

 private:
  void draw_bar(std::chrono::steady_clock::time_point now);
  double images_per_s(std::chrono::steady_clock::time_point now) const;

  std::size_t total_, done_ = 0, failed_ = 0;
  bool terminal_;
  std::FILE* out_;
  std::chrono::steady_clock::time_point start_, last_draw_;
  std::mutex mutex_;
};

// "1:05" or "2:03:04": whole seconds as a terminal clock shows them.
std::string format_clock(double seconds);

}  // namespace fastshade
