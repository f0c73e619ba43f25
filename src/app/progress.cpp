#include "app/progress.h"

#include <algorithm>
#include <cmath>

namespace fastshade {

namespace {
constexpr int kBarWidth = 24;
// Redraw a terminal bar at most 10 times a second; print a plain line at most every 5 s, so a
// log of a ten-minute run stays around a hundred lines.
constexpr double kTerminalRedrawS = 0.1;
constexpr double kPlainLineS = 5.0;
// A redrawn line must not wrap, or "\r" returns to its second half: keep it in 80 columns.
constexpr std::size_t kTerminalColumns = 79;
}  // namespace

std::string format_duration(double seconds) {
  const long long s = std::llround(std::max(seconds, 0.0));
  char buf[32];
  if (s < 60)
    std::snprintf(buf, sizeof buf, "%llds", s);
  else if (s < 3600)
    std::snprintf(buf, sizeof buf, "%lldm%02llds", s / 60, s % 60);
  else
    std::snprintf(buf, sizeof buf, "%lldh%02lldm", s / 3600, (s % 3600) / 60);
  return buf;
}

std::string progress_line(double done, double total, double eta_s, std::string_view what) {
  const double fraction = total > 0 ? std::clamp(done / total, 0.0, 1.0) : 1.0;
  const int filled = static_cast<int>(fraction * kBarWidth);
  std::string line = "[" + std::string(filled, '#') + std::string(kBarWidth - filled, '.') + "] ";
  char pct[16];
  std::snprintf(pct, sizeof pct, "%3.0f%%", 100.0 * fraction);
  line += pct;
  line += eta_s >= 0 ? "  ETA " + format_duration(eta_s) : "  ETA ?";
  if (!what.empty()) line += "  " + std::string(what);
  return line;
}

Progress::Progress(double total, std::FILE* out, bool terminal)
    : total_(total), out_(out), terminal_(terminal), start_(Clock::now()), last_shown_(start_) {}

Progress::~Progress() { finish(); }

void Progress::advance(double work, std::string_view what) {
  done_ += work;
  show(what, false);
}

void Progress::finish() {
  if (finished_ || !out_) return;
  finished_ = true;
  show("done", true);
  if (terminal_) std::fputc('\n', out_);
  std::fflush(out_);
}

void Progress::show(std::string_view what, bool force) {
  if (!out_) return;
  const Clock::time_point now = Clock::now();
  const double since_shown = std::chrono::duration<double>(now - last_shown_).count();
  if (!force && since_shown < (terminal_ ? kTerminalRedrawS : kPlainLineS)) return;
  last_shown_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  // Work done so far predicts the rest: no estimate before any work is done.
  const double eta = done_ > 0 ? elapsed * std::max(total_ - done_, 0.0) / done_ : -1;
  std::string line = progress_line(done_, total_, eta, what);
  if (terminal_) {
    if (line.size() > kTerminalColumns) line.resize(kTerminalColumns);
    std::fprintf(out_, "\r%s\033[K", line.c_str());  // erase the rest of a longer old line
  } else {
    std::fprintf(out_, "%s\n", line.c_str());
  }
  std::fflush(out_);
}

}  // namespace fastshade
