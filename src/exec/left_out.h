// What a frame skipped because its scene needs none of it ("leave out what a scene does not
// need"): one line each, for --explain and the stats JSON.
#pragma once
#include <string>
#include <vector>

#include "exec/tile_executor.h"
#include "front/scene_geometry.h"

namespace fastshade {

struct FrameFacts {
  const PathTally* tally = nullptr;  // classified frames only
  BackEndCounts back_end;
  long long tiles_total = 0;
  long long objects_culled = 0;  // objects wholly outside the view frustum
  long long triangles_hidden = 0;  // back faces their own mesh hides (front/self_occlusion.h)
  long long segments_no_specular = 0;  // hybrid triangles whose segment ends skip the specular term
  bool method_classifies = false;  // the method has shading paths: what they left out follows
  double classify_min_px = 0;      // --classify-min-px, as the user typed it
};

std::vector<std::string> left_out_report(const SceneGeometry& geometry, const ShadeConstants& shade,
                                         const FrameFacts& facts);

}  // namespace fastshade
