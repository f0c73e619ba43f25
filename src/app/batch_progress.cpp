#include "app/batch_progress.h"

#include <algorithm>
#include <cmath>

namespace fastshade {

namespace {

using Clock = std::chrono::steady_clock;

// The bar is redrawn at most this often: faster than a reader notices, and at a thousand tiny
// images a second redrawing per image would cost more terminal output than it shows.
constexpr auto kRedrawInterval = std::chrono::milliseconds(100);
constexpr int kBarChars = 24;

}  // namespace

std::string format_clock(double seconds) {
  const long long s = std::llround(std::max(seconds, 0.0));
  char text[32];
  if (s >= 3600) {
    std::snprintf(text, sizeof text, "%lld:%02lld:%02lld", s / 3600, s / 60 % 60, s % 60);
  } else {
    std::snprintf(text, sizeof text, "%lld:%02lld", s / 60, s % 60);
  }
  return text;
}

BatchProgress::BatchProgress(std::size_t total_images, bool terminal, std::FILE* out)
    : total_(total_images), terminal_(terminal), out_(out), start_(Clock::now()), last_draw_(start_) {
  if (terminal_ && total_ > 0) draw_bar(start_);
}

double BatchProgress::images_per_s(Clock::time_point now) const {
  const double s = std::chrono::duration<double>(now - start_).count();
  return s > 0 ? double(done_) / s : 0.0;
}

void BatchProgress::image_done(bool ok, const std::string& what) {
  const std::lock_guard<std::mutex> lock(mutex_);
  ++done_;
  if (!ok) ++failed_;
  const Clock::time_point now = Clock::now();
  if (!terminal_) {
    std::fprintf(out_, "batch: %zu/%zu %s %s\n", done_, total_, ok ? "ok" : "FAILED", what.c_str());
    std::fflush(out_);
  } else if (now - last_draw_ >= kRedrawInterval || done_ == total_) {
    draw_bar(now);
  }
}

void BatchProgress::finish() {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (!terminal_ || total_ == 0) return;
  draw_bar(Clock::now());
  std::fputc('\n', out_);
  std::fflush(out_);
}

void BatchProgress::draw_bar(Clock::time_point now) {
  last_draw_ = now;
  const int filled = total_ ? static_cast<int>(kBarChars * done_ / total_) : kBarChars;
  std::string bar(static_cast<std::size_t>(filled), '#');
  bar.resize(kBarChars, '.');
  const double rate = images_per_s(now);
  const std::string eta = rate > 0 ? format_clock(double(total_ - done_) / rate) : "?";
  // \r returns to the line start, \033[K clears what a longer earlier line left.
  std::fprintf(out_, "\r[%s] %zu/%zu  %.1f img/s  ETA %s%s\033[K", bar.c_str(), done_, total_, rate,
               eta.c_str(), failed_ ? ("  " + std::to_string(failed_) + " failed").c_str() : "");
  std::fflush(out_);
}

}  // namespace fastshade
