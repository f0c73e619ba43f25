#include "app/timing_rounds.h"

#include <algorithm>
#include <memory>

namespace fastshade {

namespace {
// The progress bar's cost model: a frame costs its pixels plus this many per triangle. From
// docs/PERFORMANCE.md's 1080p frames: bunny (69k triangles) 25 ms, dragon (871k) 100 ms, so a
// triangle costs about as much as 10 pixels.
constexpr double kTriangleCostPx = 10;
}  // namespace

double frame_cost(const Scene& scene) {
  double triangles = 0;
  for (const Object& o : scene.objects) triangles += static_cast<double>(o.mesh->triangles.size());
  return double(scene.width) * scene.height + kTriangleCostPx * triangles;
}

std::vector<Measured> measure_in_rounds(const std::string& scene_name, const Scene& scene,
                                        std::span<const RenderOptions> options,
                                        std::span<const std::string> labels, int frames,
                                        Progress& progress) {
  const double cost = frame_cost(scene);
  std::vector<std::unique_ptr<Renderer>> renderers;
  for (const RenderOptions& o : options) renderers.push_back(std::make_unique<Renderer>(scene, o));
  const std::size_t n = renderers.size();
  std::vector<Measured> m(n);
  for (int round = 0; round <= frames; ++round) {
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t i = (k + static_cast<std::size_t>(round)) % n;
      StageTimes t;
      renderers[i]->render_frame(m[i].image, &t);
      if (round > 0) {
        m[i].total_ms.push_back(t.total);
        m[i].raster_ms.push_back(t.raster_shade);
      }
      const std::string when = round == 0 ? "warm-up" : "frame " + std::to_string(round) + "/" + std::to_string(frames);
      progress.advance(cost, scene_name + " " + when + ": " + labels[i]);
    }
  }
  for (std::size_t i = 0; i < n; ++i) m[i].stats = renderers[i]->last_stats();
  return m;
}

}  // namespace fastshade
