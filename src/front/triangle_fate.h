// Front end: what triangle setup decides about each triangle of snapped vertices before it
// builds a record: dropped (zero area), culled (a back face under "cull": "back", a box holding
// no pixel centre, or one candidate centre the triangle misses), or kept with its facing and
// its pixel-centre box. decide_triangle() is the definition; decide_triangles() makes the same
// decisions for a block of triangles at once in SIMD lanes (a dense mesh's setup spent most of
// its time in these branches, one triangle at a time; dfc1bbd).
#pragma once
#include <cstdint>

#include "core/simd_target.h"
#include "front/projection.h"

namespace fastshade {

enum class TriangleFate : uint8_t { kDropped, kCulled, kFront, kBack };

// Pixel centres px + 0.5 inside the fixed-point bounding box, clamped to the image, inclusive.
struct PixelBox {
  int32_t x0, y0, x1, y1;
};

struct TriangleDecision {
  TriangleFate fate;
  PixelBox box;  // meaningful for kept triangles
};

// Vertices in input order; GL's front face is counter-clockwise with y up.
TriangleDecision decide_triangle(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c,
                                 int width, int height, bool cull_back);

// A block of triangles as columns: x_fx[v][i], y_fx[v][i] is vertex v of triangle i.
inline constexpr int kFateBlock = 256;  // triangle setup's plan block (front/triangle_setup.cpp)
inline constexpr int kFatePad = 16;     // room for a whole vector past the last triangle
struct TriangleColumns {
  alignas(64) int32_t x_fx[3][kFateBlock + kFatePad];
  alignas(64) int32_t y_fx[3][kFateBlock + kFatePad];
};

// The block's decisions: bit i of kept (back) set if triangle i is kept (and back-facing);
// boxes are written for every triangle, meaningful where kept.
struct TriangleFates {
  uint64_t kept[kFateBlock / 64], back[kFateBlock / 64];
  int dropped, culled;
  alignas(64) int32_t x0[kFateBlock + kFatePad], y0[kFateBlock + kFatePad];
  alignas(64) int32_t x1[kFateBlock + kFatePad], y1[kFateBlock + kFatePad];
};

// Triangles 0..count-1 (count <= kFateBlock) on the chosen ISA; decide_triangles_scalar() is
// its reference, decide_triangle() per triangle.
void decide_triangles(SimdTarget simd, const TriangleColumns& in, int count, int width, int height, bool cull_back,
                      TriangleFates& out);
void decide_triangles_scalar(const TriangleColumns& in, int count, int width, int height, bool cull_back,
                             TriangleFates& out);

}  // namespace fastshade
