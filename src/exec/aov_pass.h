// The AOVs of a tile (include/fastshade/image.h AovSet), written after its colour from the
// tile's final depths: which triangle each pixel shows, then its depth, normal and ids.
// Nothing of it runs in a frame that asks for no AOV.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

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

// AovTileScratch::entries of a pixel no triangle shows.
inline constexpr uint32_t kAovNoEntry = 0xFFFFFFFFu;

// What the pass derives once per shown triangle, reused across its pixels: 1/w and the
// normal (rotated to world space, weighted by each vertex's 1/w: perspective-correct) as
// screen-space planes, from the exact barycentrics of raster/planes.h, in double.
struct AovTriangle {
  bool set_up = false;
  int ax = 0, ay = 0;  // the planes' anchor pixel
  double inv_w[3];     // at the anchor, per pixel in x, per pixel in y
  glm::dvec3 n_world[3];
  int32_t object = -1, triangle = -1;
};

// One worker's tile-sized scratch: the tile's AOVs are made here, in cache, and streamed to
// the frame's arrays a row at a time (exec/tile_io.h stream_rows), as the colour is. Written
// in place, the arrays' cache lines were read before being written: at 3840x2160, 200 MB of
// AOVs took 41 ms a frame more than the colour alone (spot_4k, 2 threads), where streaming
// 200 MB takes 6 ms on the same machine.
struct AovTileScratch {
  std::vector<uint32_t> entries;  // per pixel: the tile's triangle it shows, from the tile's first
  std::vector<AovTriangle> shown;  // per triangle of the tile, set up when a pixel shows it
  std::vector<float> depth, normal;
  std::vector<int32_t> triangle_id, object_id;
  void size_for(int tile_px);
};

// Tile `rect`'s AOVs into aov.out. `tile_depth` holds the tile's final depths (stride
// `stride_px`, 1.0 where nothing drew); the tile's triangles are bin_entries[begin, end).
void write_tile_aovs(const Frame& frame, const AovFrame& aov, uint32_t begin, uint32_t end, const PixelRect& rect,
                     const float* tile_depth, int stride_px, AovTileScratch& scratch);

// An empty tile's AOVs: 0 depth and normal, -1 ids.
void write_empty_aovs(const Frame& frame, const AovFrame& aov, const PixelRect& rect);

}  // namespace fastshade
