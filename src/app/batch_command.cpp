// fastshade batch: checks the options, finds the meshes, plans the images (skipping those an
// earlier run completed), hands them to the library's workers (render_batch) with a progress
// bar and the stop signals, and sums up (docs/BATCH.md).
#include <malloc.h>
#include <unistd.h>

#include <charconv>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <string>

#include "app/batch_progress.h"
#include "app/commands.h"
#include "app/stop_signals.h"
#include "fastshade/aov_list.h"
#include "fastshade/batch.h"
#include "fastshade/error.h"

namespace fastshade {

namespace {

using Clock = std::chrono::steady_clock;

struct ImageSize {
  int width = 0, height = 0;
};

// "WxH", each in [1, kMaxImageSide].
ImageSize parse_size(const std::string& text) {
  ImageSize size;
  const std::size_t x = text.find('x');
  const char* begin = text.data();
  const char* end = begin + text.size();
  bool ok = x != std::string::npos;
  if (ok) {
    auto [w_end, w_err] = std::from_chars(begin, begin + x, size.width);
    auto [h_end, h_err] = std::from_chars(begin + x + 1, end, size.height);
    ok = w_err == std::errc() && w_end == begin + x && h_err == std::errc() && h_end == end;
  }
  if (!ok || size.width < 1 || size.height < 1 || size.width > kMaxImageSide ||
      size.height > kMaxImageSide)
    throw InputError("--size", "expected WxH with each in [1, " + std::to_string(kMaxImageSide) +
                                   "], got '" + text + "'");
  return size;
}

// A batch allocates and frees a mesh's and a frame's arrays (tens of MB each) again and again.
// By default glibc serves such blocks with mmap and unmaps them when freed, so every mesh pays
// its page faults afresh (about 10 ms of a 871k-triangle mesh's frame, measured). Served from
// the heap and kept there, freed memory is reused instead; the process stays at its peak size,
// which it reaches anyway. 1 GiB is above any single array of the meshes in ../shared/models
// (the largest, the dragon's OpenMesh edges, is about 60 MB).
void keep_freed_memory() {
  constexpr int kKeepBytes = 1 << 30;
  mallopt(M_MMAP_THRESHOLD, kKeepBytes);
  mallopt(M_TRIM_THRESHOLD, kKeepBytes);
}

std::string signal_name(int signal) {
  return signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : std::to_string(signal);
}

}  // namespace

int run_batch(const BatchCommand& cmd) {
  BatchSpec spec;
  spec.inputs = cmd.inputs;
  spec.outdir = cmd.outdir;
  spec.scene = cmd.scene;
  if (!cmd.size.empty()) {
    const ImageSize size = parse_size(cmd.size);
    spec.width = size.width, spec.height = size.height;
  }
  spec.views = cmd.views;
  const Shard shard = parse_shard(cmd.shard);
  spec.shard_index = shard.index, spec.shard_count = shard.count;
  spec.format = cmd.format;
  spec.aovs = cmd.aov.empty() ? AovSet{} : parse_aov_list(cmd.aov);
  spec.options = cmd.options;
  const BatchPlan plan = plan_batch(spec);

  BatchProgress progress(plan.to_render, ::isatty(STDERR_FILENO) == 1);

  keep_freed_memory();
  const Clock::time_point start = Clock::now();
  BatchOutcome outcome;
  {
    const StopSignals signals;
    outcome = render_batch(spec, plan,
                           {.image_done = [&](bool ok, const std::string& what) { progress.image_done(ok, what); },
                            .stop_requested = [] { return StopSignals::received() != 0; }});
  }
  progress.finish();
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();

  const std::size_t rendered = outcome.ok + outcome.failed;
  std::printf(
      "batch: %zu images in %.2f s (%.1f images/s, %d threads): %zu ok, %zu failed, %zu skipped\n",
      rendered, seconds, seconds > 0 ? rendered / seconds : 0.0, outcome.threads, outcome.ok,
      outcome.failed, plan.skipped.size());
  for (const auto& [key, error] : outcome.failures) {
    // Load errors name the mesh already ("PATH: problem"); others name what failed.
    const bool named = error.rfind(key + ": ", 0) == 0;
    std::printf("failed: %s%s\n", named ? "" : (key + ": ").c_str(), error.c_str());
  }
  if (!outcome.fatal.empty()) {
    std::fprintf(stderr, "fastshade: %s\n", outcome.fatal.c_str());
    return 1;
  }
  if (const int signal = StopSignals::received(); signal != 0) {
    std::printf("batch: stopped by %s after %zu of %zu images; run the same command again to resume\n",
                signal_name(signal).c_str(), rendered, plan.to_render);
    return 128 + signal;
  }
  return outcome.failed > 0 ? 1 : 0;
}

}  // namespace fastshade
