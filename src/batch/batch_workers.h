// A batch's pool of workers (render_batch in include/fastshade/batch.h): meshes loaded and
// their views rendered on N workers, every finished image written whole and recorded in
// results.jsonl.
#pragma once
#include <vector>

#include "batch/batch_results.h"
#include "batch/batch_view.h"
#include "fastshade/batch.h"

namespace fastshade {

// What the workers share: read-only, or (log, the callbacks) thread-safe.
struct BatchSetup {
  BatchContext context;  // context.options.threads: the number of workers, 0 = all cores
  ResultsLog& log;
  const BatchCallbacks& callbacks;
};

// Renders every job's images. Workers take views of loaded meshes first, else load the next
// mesh in `jobs` order (put the largest first: the longest load starts at once, small meshes
// fill in around it) and queue its views, else wait while a load is in flight; so one mesh's
// views spread over all workers. Each render has options.threads threads, so a worker with
// nothing left to take helps with the tiles of the others' renders. A mesh that fails to
// load fails all its images; an image that fails to render or write fails alone; both are
// recorded and the batch goes on. Stops taking work once callbacks.stop_requested() says so,
// and leaves no partial file: an image is written to a temp file and renamed, then recorded.
BatchOutcome render_jobs(const std::vector<MeshJob>& jobs, const BatchSetup& setup);

}  // namespace fastshade
