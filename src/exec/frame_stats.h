// One frame's counts (triangles by fate, shading paths, hybrid segment lengths, what was left
// out) gathered from the frame's chunks and the back end into RenderStats.
#pragma once
#include "exec/tile_executor.h"
#include "fastshade/render.h"
#include "frame/frame.h"
#include "frame/method_needs.h"
#include "front/scene_geometry.h"

namespace fastshade {

struct FrameOutcome {
  const SceneGeometry& geometry;
  const Frame& frame;
  BackEndCounts back_end;
  int objects_culled = 0;       // objects wholly outside the view frustum
  bool method_classifies = false;  // the method has shading paths (its options apply)
  bool classified = false;         // and this frame classified (it has lights)
  double classify_min_px = 0;      // --classify-min-px, for the left-out report
  SegmentSteps segment_steps = SegmentSteps::None;
};

// Fills every count of `stats` but the times and the renderer's own fields (threads, tile,
// method, ISA).
void count_frame(const FrameOutcome& outcome, RenderStats& stats);

}  // namespace fastshade
