// Timing several render configurations of one scene fairly on a shared, noisy machine: one
// frame of each per round, the rounds rotated. Shared by `report` and `tune`.
#pragma once
#include <span>
#include <string>
#include <vector>

#include "app/progress.h"
#include "fastshade/profile.h"
#include "fastshade/image.h"
#include "fastshade/render.h"
#include "fastshade/scene.h"

namespace fastshade {

// One configuration's last image, the counts of its last frame and its timed frames' times.
struct Measured {
  Image image;
  RenderStats stats;
  std::vector<double> total_ms, raster_ms;
};

// What one frame of `scene` costs, in the progress bar's unit (pixels).
double frame_cost(const Scene& scene);

// Renders every configuration in rounds (round 0 warms up, untimed): one frame of each, then
// the next round, starting one configuration later each time, so a machine that slows down
// during a scene slows every configuration alike and none always runs right after the same
// other one. `labels[i]` names `options[i]` on the progress bar.
std::vector<Measured> measure_in_rounds(const std::string& scene_name, const Scene& scene,
                                        std::span<const RenderOptions> options,
                                        std::span<const std::string> labels, int frames,
                                        Progress& progress);

}  // namespace fastshade
