// Front end, second stage: one chunk of triangles culled, clipped where needed, snapped and
// wound for the rasterizer.
#pragma once
#include <cstdint>
#include <vector>

#include "classify/classifier.h"
#include "fastshade/scene.h"
#include "frame/frame.h"
#include "front/scene_geometry.h"
#include "front/segment_steps.h"
#include "front/self_occlusion.h"
#include "front/vertex_stage.h"

namespace fastshade {

struct SetupParams {
  SimdTarget simd;  // the renderer's ISA
  Viewport viewport;
  Cull cull = Cull::None;
  bool with_attrs = false;  // clipping interpolates attributes only if the method reads them
  bool sierpinski = false;  // split large triangles into their four Sierpinski parts
  bool with_sources = false;  // Chunk::sources: the frame writes triangle or object ids
  // Classifying methods (`auto`): the shading path of every triangle, decided here, once,
  // from its input triangle's vertex normals (a clipped piece inherits its triangle's path:
  // its normals are a subset of the triangle's). Needs the mesh's n_view (and pos_view for
  // a local viewer).
  const Classifier* classifier = nullptr;
  // A block of kFateBlock triangles whose kept ones' pixel boxes average below this area takes
  // the specular path unclassified (RenderOptions::classify_min_px); 0: classify all.
  double classify_min_box_px = 0.0;
  // This frame's self-occlusion plan: kept back faces that it proves hidden are culled.
  const SelfOcclusionPlan* occlusion = nullptr;
  // Which triangles draw hybrid segments: those wide enough for them are listed in
  // Chunk::segment_pending, for decide_segment_steps() once setup is done.
  SegmentSteps segment_steps = SegmentSteps::None;
};

// Triangles [first, last) of the scene into `chunk` (cleared first, capacity kept).
void setup_chunk(const SceneGeometry& geometry, const ProjectedVertices& vertices,
                 const AttrArrays& attrs, uint32_t first, uint32_t last,
                 const SetupParams& params, Chunk& chunk);

}  // namespace fastshade
