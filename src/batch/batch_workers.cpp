#include "batch/batch_workers.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>

#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/task_arena.h>

#include "batch/batch_plan.h"
#include "core/ms_between.h"
#include "fastshade/image.h"
#include "fastshade/mesh.h"

namespace fastshade {

namespace {

using Clock = SteadyClock;
using nlohmann::json;

// A mesh loaded and framed, shared by the views that still need it.
struct LoadedMesh {
  const MeshJob* job;
  Scene fit_scene;
  double load_ms;
};

struct ViewTask {
  std::shared_ptr<const LoadedMesh> mesh;
  const BatchImage* image;
};

class Workers {
 public:
  Workers(const std::vector<MeshJob>& jobs, const BatchSetup& setup) : jobs_(jobs), setup_(setup) {}

  // One worker's loop: views of loaded meshes first, else the next mesh; a worker with
  // neither waits while a load is in flight (its views are coming), else it is done.
  void work() {
    for (;;) {
      Work next = take_work();
      if (!next.view && !next.job) return;
      try {
        if (next.view) {
          render(*next.view);
        } else {
          load(*next.job);
        }
      } catch (const std::exception& e) {  // results.jsonl cannot be written: stop
        const std::lock_guard<std::mutex> lock(mutex_);
        if (outcome_.fatal.empty()) outcome_.fatal = e.what();
        stop_ = true;
      }
      if (next.job) {
        const std::lock_guard<std::mutex> lock(mutex_);
        --loading_;
      }
      more_work_.notify_all();  // views were queued, or a load ended
    }
  }

  BatchOutcome outcome() {
    const std::lock_guard<std::mutex> lock(mutex_);
    return outcome_;
  }

 private:
  struct Work {
    std::optional<ViewTask> view;
    const MeshJob* job = nullptr;  // to load
  };

  bool stopping() const {
    return stop_.load() || (setup_.callbacks.stop_requested && setup_.callbacks.stop_requested());
  }

  Work take_work() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      if (stopping()) return {};
      if (!views_.empty()) {
        Work work{std::move(views_.front())};
        views_.pop_front();
        return work;
      }
      if (next_job_ < jobs_.size()) {
        ++loading_;
        return {std::nullopt, &jobs_[next_job_++]};
      }
      if (loading_ == 0) return {};
      more_work_.wait(lock);
    }
  }

  void load(const MeshJob& job) {
    const Clock::time_point t0 = Clock::now();
    auto loaded = std::make_shared<LoadedMesh>();
    try {
      loaded->fit_scene = load_batch_scene(setup_.context.scene, job.mesh);
    } catch (const std::exception& e) {  // InputError, or std::bad_alloc on a huge mesh
      const double load_ms = ms_between(t0, Clock::now());
      for (const BatchImage& image : job.images) failed(job.mesh, image, e.what(), load_ms);
      return;
    }
    loaded->job = &job;
    loaded->load_ms = ms_between(t0, Clock::now());
    const std::lock_guard<std::mutex> lock(mutex_);
    for (const BatchImage& image : job.images) views_.push_back({loaded, &image});
  }

  // Renders, writes and records one view; a failure to render or write fails this image
  // alone, a failure to record (results.jsonl) propagates and stops the batch.
  void render(const ViewTask& task) {
    const MeshJob& job = *task.mesh->job;
    const BatchImage& image = *task.image;
    const double load_ms = task.mesh->load_ms;
    json line;
    try {
      line = render_batch_view(setup_.context, task.mesh->fit_scene, job.mesh, image, load_ms);
    } catch (const std::exception& e) {  // InputError from write_image, std::bad_alloc, ...
      failed(job.mesh, image, e.what(), load_ms);
      return;
    }
    setup_.log.append(line);
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      ++outcome_.ok;
    }
    char ms[32];
    std::snprintf(ms, sizeof ms, ": %.1f ms", line["time_ms"].get<double>());
    if (setup_.callbacks.image_done)
      setup_.callbacks.image_done(true, job.mesh.key + " view " + std::to_string(image.view) + ms);
  }

  void failed(const BatchMesh& mesh, const BatchImage& image, const std::string& error,
              double load_ms) {
    setup_.log.append(failed_line(mesh, image, setup_.context.views, error, load_ms));
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      ++outcome_.failed;
      outcome_.failures.emplace(mesh.key, error);
    }
    if (setup_.callbacks.image_done)
      setup_.callbacks.image_done(false, mesh.key + " view " + std::to_string(image.view) + ": " + error);
  }

  const std::vector<MeshJob>& jobs_;
  const BatchSetup& setup_;
  std::atomic<bool> stop_{false};
  std::mutex mutex_;  // guards everything below
  std::condition_variable more_work_;
  std::size_t next_job_ = 0;
  int loading_ = 0;  // loads in flight
  std::deque<ViewTask> views_;
  BatchOutcome outcome_;
};

}  // namespace

BatchOutcome render_jobs(const std::vector<MeshJob>& jobs, const BatchSetup& setup) {
  const int threads =
      setup.context.options.threads > 0 ? setup.context.options.threads : tbb::info::default_concurrency();
  Workers workers(jobs, setup);
  // The workers are TBB worker threads and this thread only waits, outside their arena, so a
  // worker that has run out of work is free to join another worker's render (its tiles): N
  // workers, and the limit counts this thread too.
  const tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                                  static_cast<std::size_t>(threads) + 1);
  tbb::task_arena arena(threads, /*reserved_for_masters=*/0);
  std::mutex done_mutex;
  std::condition_variable done;
  int running = threads;
  for (int w = 0; w < threads; ++w) {
    arena.enqueue([&] {
      workers.work();
      // Notified under the lock: this thread is done with the mutex and the condition before
      // the waiting thread can return and destroy them.
      const std::lock_guard<std::mutex> lock(done_mutex);
      if (--running == 0) done.notify_all();
    });
  }
  std::unique_lock<std::mutex> lock(done_mutex);
  done.wait(lock, [&] { return running == 0; });
  BatchOutcome outcome = workers.outcome();
  outcome.threads = threads;
  return outcome;
}

BatchOutcome render_batch(const BatchSpec& spec, const BatchPlan& plan, const BatchCallbacks& callbacks) {
  const SceneTemplate scene = batch_template(spec);
  ResultsLog log(spec.outdir / "results.jsonl");
  for (const std::string& line : plan.skipped) log.append(nlohmann::json::parse(line));
  return render_jobs(plan.jobs, BatchSetup{{scene, spec.options, spec.aovs, spec.outdir, spec.views}, log, callbacks});
}

}  // namespace fastshade
