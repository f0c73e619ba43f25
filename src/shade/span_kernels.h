// The span kernels' plain data, so each SIMD kernel can be tested against its scalar twin
// (shade/span_kernels_testing.h): what a kernel reads is set up once per triangle (raster/
// planes.h), and a call shades one row span [x0, x1] of it into a tile row.
#pragma once
#include <algorithm>
#include <cstdint>

#include "frame/shade_constants.h"
#include "raster/planes.h"

namespace fastshade {

// One row of a tile's scratch, indexed by absolute pixel x (the pointers are pre-offset).
struct RowTarget {
  float* depth;
  uint32_t* color;
  uint32_t alpha_xor = 0;  // XORed into every stored pixel: tags a classified path's pixels
};

// Gouraud interpolates 255 x colour, so its quotient by 1/w is the output level before
// rounding: no multiply by 255 per pixel. The quotient is clamped once, to the range of the
// vertex levels, instead of clamping each plane to its vertex values: a perspective-correct
// colour is a convex combination of the vertex colours, so this range holds every correct
// value (and bounds a sliver's imprecise planes more tightly than clamping numerator and
// denominator apart did), and it is also the [0, 255] clamp of quantisation.
struct GouraudSpanInput {
  Barycentrics bary;
  Plane depth;
  Plane level_over_w[3];          // 255 x vertex colour / w, per channel (lo, hi unused)
  Plane inv_w;
  float level_lo[3], level_hi[3];  // 255 x the vertex colours' range, within [0, 255]
};
// The level bounds from the vertex colours; inline, so each kernel target compiles it with its
// own instructions.
FASTSHADE_FORCE_INLINE void set_gouraud_levels(GouraudSpanInput& in, const glm::vec3 color[3]) {
  for (int c = 0; c < 3; ++c) {
    // Pairwise min and max, not std::minmax or std::clamp: those branch, and mispredict.
    const float lo = std::min(std::min(color[0][c], color[1][c]), color[2][c]);
    const float hi = std::max(std::max(color[0][c], color[1][c]), color[2][c]);
    in.level_lo[c] = 255.0f * std::min(std::max(lo, 0.0f), 1.0f);
    in.level_hi[c] = 255.0f * std::min(std::max(hi, 0.0f), 1.0f);
  }
}
// The level planes and bounds from the vertex colours and 1/w (in.bary and in.depth are left
// alone: the frame's kernels take them from the triangle). The planes in scalar doubles: the
// kernel sets up the same bits with PlanesOverW (shade/planes_over_w-inl.h).
FASTSHADE_FORCE_INLINE void set_gouraud_colors(GouraudSpanInput& in, const Barycentrics& bary, const glm::vec3 color[3],
                                               const float inv_w[3]) {
  for (int c = 0; c < 3; ++c)
    in.level_over_w[c] = make_plane(bary, 255.0 * color[0][c] * inv_w[0], 255.0 * color[1][c] * inv_w[1],
                                    255.0 * color[2][c] * inv_w[2]);
  in.inv_w = make_plane(bary, inv_w[0], inv_w[1], inv_w[2]);
  set_gouraud_levels(in, color);
}

struct PhongSpanInput {
  Barycentrics bary;
  Plane depth;
  Plane n[3];      // vertex normal / w
  Plane p[3];      // vertex position / w (local viewer only)
  Plane inv_w;     // (local viewer only)
  const MaterialConstants* material;
  const ShadeConstants* shade;  // lights, ambient, viewer, sRGB
};

// [xl, xr]: the row's whole covered run in the triangle; [x0, x1]: the part to shade.
struct HybridRun {
  int step;  // segment length for the triangle (classify/segment_step.h), 1 = per-pixel Phong
  int xl, xr;
  int split_light = -1;  // the light whose N.L is interpolated unclamped (SegmentPlan)
  bool specular = true;  // false: the ends leave the specular term out (SegmentPlan)
};

}  // namespace fastshade
