// The frame benchmark: full 1920x1080 frames of real meshes, per method and thread count,
// with the per-stage medians as counters. Run (Release build):
//   build/frame_bench --benchmark_counters_tabular=true
// Meshes come from ../shared/models (FASTSHADE_SHARED_MODELS); missing ones are skipped.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "fastshade/profile.h"
#include "fastshade/render.h"
#include "fastshade/scene.h"

namespace {

using namespace fastshade;

// The issue's frame: fit camera at 2.5 radii, one view-space light toward (1,1,1), ambient
// 0.1, kd 0.7, ks 0.5, n 32, normals recomputed.
std::string frame_scene_json(const std::string& mesh, int width, int height, double shininess,
                             double distance) {
  return R"({"image": {"width": )" + std::to_string(width) + R"(, "height": )" +
         std::to_string(height) + R"(, "background": [0, 0, 0]},
    "camera": {"fit": true, "distance": )" + std::to_string(distance) + R"(, "fovy_deg": 45},
    "lights": [{"type": "directional", "direction": [1, 1, 1], "color": [1, 1, 1], "space": "view"}],
    "ambient": [0.1, 0.1, 0.1],
    "materials": {"m": {"diffuse": 0.7, "specular": 0.5, "shininess": )" +
         std::to_string(shininess) + R"(}},
    "objects": [{"mesh": ")" + mesh + R"(", "material": "m", "normals": "recompute"}]})";
}

const Scene* cached_scene(const std::string& file) {
  static std::map<std::string, std::unique_ptr<Scene>> scenes;
  auto it = scenes.find(file);
  if (it != scenes.end()) return it->second.get();
  const std::filesystem::path models = FASTSHADE_SHARED_MODELS;
  if (!std::filesystem::exists(models / file)) return nullptr;
  auto scene = std::make_unique<Scene>(
      parse_scene(frame_scene_json(file, 1920, 1080, 32, 2.5), file, models));
  return (scenes[file] = std::move(scene)).get();
}

void BM_Frame(benchmark::State& state, std::string mesh, std::string method) {
  const Scene* scene = cached_scene(mesh);
  if (!scene) {
    state.SkipWithError(("missing " + mesh).c_str());
    return;
  }
  RenderOptions options;
  options.method = parse_option<ShadingMethod>(method, "method");
  options.threads = static_cast<int>(state.range(0));
  Renderer renderer(*scene, options);
  Image image = renderer.render_frame();  // warm-up
  std::vector<StageTimes> times;
  for (auto _ : state) {
    StageTimes t;
    renderer.render_frame(image, &t);
    benchmark::DoNotOptimize(image.rgb.data());
    times.push_back(t);
  }
  const StageTimes median = median_stages(times);
  state.counters["front_ms"] = median.front_end;
  state.counters["bin_ms"] = median.binning;
  state.counters["raster_ms"] = median.raster_shade;
  state.counters["total_ms"] = median.total;
  const RenderStats stats = renderer.last_stats();
  state.counters["Mtri"] = stats.triangles_in / 1e6;
  state.counters["Mpix"] = stats.covered_pixels / 1e6;
  state.SetLabel(stats.isa);
}

void register_all() {
  for (const char* mesh : {"bunny.ply", "dragon_871k.ply"})
    for (const char* method : {"phong", "gouraud", "auto"})
      benchmark::RegisterBenchmark((std::string("frame/") + mesh + "/" + method).c_str(), BM_Frame,
                                   std::string(mesh), std::string(method))
          ->Arg(1)
          ->Arg(2)
          ->ArgName("threads")
          ->Unit(benchmark::kMillisecond)
          ->MinTime(2.0)
          ->UseRealTime();
}

}  // namespace

int main(int argc, char** argv) {
  register_all();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
