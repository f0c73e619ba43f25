// Front end, second stage: one chunk of triangles clipped, projected, snapped to fixed point,
// culled and wound for the rasterizer.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/vec4.hpp>

#include "fastshade/scene.h"
#include "frame/frame.h"
#include "front/clip.h"
#include "front/scene_geometry.h"

namespace fastshade {

struct SetupParams {
  TileGrid grid;
  ClipPlanes planes;    // near, far and guard band
  float guard_x = 1, guard_y = 1;  // |x/w|, |y/w| a vertex may reach without clipping
  Cull cull = Cull::None;
  bool with_attrs = false;  // clipping interpolates attributes only if the method reads them
};

SetupParams setup_params(const TileGrid& grid, Cull cull, bool with_attrs);

// Triangles [first, last) of the scene into `chunk` (cleared first, capacity kept).
void setup_chunk(const SceneGeometry& geometry, const std::vector<glm::vec4>& clip_pos,
                 const std::vector<VertexAttrs>& attrs, uint32_t first, uint32_t last,
                 const SetupParams& params, Chunk& chunk);

}  // namespace fastshade
