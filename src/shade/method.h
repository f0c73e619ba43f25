// The method registry: a shading method is a name, what it needs from the front end, and the
// function that draws one binned triangle into a tile. New kernels join here; the pipeline
// never names a method.
#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "core/simd_target.h"
#include "frame/frame.h"
#include "frame/method_needs.h"
#include "fastshade/options.h"
#include "raster/spans.h"

namespace fastshade {

// One tile's scratch: colour packed as R | G << 8 | B << 16 | 0xFF << 24, and float depth.
// Rows are `stride` pixels; (x_origin, y_origin) is the image position of element 0. The
// buffers carry limits::kScratchPadPx pixels of slack (shade/shade_limits.h).
struct TileTarget;
struct PixelQueue;
using DrawTriangleFn = void (*)(const Frame& frame, uint32_t entry, const TileTarget& target);

struct TileTarget {
  uint32_t* color;
  float* depth;
  int stride;
  int x_origin, y_origin;
  PixelRect rect;  // tile ∩ image
  // Classifying methods: the draw function of each shading path, and the alpha byte's tag
  // (XORed into 0xFF: a pixel drawn on path p keeps alpha p, for the per-path pixel counts).
  const DrawTriangleFn* path_draw = nullptr;
  uint32_t alpha_xor = 0;
  // The worker's queue of pixels waiting to be lit (shade/pixel_queue.h), lit before the tile
  // is written out; null where a caller provides none (a draw then stores every pixel at once).
  PixelQueue* pending = nullptr;
};
inline constexpr uint32_t path_alpha_xor(ShadePath p) { return (0xFFu ^ static_cast<uint32_t>(p)) << 24; }

// What a method draws a tile with: `any` for every triangle; a classifying method also names
// each path's function, and a tile whose triangles all take one path runs that one directly.
struct TileDraw {
  DrawTriangleFn any = nullptr;
  DrawTriangleFn path[kShadePathCount] = {};
};

struct Method {
  ShadingMethod id;  // its spelling: option_name(id)
  std::string_view summary;
  AttrNeeds (*needs)(const ShadeConstants& shade);
  // Chooses the variant for this frame (ISA, viewer, sRGB...): decided once, outside loops.
  TileDraw (*select)(SimdTarget simd, const ShadeConstants& shade, const RenderOptions& options);
  // Why these options make no sense with this method ("--brdf: ..."), or "" if they do.
  std::string (*refuse)(const RenderOptions& options);
  // Whether the front end classifies triangles into shading paths for this method (and the
  // classifier's options apply).
  bool classifies;
  // Whether --gouraud sierpinski applies: set-up splits large triangles into subtriangles whose
  // vertices are lit, which only a method lighting vertices alone can use.
  bool lights_subtriangles;
  // Which triangles the front end gives a hybrid segment length (frame/method_needs.h).
  SegmentSteps (*segment_steps)(const RenderOptions& options);
};

std::span<const Method> all_methods();
const Method& find_method(ShadingMethod id);  // every ShadingMethod has one

// Packs a colour the way the kernels do (for scalar paths and background fills).
inline uint32_t pack_rgba(uint8_t r, uint8_t g, uint8_t b) {
  return uint32_t(r) | uint32_t(g) << 8 | uint32_t(b) << 16 | 0xFF000000u;
}

}  // namespace fastshade
