// Rendering a resolved scene: options in, image and statistics out.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "fastshade/image.h"
#include "fastshade/options.h"
#include "fastshade/scene.h"

namespace fastshade {

struct StageTimes {  // milliseconds
  double front_end = 0, binning = 0, raster_shade = 0, total = 0;
};

// One shading path of a classifying method: triangles sent down it (input triangles, by the
// classifier) and pixels it drew that stayed visible.
struct PathStats {
  std::string name;
  long long triangles = 0, pixels = 0;
};

// Per-item costs of a frame, for load-balance studies (include/fastshade/profile.h).
struct FrameProfile;

struct RenderStats {
  long long triangles_in = 0;       // in the scene's meshes
  long long triangles_drawn = 0;    // binned (after clipping; a clipped triangle may count more)
  long long triangles_dropped = 0;  // zero area after snapping, or non-finite
  long long triangles_culled = 0;   // outside the frustum, back-facing, or covering no pixel centre
  long long triangles_hidden = 0;   // of culled: back faces their own mesh provably hides
  long long tiles_total = 0, tiles_nonempty = 0;
  long long covered_pixels = 0;     // pixels any triangle covers (after depth, counted once)
  int threads = 0, tile = 0;
  std::string isa, method;
  // The method that drew: `method`, except where `auto`'s cost model found classifying cannot
  // pay on this frame and ISA and drew it as `phong` (docs/CLASSIFIER.md, "When auto classifies").
  std::string drawn_as;
  std::vector<PathStats> paths;        // classifying methods only
  long long triangles_unclassified = 0;  // of paths' specular: sent there unclassified (--classify-min-px)
  // Frames that draw hybrid segments: of the triangles wide enough for them, how many take
  // segments of 2^m px (index m; 1 px is per-pixel Phong), and how many of those interpolate
  // a light's N.L unclamped (the terminator's split light), and how many of 2+ px light their
  // ends without the specular term (bounded below 2^-24 on the whole triangle). Empty and 0
  // otherwise.
  std::vector<long long> segment_triangles;
  long long segment_split = 0;
  long long segment_no_specular = 0;
  std::vector<std::string> left_out;   // what the frame skipped because the scene needs none of it
  StageTimes median;  // median over timed frames
  int frames = 0;
  double mpix_per_s() const;  // covered pixels / total time
  double mtri_per_s() const;  // triangles_in / total time
  // Every field as one JSON object (the keys of `render --stats`; docs/PIPELINE.md, "Statistics").
  std::string to_json() const;
};

// Renders frames of one scene; keeps its per-frame arena and per-thread scratch between
// frames so that timed frames measure rendering, not allocation.
class Renderer {
 public:
  Renderer(const Scene& scene, const RenderOptions& options);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // One frame; `times` receives this frame's stage times. A non-null `profile` (include/
  // fastshade/profile.h) receives every parallel item's cost; null costs nothing.
  Image render_frame(StageTimes* times = nullptr, FrameProfile* profile = nullptr);
  // The same into `into`, whose buffer is reused when it has the frame's size: what timed
  // loops call, so that frames after the first allocate and clear nothing.
  void render_frame(Image& into, StageTimes* times = nullptr, FrameProfile* profile = nullptr);
  // The same with the AOVs `which` names into `aovs` (buffers reused as `into`'s are; the
  // others emptied). The colour is byte for byte the one without AOVs; the AOVs are the same
  // for any thread count and tile size. A frame without AOVs runs none of their work.
  void render_frame(Image& into, const AovSet& which, AovImages& aovs, StageTimes* times = nullptr);
  // The counts of the last frame (times filled by the caller's timing policy).
  RenderStats last_stats() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// With frames > 1 (a benchmark): one warm-up frame, then `frames` timed ones; stats carry the
// medians. With frames == 1: one frame, timed. `aovs` (non-null) receives the AOVs `which`
// names (Renderer::render_frame); every timed frame computes them.
Image render(const Scene& scene, const RenderOptions& options, int frames = 1, RenderStats* stats = nullptr,
             const AovSet& which = {}, AovImages* aovs = nullptr);

}  // namespace fastshade
