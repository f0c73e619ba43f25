// `fastshade bench scaling`: renders one scene at every tile size with 1, 2, ... threads, taking
// frames round-robin across the thread counts (so that a shared machine's drift hits them all
// alike), and a profiled frame per thread count in the same rounds: the 1-thread ones feed the
// load-balance model, the others show how much slower each item gets beside other threads.
#include <algorithm>
#include <charconv>
#include <cstdio>
#include <memory>
#include <set>
#include <system_error>

#include <sys/resource.h>

#include <chrono>

#include <tbb/info.h>

#include "app/commands.h"
#include "app/scaling.h"
#include "fastshade/atomic_file.h"
#include "fastshade/error.h"
#include "fastshade/profile.h"
#include "fastshade/scene.h"

namespace fastshade {

namespace {

namespace fs = std::filesystem;

// The same bounds as `render --threads` (validate() in exec/renderer.cpp) and `render --frames`.
constexpr int kMaxThreads = 1024;
constexpr int kMaxFrames = 100000;

std::vector<int> parse_tiles(const std::string& text) {
  std::set<int> tiles;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    const std::size_t comma = std::min(text.find(',', pos), text.size());
    const char* first = text.data() + pos;
    const char* last = text.data() + comma;
    int px = 0;
    const auto [end, ec] = std::from_chars(first, last, px);
    if (ec != std::errc() || end != last || px == 0)
      throw InputError("--tiles", "expected tile sizes separated by commas, got '" + text + "'");
    RenderOptions probe;  // the renderer's own check says what a tile size may be
    probe.tile_px = px;
    try {
      validate(probe);
    } catch (const InputError& e) {  // "--tile: expected ..."
      const std::string message = e.what();
      throw InputError("--tiles", message.substr(message.find(": ") + 2));
    }
    tiles.insert(px);
    pos = comma + 1;
  }
  return {tiles.begin(), tiles.end()};
}

// 1 to 4 one by one (where a small machine's curve bends), then powers of two, the hardware's
// count and the maximum.
std::vector<int> thread_counts(int max_threads, int hardware_threads) {
  std::set<int> counts{max_threads};
  for (int t = 1; t <= std::min(max_threads, 4); ++t) counts.insert(t);
  for (int t = 8; t < max_threads; t *= 2) counts.insert(t);
  if (hardware_threads <= max_threads) counts.insert(hardware_threads);
  return {counts.begin(), counts.end()};
}

// An existing writable directory, or a new one whose parent exists: created only once the
// measurements are done, so a failed run leaves nothing behind.
void check_out_dir(const fs::path& dir) {
  std::error_code ec;
  if (fs::exists(dir, ec)) {
    if (!fs::is_directory(dir, ec)) throw InputError(dir.string(), "--out is not a directory");
    check_output_path(dir / "scaling.png");
    return;
  }
  const fs::path parent = dir.has_parent_path() ? dir.parent_path() : fs::path(".");
  if (!fs::is_directory(parent, ec))
    throw InputError(dir.string(), "directory '" + parent.string() + "' does not exist");
}

// The process's CPU time (all threads, user + system) in seconds.
double process_cpu_s() {
  rusage usage{};
  ::getrusage(RUSAGE_SELF, &usage);
  auto seconds = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

ScalingModel model_from(int tile_px, const std::vector<FrameProfile>& one_thread) {
  ScalingModel m;
  m.tile_px = tile_px;
  m.phases = schedule_phases(one_thread);
  m.tiles = one_thread.front().tile_ns.size();
  m.chunks = one_thread.front().setup_chunk_ns.size();
  for (const SchedulePhase& phase : m.phases)
    if (phase.item_ms.size() == 1) m.serial_ms += phase.item_ms.front();
  m.critical_path_ms = critical_path_ms(m.phases);
  for (const int workers : kModelWorkers) m.predictions.push_back(predict_schedule(m.phases, workers));
  return m;
}

// Every thread count at one tile size, round-robin: a timed and a profiled frame each a round.
void measure_tile(const Scene& scene, const ScalingCommand& cmd, int tile_px,
                  const std::vector<int>& threads, int hardware_threads, ScalingRun& run) {
  std::vector<std::unique_ptr<Renderer>> renderers;
  std::vector<Image> images(threads.size());  // one per renderer, reused by its frames
  for (const int t : threads) {
    RenderOptions o;
    o.method = cmd.method;
    o.tile_px = tile_px;
    o.threads = t;
    renderers.push_back(std::make_unique<Renderer>(scene, o));
    renderers.back()->render_frame(images[renderers.size() - 1]);  // warm-up: first-touch allocation, caches
  }
  std::vector<std::vector<StageTimes>> times(threads.size());
  std::vector<std::vector<FrameProfile>> profiles(threads.size(), std::vector<FrameProfile>(cmd.frames));
  std::vector<double> cpu_s(threads.size(), 0.0), wall_s(threads.size(), 0.0);
  for (int f = 0; f < cmd.frames; ++f)
    for (std::size_t i = 0; i < renderers.size(); ++i) {
      const double cpu0 = process_cpu_s();
      const auto wall0 = std::chrono::steady_clock::now();
      renderers[i]->render_frame(images[i], &times[i].emplace_back());
      wall_s[i] += std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
      cpu_s[i] += process_cpu_s() - cpu0;
      renderers[i]->render_frame(images[i], nullptr, &profiles[i][f]);
    }
  for (std::size_t i = 0; i < threads.size(); ++i)
    run.points.push_back({tile_px, threads[i], threads[i] > hardware_threads, median_stages(times[i]),
                          wall_s[i] > 0 ? cpu_s[i] / wall_s[i] : 0.0,
                          schedule_phases(profiles[i], /*with_overheads=*/false)});
  run.models.push_back(model_from(tile_px, profiles.front()));  // threads.front() == 1
  const RenderStats stats = renderers.front()->last_stats();
  run.triangles = stats.triangles_in;
  run.isa = stats.isa;
}

}  // namespace

int run_bench_scaling(const ScalingCommand& cmd) {
  const int hardware_threads = tbb::info::default_concurrency();
  const int max_threads = cmd.max_threads == 0 ? hardware_threads + 1 : cmd.max_threads;
  if (max_threads < 1 || max_threads > kMaxThreads)
    throw InputError("--max-threads", "expected 1 to " + std::to_string(kMaxThreads) + ", got " +
                                          std::to_string(cmd.max_threads));
  if (cmd.frames < 1 || cmd.frames > kMaxFrames)
    throw InputError("--frames", "expected 1 to " + std::to_string(kMaxFrames) + ", got " +
                                     std::to_string(cmd.frames));
  const std::vector<int> tiles = parse_tiles(cmd.tiles);
  const fs::path out_dir = cmd.out_dir;
  check_out_dir(out_dir);
  const Scene scene = cmd.scene.empty() ? parse_scene(default_scene_json(), "<default scene>", ".")
                                        : load_scene(cmd.scene);

  const std::vector<int> threads = thread_counts(max_threads, hardware_threads);
  ScalingRun run;
  run.scene = cmd.scene.empty() ? "<default scene>" : fs::path(cmd.scene).filename().string();
  run.method = option_name(cmd.method);
  run.width = scene.width;
  run.height = scene.height;
  run.hardware_threads = hardware_threads;
  run.frames = cmd.frames;
  for (const int tile_px : tiles) {
    std::fprintf(stderr, "tile %d: %zu thread counts x %d frames ...\n", tile_px, threads.size(),
                 cmd.frames);
    measure_tile(scene, cmd, tile_px, threads, hardware_threads, run);
  }

  fs::create_directories(out_dir);
  write_text_file(out_dir / "scaling.csv", scaling_csv(run));
  write_text_file(out_dir / "scaling.json", scaling_json(run));
  print_scaling_tables(run);
  if (!cmd.no_plot && plot_scaling(out_dir / "scaling.json", out_dir / "scaling.png"))
    std::printf("wrote %s\n", (out_dir / "scaling.png").string().c_str());
  std::printf("wrote %s and %s\n", (out_dir / "scaling.csv").string().c_str(),
              (out_dir / "scaling.json").string().c_str());
  return 0;
}

}  // namespace fastshade
