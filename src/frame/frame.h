// The one contract between the front end (producer: front/) and the back end (consumer:
// exec/, raster/, shade/): what a frame's setup and binning leave for the tile workers.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "core/limits.h"
#include "core/simd_target.h"
#include "frame/shade_constants.h"
#include "frame/shade_path.h"

namespace fastshade {

// Per-vertex data the shading methods interpolate, in view space, one array per quantity.
// An array is filled only if the frame's method reads it (shade/method.h): phong with an
// infinite viewer moves 12 bytes a vertex, not 36.
struct AttrArrays {
  std::vector<glm::vec3> n_view;    // unit normal
  std::vector<glm::vec3> color;     // lit vertex colour in [0,1] (Gouraud)
  std::vector<glm::vec3> pos_view;  // position (local viewer)
  void clear() {
    n_view.clear();
    color.clear();
    pos_view.clear();
  }
};
using AttrField = std::vector<glm::vec3> AttrArrays::*;

// One vertex's attributes as values: what clipping interpolates.
struct VertexAttrs {
  glm::vec3 n_view{0.0f}, color{0.0f}, pos_view{0.0f};
};

// A triangle after clipping, projection and snapping, wound so that its doubled area is
// positive: edge functions are >= 0 inside. Everything the rasterizer needs, nothing more.
struct SetupTriangle {
  int32_t x_fx[3], y_fx[3];  // screen position, fixed point (kSubpixelBits), y down
  float depth[3];            // window depth in [0, 1]
  float inv_w[3];            // 1 / clip w, for perspective-correct attributes
  uint32_t attr[3];          // attribute index; kClippedAttr marks the chunk's own arrays
  // Pixel-centre bounding box, inclusive, inside the image; for a whole (unsplit) triangle
  // px_min is also its planes' anchor (raster/planes.h barycentrics).
  int16_t px_min[2], px_max[2];
  uint16_t material;
  uint16_t flags;            // kBackFacing
};
inline constexpr uint32_t kClippedAttr = 0x80000000u;
// Chunk::only_tile of a triangle binned to any number of tiles but one.
inline constexpr uint32_t kSeveralTiles = 0xFFFFFFFFu;
inline constexpr uint16_t kBackFacing = 1;
// Bits 1-3: which Sierpinski part of its triangle this record covers (0: the whole triangle;
// frame/edge_function.h). The record keeps the parent's vertices: attributes are the parent's.
inline constexpr int kSierpinskiShift = 1;
// Bits 4-5: the shading path the classifier chose (frame/shade_path.h); 0 when the frame's
// method does not classify.
inline constexpr int kShadePathShift = 4;
inline constexpr uint16_t kShadePathMask = 3 << kShadePathShift;
// Bits 6-8: log2 of the triangle's hybrid segment length in pixels (classify/segment_step.h),
// decided once by the front end where the frame draws hybrid segments; 0 (per-pixel Phong)
// elsewhere.
inline constexpr int kSegmentStepShift = 6;
inline constexpr uint16_t kSegmentStepMask = 7 << kSegmentStepShift;
// Bits 9-13: 1 + the light whose N.L hybrid interpolates unclamped and clamps per pixel (the
// terminator's kink, classify/segment_step.h); 0 when no light's is. Five bits: lights 0-30.
inline constexpr int kSplitLightShift = 9;
inline constexpr uint16_t kSplitLightMask = 31 << kSplitLightShift;
inline constexpr int kMaxSplitLight = 30;
// Bit 14: hybrid's segment ends leave the specular term out (SegmentPlan::specular false).
inline constexpr uint16_t kSegmentNoSpecular = 1 << 14;
static_assert(kMaxImageSide <= 32767, "pixel bounding boxes are int16");

// One chunk of the front end's work: the triangles it set up (in draw order) and the vertex
// attributes that clipping made.
struct Chunk {
  std::vector<SetupTriangle> triangles;
  // Per record, its input triangle (index in the scene's flattened triangles), only in frames
  // that write triangle or object ids (include/fastshade/image.h AovSet): the records of a
  // clipped or split triangle share it.
  std::vector<uint32_t> sources;
  AttrArrays clipped;  // attributes of vertices that clipping made
  uint32_t clipped_count = 0;
  std::vector<uint32_t> tile_counts;  // per tile: how many of this chunk's triangles it holds
  std::vector<uint32_t> only_tile;    // per triangle: its one tile, or kSeveralTiles
  std::vector<uint8_t> tile_paths;    // per tile: bit p set if a triangle takes path p (classified frames)
  long long dropped = 0, culled = 0;
  long long hidden = 0;               // of culled: back faces their own mesh hides (front/self_occlusion.h)
  PathTally paths;                    // what the classifier decided for this chunk's triangles
  std::vector<uint32_t> segment_pending;  // triangles whose hybrid segment length is still to decide
};

// Bin entries name a triangle as (chunk, index in chunk). Clipping one input triangle makes at
// most 7 (a 9-gon fanned) and a Sierpinski split 4 of each, so 17 bits of index hold a chunk
// of 4096 inputs; 15 bits of chunk allow 134 M input triangles.
inline constexpr int kBinIndexBits = 17;
static_assert((limits::kTrianglesPerChunk * 7 * 4) < (1 << kBinIndexBits));
inline constexpr uint32_t bin_entry(uint32_t chunk, uint32_t index) {
  return (chunk << kBinIndexBits) | index;
}

struct TileGrid {
  int width = 0, height = 0;  // image, pixels
  int tile_px = 0;            // set with the image (exec/renderer.cpp)
  int tile_shift = 0;         // log2(tile_px)
  int tiles_x = 0, tiles_y = 0;
  int tile_count() const { return tiles_x * tiles_y; }
};

struct Frame {
  SimdTarget simd;                     // the renderer's ISA, for every SIMD entry point
  TileGrid grid;
  ShadeConstants shade;                // lights in view space, materials, background
  AttrArrays attrs;                    // every object's vertices, concatenated
  std::vector<Chunk> chunks;           // in draw order
  // Binning result: tile t's triangles are bin_entries[tile_begin[t] .. tile_begin[t+1]),
  // chunk by chunk and in draw order within a chunk.
  std::vector<uint32_t> tile_begin;
  std::vector<uint32_t> bin_entries;
  // Per tile, bit p set if one of its triangles takes shading path p: a tile with one path
  // runs that path's loop alone. Empty unless the method classifies.
  std::vector<uint8_t> tile_paths;

  static ShadePath path_of(const SetupTriangle& t) {
    return static_cast<ShadePath>((t.flags & kShadePathMask) >> kShadePathShift);
  }
  static int segment_step_px(const SetupTriangle& t) {
    return 1 << ((t.flags & kSegmentStepMask) >> kSegmentStepShift);
  }
  static bool segment_specular(const SetupTriangle& t) { return !(t.flags & kSegmentNoSpecular); }
  static int split_light(const SetupTriangle& t) {  // -1: none
    return ((t.flags & kSplitLightMask) >> kSplitLightShift) - 1;
  }
  const SetupTriangle& triangle(uint32_t entry) const {
    return chunks[entry >> kBinIndexBits].triangles[entry & ((1u << kBinIndexBits) - 1)];
  }
  // One attribute of one of the triangle's vertices: (frame.*field) for mesh vertices, the
  // chunk's for vertices made by clipping.
  const glm::vec3& vertex(uint32_t entry, uint32_t attr, AttrField field) const {
    const AttrArrays& arrays = (attr & kClippedAttr) ? chunks[entry >> kBinIndexBits].clipped : attrs;
    return (arrays.*field)[attr & ~kClippedAttr];
  }
};

}  // namespace fastshade
