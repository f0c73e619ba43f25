// Sutherland-Hodgman clipping of a triangle in homogeneous clip space, carrying attributes.
#pragma once
#include <cstdint>

#include <glm/vec4.hpp>

#include "frame/frame.h"

namespace fastshade {

// A polygon vertex: its clip position, and either a source vertex (index into the frame's
// attribute table) or attributes made by interpolation.
struct ClipVertex {
  glm::vec4 pos_clip;
  VertexAttrs attrs;
  uint32_t source;  // kNewVertex when `attrs` holds interpolated data
};
inline constexpr uint32_t kNewVertex = 0xFFFFFFFFu;

// Clip planes as dot(plane, pos_clip) >= 0. Near/far are GL's z >= -w, z <= w; the guard band
// planes keep |x/w| <= gx and |y/w| <= gy so snapped coordinates fit limits::kGuardPx.
struct ClipPlanes {
  glm::vec4 plane[6];
  int count = 0;
};
ClipPlanes guard_band_planes(float gx, float gy);

// Clips in place; returns the vertex count of the result (0 if nothing is left). A triangle
// clipped by p planes has at most 3 + p vertices.
inline constexpr int kMaxClipVertices = 9;
int clip_polygon(ClipVertex* poly, int count, const ClipPlanes& planes, bool with_attrs,
                 const AttrArrays& source_attrs);

}  // namespace fastshade
