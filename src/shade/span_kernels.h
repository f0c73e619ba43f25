// The span kernels as plain functions over plain data, so each SIMD kernel can be tested
// against its scalar reference: what a kernel reads is set up once per triangle (raster/
// planes.h), and a call shades one row span [x0, x1] of it into a tile row.
#pragma once
#include <algorithm>
#include <cstdint>

#include "core/simd_target.h"
#include "frame/shade_constants.h"
#include "raster/planes.h"
#include "frame/shade_constants.h"

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

// Phong's colour at one pixel before quantisation (the scalar twin of PhongColor in phong-inl).
struct PhongColor {
  float c[3];
};
// split_light >= 0 (hybrid's split light, classify/segment_step.h): that light's diffuse term is
// left out and its unclamped N.L written to *split_n_dot_l. specular = false: no specular term
// (the SIMD kSpecular = false; x + 0 gives x's bits).
PhongColor phong_color_scalar(const PhongSpanInput& in, const PixelOffsets& o, int split_light = -1,
                              float* split_n_dot_l = nullptr, bool specular = true);
// The same for a given unit normal (the --normals paths).
PhongColor phong_color_from_normal_scalar(const PhongSpanInput& in, float nx, float ny, float nz,
                                          const PixelOffsets& o, int split_light = -1,
                                          float* split_n_dot_l = nullptr, bool specular = true);

// Scalar references: per pixel, the same float operations as the SIMD kernels.
void gouraud_span_scalar(const GouraudSpanInput& in, bool srgb, int py, int x0, int x1, RowTarget row);
void phong_span_scalar(const PhongSpanInput& in, int py, int x0, int x1, RowTarget row);
// [xl, xr]: the row's whole covered run in the triangle; [x0, x1]: the part to shade.
struct HybridRun {
  int step;  // segment length for the triangle (classify/segment_step.h), 1 = per-pixel Phong
  int xl, xr;
  int split_light = -1;  // the light whose N.L is interpolated unclamped (SegmentPlan)
  bool specular = true;  // false: the ends leave the specular term out (SegmentPlan)
};
void hybrid_span_scalar(const PhongSpanInput& in, const HybridRun& run, int py, int x0, int x1, RowTarget row);

// The SIMD kernels on the ISA `simd` (core/simd_target.h), for tests and benchmarks.
void gouraud_span(SimdTarget simd, const GouraudSpanInput& in, bool srgb, int py, int x0, int x1, RowTarget row);
void phong_span(SimdTarget simd, const PhongSpanInput& in, int py, int x0, int x1, RowTarget row);
void hybrid_span(SimdTarget simd, const PhongSpanInput& in, const HybridRun& run, int py, int x0, int x1, RowTarget row);

// --normals adaptive | equal-angle (shade/normal_blocks.h); run.step is unused.
void normals_span_scalar(const PhongSpanInput& in, SpanNormals mode, float tol, const HybridRun& run,
                         int py, int x0, int x1, RowTarget row);
void normals_span(SimdTarget simd, const PhongSpanInput& in, SpanNormals mode, float tol, const HybridRun& run, int py,
                  int x0, int x1, RowTarget row);

// quantize() (light/lighting.h) as the SIMD kernels compute it: the same float operations,
// with the kernels' exp2/log2 for the sRGB curve.
uint8_t quantize_like_simd(float v, bool srgb);

}  // namespace fastshade
