#include "batch/batch_plan.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "batch/batch_inputs.h"
#include "batch/batch_results.h"
#include "batch/batch_view.h"
#include "core/ms_between.h"
#include "fastshade/error.h"
#include "fastshade/aov_list.h"
#include "fastshade/atomic_file.h"
#include "io/scene_file.h"

namespace fastshade {
namespace fs = std::filesystem;

namespace {

// Views per mesh: one a degree at most; more would only repeat nearly the same image.
constexpr int kMaxViews = 360;

// The settings that decide every image's pixels, besides the mesh and the view: the template
// (with --size), the shading options, the format. Not threads or tiles (the image is the same).
std::string settings_text(const SceneTemplate& scene, const BatchSpec& spec) {
  const RenderOptions& o = spec.options;
  return scene.canonical() + "|method=" + std::string(option_name(o.method)) + "|brdf=" + option_name(o.brdf) +
         "|normals=" + std::string(option_name(o.normals)) + "|gouraud=" + std::string(option_name(o.gouraud)) +
         "|max_error=" + std::to_string(o.max_error) +
         "|srgb=" + std::to_string(o.srgb) + "|views=" + std::to_string(spec.views) +
         "|format=" + spec.format + (spec.aovs.any() ? "|aov=" + aov_list_text(spec.aovs) : "");
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
// (`completed`: a results line says so) whose files, renamed into place whole, exist.
// `outputs`: every file name of this shard, skipped ones included.
BatchPlan plan_images(const std::vector<BatchMesh>& meshes, const std::string& settings, const BatchSpec& spec,
                      const std::set<std::string>& completed, std::set<std::string>& outputs) {
  BatchPlan plan;
  const bool separate_aovs = spec.aovs.any() && spec.format != "exr";  // STEM.aov.exr beside the image
  for (const BatchMesh& mesh : meshes) {
    MeshJob job{mesh, {}};
    const std::string stamp = mesh_stamp(mesh);
    for (int view = 0; view < spec.views; ++view) {
      BatchImage image;
      image.view = view;
      image.angle_deg = 360.0 * view / spec.views;
      image.output = output_name(mesh, view, spec.views, spec.format);
      image.fingerprint = stable_hash(settings + "|" + stamp + "|view=" + std::to_string(view));
      outputs.insert(image.output);
      if (separate_aovs) {
        image.aov_output = aov_path(image.output).string();
        outputs.insert(image.aov_output);
      }
      std::error_code ec;
      if (completed.count(completed_key(image.output, image.fingerprint)) &&
          fs::exists(spec.outdir / image.output, ec) &&
          (!separate_aovs || fs::exists(spec.outdir / image.aov_output, ec))) {
        plan.skipped.push_back(batch_line(mesh, image, spec.views, "skipped").dump());
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

}  // namespace

SceneTemplate batch_template(const BatchSpec& spec) {
  SceneTemplate scene = spec.scene.empty()
                            ? SceneTemplate(default_batch_template_json(), "<default batch template>")
                            : SceneTemplate(read_scene_file(spec.scene), spec.scene);
  if (spec.width != 0 || spec.height != 0) {
    if (spec.width < 1 || spec.height < 1 || spec.width > kMaxImageSide || spec.height > kMaxImageSide)
      throw InputError("--size", "expected WxH with each in [1, " + std::to_string(kMaxImageSide) + "], got " +
                                     std::to_string(spec.width) + "x" + std::to_string(spec.height));
    scene.set_image_size(spec.width, spec.height);
  }
  return scene;
}

BatchPlan plan_batch(const BatchSpec& spec) {
  // Everything is checked before anything is written.
  validate(spec.options);
  if (spec.views < 1 || spec.views > kMaxViews)
    throw InputError("--views", "expected 1 to " + std::to_string(kMaxViews) + ", got " + std::to_string(spec.views));
  if (spec.format != "png" && spec.format != "exr" && spec.format != "tif")
    throw InputError("--format", "expected png, exr or tif, got '" + spec.format + "'");
  const Shard shard{spec.shard_index, spec.shard_count};
  check_shard(shard, "--shard");
  const SceneTemplate scene = batch_template(spec);
  const std::vector<BatchMesh> meshes = take_shard(find_meshes(spec.inputs), shard);
  check_outdir(spec.outdir, spec.format);
  std::set<std::string> outputs;
  BatchPlan plan = plan_images(meshes, settings_text(scene, spec), spec,
                               completed_images(spec.outdir / "results.jsonl"), outputs);
  remove_stale_temp_files(spec.outdir, outputs);
  return plan;
}

std::vector<std::string> render_mesh_job(const BatchSpec& spec, const MeshJob& job) {
  const SceneTemplate scene = batch_template(spec);
  const BatchContext context{scene, spec.options, spec.aovs, spec.outdir, spec.views};
  std::vector<std::string> lines;
  const auto t0 = SteadyClock::now();
  Scene fit_scene;
  try {
    fit_scene = load_batch_scene(scene, job.mesh);
  } catch (const std::exception& e) {  // InputError, or std::bad_alloc on a huge mesh
    const double load_ms = ms_since(t0);
    for (const BatchImage& image : job.images) lines.push_back(failed_line(job.mesh, image, spec.views, e.what(), load_ms).dump());
    return lines;
  }
  const double load_ms = ms_since(t0);
  for (const BatchImage& image : job.images) {
    try {
      lines.push_back(render_batch_view(context, fit_scene, job.mesh, image, load_ms).dump());
    } catch (const std::exception& e) {  // InputError from write_image, std::bad_alloc, ...
      lines.push_back(failed_line(job.mesh, image, spec.views, e.what(), load_ms).dump());
    }
  }
  return lines;
}

std::vector<std::string> failed_job_lines(const BatchSpec& spec, const MeshJob& job, const std::string& error) {
  std::vector<std::string> lines;
  for (const BatchImage& image : job.images) lines.push_back(failed_line(job.mesh, image, spec.views, error, 0.0).dump());
  return lines;
}

void append_batch_results(const fs::path& outdir, const std::vector<std::string>& lines) {
  ResultsLog log(outdir / "results.jsonl");
  for (const std::string& line : lines) log.append(nlohmann::json::parse(line));
}

}  // namespace fastshade
