// The threads a render asks for are the threads that run it, beyond the hardware's too, and
// stats.threads says what could run, also when someone else's tbb::global_control holds TBB
// lower. The deadline below only keeps a failing run from hanging: it decides nothing.
#include "exec/worker_arena.h"

#include <gtest/gtest.h>

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <set>
#include <thread>

#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>

#include "fastshade/render.h"
#include "fastshade/scene.h"

namespace fastshade {
namespace {

using tbb::global_control;

// A passing run meets in milliseconds; a failing one waits this long for threads that do not
// exist, then reports how many did.
constexpr std::chrono::seconds kGiveUp{30};

int hardware_threads() { return tbb::info::default_concurrency(); }

// Runs `count` tasks in `arena`, each of which waits until `count` distinct threads have
// started one (a thread in a waiting task takes no other): the number of distinct threads that
// did. Only an arena with `count` threads reaches it.
int distinct_threads_meeting(WorkerArena& arena, int count) {
  std::mutex mutex;
  std::condition_variable arrived;
  std::set<std::thread::id> seen;
  const auto deadline = std::chrono::steady_clock::now() + kGiveUp;
  arena.execute([&] {
    tbb::parallel_for(
        0, count,
        [&](int) {
          std::unique_lock<std::mutex> lock(mutex);
          seen.insert(std::this_thread::get_id());
          arrived.notify_all();
          arrived.wait_until(lock, deadline, [&] { return static_cast<int>(seen.size()) >= count; });
        },
        tbb::simple_partitioner());
  });
  return static_cast<int>(seen.size());
}

Scene small_scene() { return parse_scene(default_scene_json(), "<default scene>", "."); }

TEST(WorkerArena, RunsMoreThreadsThanTheHardwareHasWhenAskedTo) {
  const int asked = hardware_threads() + 2;
  WorkerArena arena(asked);
  EXPECT_EQ(distinct_threads_meeting(arena, asked), asked);
  EXPECT_EQ(arena.threads_available(), asked);
}

TEST(WorkerArena, NeverLowersAHigherLimitInForce) {
  // `fastshade batch` and `bench scaling` raise the limit for their own threads and build
  // renderers with fewer inside it.
  const std::size_t outer = std::size_t(hardware_threads()) + 4;
  const global_control batch(global_control::max_allowed_parallelism, outer);
  WorkerArena arena(hardware_threads() + 2);
  std::size_t inside = 0;
  arena.execute([&] { inside = global_control::active_value(global_control::max_allowed_parallelism); });
  EXPECT_EQ(inside, outer);
  EXPECT_EQ(global_control::active_value(global_control::max_allowed_parallelism), outer);
}

TEST(WorkerArena, RenderStatsCountTheThreadsThatCouldRun) {
  const Scene scene = small_scene();
  RenderOptions o;
  o.method = ShadingMethod::Phong;
  o.threads = hardware_threads() + 2;
  RenderStats stats;
  render(scene, o, 1, &stats);
  EXPECT_EQ(stats.threads, o.threads);
  {
    // Someone else holds TBB to one thread: no arena can overrule that, and the stats say so.
    const global_control one(global_control::max_allowed_parallelism, 1);
    render(scene, o, 1, &stats);
    EXPECT_EQ(stats.threads, 1);
  }
  o.threads = 0;
  render(scene, o, 1, &stats);
  EXPECT_EQ(stats.threads, hardware_threads());
}

}  // namespace
}  // namespace fastshade
