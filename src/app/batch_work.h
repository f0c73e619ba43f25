// The working part of fastshade batch: meshes loaded and their views rendered on N workers,
// every finished image written whole and recorded in results.jsonl.
#pragma once
#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/batch_inputs.h"
#include "app/batch_progress.h"
#include "app/batch_results.h"
#include "fastshade/render.h"
#include "io/scene_template.h"

namespace fastshade {

// One image to render: a view of a mesh.
struct BatchImage {
  int view = 0;
  double angle_deg = 0;     // the camera's turn about the vertical (orbit_camera)
  std::string output;       // file name in the output directory
  std::string aov_output;   // its AOVs' file beside it (STEM.aov.exr), or "" (none, or in `output`)
  std::string fingerprint;  // what decided its pixels; resuming compares it
};

struct MeshJob {
  BatchMesh mesh;
  std::vector<BatchImage> images;  // its views still to render
};

// What the workers share: read-only, or (log, progress) thread-safe.
struct BatchSetup {
  const SceneTemplate& scene;
  const RenderOptions& options;  // options.threads: the number of workers, 0 = all cores
  AovSet aovs;                   // written with each image (write_image with AOVs)
  std::filesystem::path outdir;
  int views = 1;
  ResultsLog& log;
  BatchProgress& progress;
};

// The fields of an image's results line that every status has.
nlohmann::json batch_line(const BatchMesh& mesh, const BatchImage& image, int views,
                          const char* status);

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
