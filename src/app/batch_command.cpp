// fastshade batch: checks the options, finds the meshes, plans the images (skipping those an
// earlier run completed), hands them to the workers (batch_work.h) and sums up (docs/BATCH.md).
#include <malloc.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "app/aov_list.h"
#include "app/batch_inputs.h"
#include "app/batch_progress.h"
#include "app/batch_results.h"
#include "app/batch_work.h"
#include "app/commands.h"
#include "app/stop_signals.h"
#include "fastshade/error.h"
#include "fastshade/image.h"
#include "io/atomic_file.h"
#include "io/scene_file.h"
#include "io/scene_template.h"

namespace fastshade {
namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

// Views per mesh: one a degree at most; more would only repeat nearly the same image.
constexpr int kMaxViews = 360;

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

// The settings that decide every image's pixels, besides the mesh and the view: the template
// (with --size), the shading options, the format. Not threads or tiles (the image is the same).
std::string settings_text(const SceneTemplate& scene, const BatchCommand& cmd, const AovSet& aovs) {
  const RenderOptions& o = cmd.options;
  return scene.canonical() + "|method=" + o.method + "|brdf=" + o.brdf + "|normals=" + o.normals +
         "|gouraud=" + o.gouraud + "|max_error=" + std::to_string(o.max_error) +
         "|srgb=" + std::to_string(o.srgb) + "|views=" + std::to_string(cmd.views) +
         "|format=" + cmd.format + (aovs.any() ? "|aov=" + aov_list_text(aovs) : "");
}

// The mesh file's identity as far as a rerun can tell without reading it.
std::string mesh_stamp(const BatchMesh& mesh) {
  std::error_code ec;
  const auto mtime = fs::last_write_time(mesh.path, ec);
  return mesh.key + "|bytes=" + std::to_string(mesh.file_bytes) + "|mtime=" +
         (ec ? std::string("?") : std::to_string(mtime.time_since_epoch().count()));
}

std::string output_name(const BatchMesh& mesh, int view, int views, const std::string& format) {
  std::string name = mesh.name;
  if (views > 1) {
    std::string index = std::to_string(view);
    index.insert(0, std::to_string(views - 1).size() - index.size(), '0');  // sorts by view
    name += "-v" + index;
  }
  return name + "." + format;
}

void check_outdir(const fs::path& outdir, const std::string& format) {
  const std::string where = outdir.string();
  if (where.empty()) throw InputError("-o", "empty output directory");
  std::error_code ec;
  if (fs::exists(outdir, ec) && !fs::is_directory(outdir, ec))
    throw InputError(where, "exists and is not a directory");
  fs::create_directories(outdir, ec);
  if (ec) throw InputError(where, "cannot create the output directory: " + ec.message());
  if (::access(outdir.c_str(), W_OK) != 0)
    throw InputError(where, "the output directory is not writable");
  check_output_path(outdir / ("probe." + format));  // the format can be written
}

// Temp files of our own outputs are from a run that was killed (this shard's outputs are no
// other shard's): never renamed into place, they are removed.
void remove_stale_temp_files(const fs::path& outdir, const std::set<std::string>& outputs) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(outdir, ec)) {
    const std::string target = temp_file_target(entry.path().filename().string());
    if (!target.empty() && outputs.count(target)) fs::remove(entry.path(), ec);
  }
}

// Every view of every mesh, minus those an earlier run completed with the same settings
// (`completed`: a results line says so) whose file, renamed into place whole, exists.
struct Plan {
  std::vector<MeshJob> jobs;  // the largest mesh file first: its load starts at once
  std::vector<std::pair<const BatchMesh*, BatchImage>> skipped;
  std::set<std::string> outputs;  // every image name of this shard, skipped ones included
  std::size_t to_render = 0;
};

Plan plan_images(const std::vector<BatchMesh>& meshes, const std::string& settings,
                 const BatchCommand& cmd, const AovSet& aovs, const std::set<std::string>& completed) {
  Plan plan;
  const bool separate_aovs = aovs.any() && cmd.format != "exr";  // STEM.aov.exr beside the image
  for (const BatchMesh& mesh : meshes) {
    MeshJob job{mesh, {}};
    const std::string stamp = mesh_stamp(mesh);
    for (int view = 0; view < cmd.views; ++view) {
      BatchImage image;
      image.view = view;
      image.angle_deg = 360.0 * view / cmd.views;
      image.output = output_name(mesh, view, cmd.views, cmd.format);
      image.fingerprint = stable_hash(settings + "|" + stamp + "|view=" + std::to_string(view));
      plan.outputs.insert(image.output);
      if (separate_aovs) image.aov_output = aov_path(image.output).string();
      if (separate_aovs) plan.outputs.insert(image.aov_output);
      std::error_code ec;
      if (completed.count(completed_key(image.output, image.fingerprint)) &&
          fs::exists(fs::path(cmd.outdir) / image.output, ec) &&
          (!separate_aovs || fs::exists(fs::path(cmd.outdir) / image.aov_output, ec))) {
        plan.skipped.emplace_back(&mesh, image);
      } else {
        job.images.push_back(image);
      }
    }
    plan.to_render += job.images.size();
    if (!job.images.empty()) plan.jobs.push_back(std::move(job));
  }
  std::stable_sort(plan.jobs.begin(), plan.jobs.end(), [](const MeshJob& a, const MeshJob& b) {
    return a.mesh.file_bytes > b.mesh.file_bytes;
  });
  return plan;
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
  // Everything is checked before anything is written.
  validate(cmd.options);
  if (cmd.views < 1 || cmd.views > kMaxViews)
    throw InputError("--views", "expected 1 to " + std::to_string(kMaxViews) + ", got " +
                                    std::to_string(cmd.views));
  if (cmd.format != "png" && cmd.format != "exr" && cmd.format != "tif")
    throw InputError("--format", "expected png, exr or tif, got '" + cmd.format + "'");
  const AovSet aovs = cmd.aov.empty() ? AovSet{} : parse_aov_list(cmd.aov);
  const Shard shard = parse_shard(cmd.shard);
  SceneTemplate scene = cmd.scene.empty()
                            ? SceneTemplate(default_batch_template_json(), "<default batch template>")
                            : SceneTemplate(read_scene_file(cmd.scene), cmd.scene);
  if (!cmd.size.empty()) {
    const ImageSize size = parse_size(cmd.size);
    scene.set_image_size(size.width, size.height);
  }
  const std::vector<BatchMesh> meshes = take_shard(find_meshes(cmd.inputs), shard);
  const fs::path outdir(cmd.outdir);
  check_outdir(outdir, cmd.format);

  const fs::path results_path = outdir / "results.jsonl";
  const Plan plan =
      plan_images(meshes, settings_text(scene, cmd, aovs), cmd, aovs, completed_images(results_path));
  remove_stale_temp_files(outdir, plan.outputs);

  ResultsLog log(results_path);
  BatchProgress progress(plan.to_render, ::isatty(STDERR_FILENO) == 1);
  for (const auto& [mesh, image] : plan.skipped)
    log.append(batch_line(*mesh, image, cmd.views, "skipped"));

  keep_freed_memory();
  const Clock::time_point start = Clock::now();
  BatchOutcome outcome;
  {
    const StopSignals signals;
    outcome = render_jobs(plan.jobs, BatchSetup{scene, cmd.options, aovs, outdir, cmd.views, log, progress});
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
