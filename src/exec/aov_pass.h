// The AOVs of a tile (include/fastshade/image.h AovSet), written after its colour from the
// tile's final depths: which triangle each pixel shows, then its depth, normal and ids.
// Nothing of it runs in a frame that asks for no AOV.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/mat3x3.hpp>

#include "fastshade/image.h"
#include "frame/frame.h"
#include "raster/spans.h"

namespace fastshade {

// What the pass needs of the frame beyond the contract, set once per frame.
struct AovFrame {
  AovSet which;
  AovImages* out = nullptr;         // sized to the frame, `which` present
  glm::dmat3 view_to_world{1.0};    // the camera's rotation: view-space normals to world space
  // Per object, the index of its first triangle in the flattened scene (ascending): a
  // triangle's object and its index in that object's mesh.
  std::vector<uint32_t> object_first_triangle;
};

// Tile `rect`'s AOVs into frame.out. `tile_depth` holds the tile's final depths (stride
// `stride_px`, 1.0 where nothing drew), the tile's triangles are bin_entries[begin, end);
// `entry_scratch` holds stride_px rows of the tile.
void write_tile_aovs(const Frame& frame, const AovFrame& aov, uint32_t begin, uint32_t end, const PixelRect& rect,
                     const float* tile_depth, int stride_px, uint32_t* entry_scratch);

// An empty tile's AOVs: 0 depth and normal, -1 ids.
void write_empty_aovs(const AovFrame& aov, const PixelRect& rect);

}  // namespace fastshade
