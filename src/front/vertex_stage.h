// Front end, first stage: every vertex to clip space, plus the view-space attributes the
// frame's shading method interpolates.
#pragma once
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "frame/frame.h"
#include "frame/method_needs.h"
#include "front/projection.h"
#include "front/scene_geometry.h"

namespace fastshade {

struct ViewTransform {
  glm::mat4 view{1.0f}, proj{1.0f};
};

ViewTransform view_transform(const Scene& scene);

// Every vertex transformed once: clip position (for the clipper), flags, and, for vertices
// that need no clipping, the snapped screen position the triangles share.
struct ProjectedVertices {
  std::vector<glm::vec4> clip;
  std::vector<ScreenVertex> screen;
  std::vector<uint8_t> flags;

  void resize(std::size_t n) {
    clip.resize(n);
    screen.resize(n);
    flags.resize(n);
  }
};

// Parallel over vertices. Outputs are resized; their capacity is reused across frames. An
// object whose bounding box lies wholly outside one frustum plane is not transformed: its
// vertices get every outcode bit, so setup culls its triangles at once. Returns how many
// objects were left out so.
int run_vertex_stage(SimdTarget simd, const SceneGeometry& geometry, const ViewTransform& xf, const Viewport& vp,
                      const AttrNeeds& needs, const ShadeConstants& shade, ProjectedVertices& out,
                      AttrArrays& attrs);

}  // namespace fastshade
