// fastshade side by side with Mesa's llvmpipe: the same frame (geometry, camera, lights,
// materials, size) drawn by both in one process, timed alternately, and both compared with
// fastshade's `reference` method. One thread count per run: llvmpipe reads LP_NUM_THREADS
// once, when EGL creates its screen. See bench/peers/README.md; run with `bash tools/peer.sh`.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "fastshade/profile.h"
#include "egl_context.h"
#include "fastshade/compare.h"
#include "fastshade/error.h"
#include "fastshade/render.h"
#include "fastshade/scene.h"
#include "gl_api.h"
#include "gl_frame.h"

namespace {

using namespace fastshade;

// Idle time before each timed frame, so that the other renderer's worker threads (TBB spins
// briefly before sleeping) are asleep and the two do not compete for the two cores.
constexpr std::chrono::milliseconds kSettle{20};

struct Times {
  std::vector<double> wall_ms, cpu_ms;
};

double cpu_now_ms() {  // all threads of the process
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

template <typename F>
void time_frame(Times& times, F&& frame) {
  std::this_thread::sleep_for(kSettle);
  const double cpu0 = cpu_now_ms();
  const auto t0 = std::chrono::steady_clock::now();
  frame();
  times.wall_ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  times.cpu_ms.push_back(cpu_now_ms() - cpu0);
}

// "median (fastest)": on a shared machine the fastest frame is the one least disturbed.
std::string time_cell(const std::vector<double>& ms) {
  char cell[48];
  std::snprintf(cell, sizeof cell, "%.1f (%.1f)", median(ms), *std::min_element(ms.begin(), ms.end()));
  return cell;
}

std::string error_cell(const ImageDiff& d) {
  char cell[64];
  std::snprintf(cell, sizeof cell, "%.0f / %.3f / %.3f", d.max_abs_lsb, d.rmse_lsb, d.pct_over_1lsb);
  return cell;
}

struct Args {
  int threads = 2;
  int frames = 21;
  std::vector<std::string> methods{"auto", "phong", "gouraud"};
  std::string hidden_faces = "skip";  // fastshade's --hidden-faces
  std::string cull = "back";          // llvmpipe: back faces culled (pyrender's default) or none
  std::filesystem::path images;
  std::vector<std::filesystem::path> scenes;
};

void run_scene(const std::filesystem::path& scene_path, const Args& args) {
  const Scene scene = load_scene(scene_path);
  const std::string name = scene_path.stem().string();
  RenderOptions options;
  options.threads = args.threads;
  options.hidden_faces = parse_option<HiddenFaces>(args.hidden_faces, "--hidden-faces");
  options.method = ShadingMethod::Reference;
  const Image reference_image = render(scene, options);
  const ImageF reference = to_float(reference_image);
  if (!args.images.empty()) write_image(reference_image, args.images / (name + "_reference.png"));
  long long triangles = 0;
  for (const Object& o : scene.objects) triangles += static_cast<long long>(o.mesh->triangles.size());

  for (const std::string& method : args.methods) {
    options.method = parse_option<ShadingMethod>(method, "--method");
    Renderer fastshade(scene, options);
    // auto's image is phong's within its budget: the GL side draws per-pixel Phong for it.
    peer::GlFrame llvmpipe(scene, method != "gouraud", args.cull == "back");
    auto draw_llvmpipe = [&] {
      llvmpipe.draw();
      glFinish();
    };
    const Image fastshade_image = fastshade.render_frame();  // warm-up (and the image: deterministic)
    Image scratch = fastshade_image;  // the timed frames' buffer, reused as render() reuses its own
    draw_llvmpipe();                                         // warm-up: compiles the shader variants
    Times fs, gl;
    for (int i = 0; i < args.frames; ++i) {  // alternate who goes first
      if (i % 2) time_frame(fs, [&] { fastshade.render_frame(scratch); });
      time_frame(gl, draw_llvmpipe);
      if (!(i % 2)) time_frame(fs, [&] { fastshade.render_frame(scratch); });
    }
    const auto t0 = std::chrono::steady_clock::now();
    const Image llvmpipe_image = llvmpipe.read();
    const double read_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();

    const ImageDiff gl_error = compare_images(to_float(llvmpipe_image), reference);
    const ImageDiff fs_error = compare_images(to_float(fastshade_image), reference);
    const ImageDiff between = compare_images(to_float(llvmpipe_image), to_float(fastshade_image));
    const double gl_ms = median(gl.wall_ms), fs_ms = median(fs.wall_ms);
    std::printf("| %s | %lld | %s | %s | %d | %s | %s | %.2f | %s | %s | %s | %.2f | %.2f | %.1f |\n",
                name.c_str(), triangles, method.c_str(), args.cull.c_str(), args.threads, time_cell(gl.wall_ms).c_str(),
                time_cell(fs.wall_ms).c_str(), gl_ms / fs_ms, error_cell(gl_error).c_str(),
                error_cell(fs_error).c_str(), error_cell(between).c_str(), median(gl.cpu_ms) / gl_ms,
                median(fs.cpu_ms) / fs_ms, read_ms);
    std::fflush(stdout);
    if (!args.images.empty()) {
      write_image(llvmpipe_image, args.images / (name + "_" + method + "_llvmpipe.png"));
      write_image(fastshade_image, args.images / (name + "_" + method + "_fastshade.png"));
    }
  }
}

int run(const Args& args) {
  if (!args.images.empty()) check_output_path(args.images / "probe.png");
  const peer::EglContext context(args.threads);
  std::printf("GL_RENDERER: %s\nGL_VERSION: %s\nthreads: %d (fastshade --threads, LP_NUM_THREADS); %d timed "
              "frames each after one warm-up, alternating; medians (fastest in brackets)\n\n",
              context.renderer().c_str(), context.version().c_str(), args.threads, args.frames);
  std::printf(
      "| mesh | triangles | method | llvmpipe culls | threads | llvmpipe ms: median (min) | fastshade ms | "
      "llvmpipe / fastshade (medians) | "
      "llvmpipe vs reference: max / RMSE LSB / %% px > 1 | fastshade vs reference | llvmpipe vs fastshade | "
      "llvmpipe CPU/wall | fastshade CPU/wall | llvmpipe readback ms |\n"
      "|---|---:|---|---|---:|---:|---:|---:|---|---|---|---:|---:|---:|\n");
  for (const std::filesystem::path& scene : args.scenes) run_scene(scene, args);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"fastshade and Mesa's llvmpipe on the same frames: time ratio and error vs reference"};
  Args args;
  app.add_option("scenes", args.scenes, "scene files (bench/peers/*.json)")->required()->check(CLI::ExistingFile);
  app.add_option("--threads", args.threads, "fastshade threads and LP_NUM_THREADS")->check(CLI::Range(1, 64));
  app.add_option("--frames", args.frames, "timed frames per renderer")->check(CLI::Range(1, 10000));
  app.add_option("--method", args.methods, "fastshade's methods (auto is drawn as phong by GL): auto, phong, gouraud")
      ->check(CLI::IsMember({"auto", "phong", "gouraud"}));
  app.add_option("--cull", args.cull, "llvmpipe: back (back faces culled, pyrender's default) or none")
      ->check(CLI::IsMember({"back", "none"}));
  app.add_option("--hidden-faces", args.hidden_faces,
                 "fastshade: skip (its default: back faces a closed mesh hides are culled) or draw "
                 "(every face, as llvmpipe without culling)")
      ->check(CLI::IsMember({"skip", "draw"}));
  app.add_option("--images", args.images, "write both renderers' images to this directory")
      ->check(CLI::ExistingDirectory);
  CLI11_PARSE(app, argc, argv);
  try {
    return run(args);
  } catch (const InputError& e) {
    std::fprintf(stderr, "llvmpipe_peer: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "llvmpipe_peer: %s\n", e.what());
    return 1;
  }
}
