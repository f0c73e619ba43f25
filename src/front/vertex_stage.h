// Front end, first stage: every vertex to clip space, plus the view-space attributes the
// frame's shading method interpolates.
#pragma once
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "frame/frame.h"
#include "front/scene_geometry.h"

namespace fastshade {

struct AttrNeeds {  // which VertexAttrs fields a method reads (shade/method.h decides)
  bool normal = false, color = false, position = false;
};

struct ViewTransform {
  glm::mat4 view{1.0f}, proj{1.0f};
};

ViewTransform view_transform(const Scene& scene);

// Parallel over vertices. `clip_pos` and `attrs` are resized; their capacity is reused.
void run_vertex_stage(const SceneGeometry& geometry, const ViewTransform& xf, const AttrNeeds& needs,
                      const ShadeConstants& shade, std::vector<glm::vec4>& clip_pos,
                      std::vector<VertexAttrs>& attrs);

// Lights to view space and the infinite viewer's half vectors; materials as constants.
ShadeConstants shade_constants(const Scene& scene, const ViewTransform& xf, bool srgb);

}  // namespace fastshade
