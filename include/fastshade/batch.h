// Batches: every mesh of files, directories and list files rendered from a template scene's
// fit camera in K views, resumable, each image recorded in OUTDIR/results.jsonl
// (docs/BATCH.md). `fastshade batch` runs a plan on a pool of workers; fastshade.batch in
// Python runs it mesh by mesh, locally or as Ray tasks. Both write the same files.
#pragma once
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "fastshade/image.h"
#include "fastshade/render.h"

namespace fastshade {

struct BatchSpec {
  std::vector<std::string> inputs;  // mesh files, directories (searched recursively), list files
  std::filesystem::path outdir;     // created if missing
  std::string scene;                // template scene file; empty: the embedded default template
  int width = 0, height = 0;        // image size; 0: the template's
  int views = 1;                    // per mesh, turned 360/K degrees about the vertical
  int shard_index = 0, shard_count = 1;  // render part I of N of the sorted meshes
  std::string format = "png";       // png, exr or tif
  AovSet aovs;                      // written with each image (write_image with AOVs)
  RenderOptions options;            // options.threads: each render's threads
};

// A mesh as the inputs name it.
struct BatchMesh {
  // As found: an argument, a directory argument joined with the file's path below it, or a
  // list file's directory joined with its line; lexically normalised.
  std::filesystem::path path;
  std::string key;   // path.generic_string(): the sort key, hashed into `name`
  std::string name;  // output base name: the file's stem, '-', 16 hex digits of the key's hash
  std::uintmax_t file_bytes = 0;  // 0 if the file cannot be read (its load will say why)
};

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

struct BatchPlan {
  std::vector<MeshJob> jobs;  // the largest mesh file first: its load starts at once
  // The results lines (JSON text) of the images an earlier run completed with the same
  // settings, whose files exist: status "skipped".
  std::vector<std::string> skipped;
  std::size_t to_render = 0;
};

// Checks the spec (InputError naming the option: "--views: ...", "--format: ..."), reads the
// template, finds the meshes of the shard, creates the output directory, and plans every view
// the results of earlier runs do not cover. Removes temporary files a killed run left.
BatchPlan plan_batch(const BatchSpec& spec);

// Loads the job's mesh once and renders, writes and records each of its views in order: one
// results line (JSON text) per image, status "ok" or "failed" (with "error"); a mesh that does
// not load fails all its images. Throws only for a spec plan_batch() would refuse.
std::vector<std::string> render_mesh_job(const BatchSpec& spec, const MeshJob& job);

// The "failed" results lines of every image of a job whose render never reported (a Ray task
// that failed, a worker that died), each with `error`.
std::vector<std::string> failed_job_lines(const BatchSpec& spec, const MeshJob& job, const std::string& error);

// What a batch on this machine reports back while it runs, each from any worker thread (both
// optional).
struct BatchCallbacks {
  std::function<void(bool ok, const std::string& what)> image_done;  // "KEY view V: 12.3 ms"
  std::function<bool()> stop_requested;  // polled before each load and image: true stops
};
struct BatchOutcome {
  std::size_t ok = 0, failed = 0;
  std::map<std::string, std::string> failures;  // mesh key -> its first error
  std::string fatal;  // results.jsonl could not be written: the batch stopped
  int threads = 0;    // workers used
};
// Runs a plan on this machine: records its skipped lines, then renders every job on
// spec.options.threads workers (0: all cores), each render with the same number of threads.
// Workers take views of loaded meshes first, else load the next mesh in plan order (the
// largest first), so one mesh's views spread over all workers and small meshes load around
// a large one. A mesh that fails to load fails all its images, an image that fails fails
// alone; both are recorded and the batch goes on. Throws InputError if results.jsonl cannot be
// opened.
BatchOutcome render_batch(const BatchSpec& spec, const BatchPlan& plan, const BatchCallbacks& callbacks = {});

// The part I (from 0) of N that BatchSpec's shard_index and shard_count name, from "I/N" (the
// command line's --shard). Throws InputError naming `where` unless 0 <= I < N <= kMaxShards.
struct Shard {
  int index = 0, count = 1;
};
inline constexpr int kMaxShards = 1000000;  // far above any cluster; keeps I and N in an int
Shard parse_shard(const std::string& text, const std::string& where = "--shard");

// Appends results lines to OUTDIR/results.jsonl, each whole (docs/BATCH.md, "Results").
void append_batch_results(const std::filesystem::path& outdir, const std::vector<std::string>& lines);

}  // namespace fastshade
