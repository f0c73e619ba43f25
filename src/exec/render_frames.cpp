// render(): a scene's frames through one Renderer, and the benchmark's policy for timing them.
#include <algorithm>
#include <vector>

#include "fastshade/profile.h"
#include "fastshade/render.h"

namespace fastshade {

StageTimes median_stages(std::span<const StageTimes> frames) {
  auto of = [&](double StageTimes::*stage) {
    std::vector<double> v;
    v.reserve(frames.size());
    for (const StageTimes& t : frames) v.push_back(t.*stage);
    return median(std::move(v));
  };
  return {of(&StageTimes::front_end), of(&StageTimes::binning), of(&StageTimes::raster_shade),
          of(&StageTimes::total)};
}

double RenderStats::mpix_per_s() const {
  return median.total > 0 ? covered_pixels / (median.total * 1e3) : 0.0;
}
double RenderStats::mtri_per_s() const {
  return median.total > 0 ? triangles_in / (median.total * 1e3) : 0.0;
}

Image render(const Scene& scene, const RenderOptions& options, int frames, RenderStats* stats, const AovSet& which,
             AovImages* aovs) {
  Renderer renderer(scene, options);
  frames = std::max(frames, 1);
  std::vector<StageTimes> times(1);
  Image image;
  AovImages no_aovs;
  AovImages& into = aovs ? *aovs : no_aovs;
  const AovSet asked = aovs ? which : AovSet{};
  renderer.render_frame(image, asked, into, &times[0]);
  // One frame is the frame asked for, timed; a benchmark's first frame is a warm-up
  // (first-touch allocation, caches) that no median includes.
  if (frames > 1) {
    times.resize(frames);
    for (StageTimes& t : times) renderer.render_frame(image, asked, into, &t);
  }
  if (stats) {
    *stats = renderer.last_stats();
    stats->frames = frames;
    stats->median = median_stages(times);
  }
  return image;
}

}  // namespace fastshade
