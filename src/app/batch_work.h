// The working part of fastshade batch: meshes loaded and their views rendered on N workers,
// every finished image written whole and recorded in results.jsonl.
#pragma once
#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "batch/batch_inputs.h"
#include "app/batch_progress.h"
#include "batch/batch_results.h"
#include "fastshade/render.h"
#include "batch/batch_view.h"

namespace fastshade {

// What the workers share: read-only, or (log, progress) thread-safe.
struct BatchSetup {
  BatchContext context;  // context.options.threads: the number of workers, 0 = all cores
  ResultsLog& log;
  BatchProgress& progress;
};

struct BatchOutcome {
  std::size_t ok = 0, failed = 0;
  std::map<std::string, std::string> failures;  // mesh key -> its first error
  std::string fatal;  // results.jsonl could not be written: the batch stopped
  int threads = 0;    // workers used
};

// Renders every job's images. Workers take views of loaded meshes first, else load the next
// mesh in `jobs` order (put the largest first: the longest load starts at once, small meshes
// fill in around it) and queue its views, else wait while a load is in flight; so one mesh's
// views spread over all workers. Each render has options.threads threads, so a worker with
// nothing left to take helps with the tiles of the others' renders. A mesh that fails to
// load fails all its images; an image that fails to render or write fails alone; both are
// recorded and the batch goes on. Stops taking work on SIGINT/SIGTERM (StopSignals) and
// leaves no partial file: an image is written to a temp file and renamed, then recorded.
BatchOutcome render_jobs(const std::vector<MeshJob>& jobs, const BatchSetup& setup);

}  // namespace fastshade
