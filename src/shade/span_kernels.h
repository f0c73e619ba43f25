// The span kernels as plain functions over plain data, so each SIMD kernel can be tested
// against its scalar reference: what a kernel reads is set up once per triangle (raster/
// planes.h), and a call shades one row span [x0, x1] of it into a tile row.
#pragma once
#include <cstdint>

#include "frame/shade_constants.h"
#include "raster/planes.h"
#include "shade/normal_blocks_mode.h"

namespace fastshade {

// One row of a tile's scratch, indexed by absolute pixel x (the pointers are pre-offset).
struct RowTarget {
  float* depth;
  uint32_t* color;
  uint32_t alpha_xor = 0;  // XORed into every stored pixel: tags a classified path's pixels
};

struct GouraudSpanInput {
  Barycentrics bary;
  Plane depth;
  Plane c_over_w[3];  // vertex colour / w
  Plane inv_w;
};

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
PhongColor phong_color_scalar(const PhongSpanInput& in, const PixelOffsets& o);
// The same for a given unit normal (the --normals paths).
PhongColor phong_color_from_normal_scalar(const PhongSpanInput& in, float nx, float ny, float nz,
                                          const PixelOffsets& o);

// Scalar references: per pixel, the same float operations as the SIMD kernels.
void gouraud_span_scalar(const GouraudSpanInput& in, bool srgb, int py, int x0, int x1, RowTarget row);
void phong_span_scalar(const PhongSpanInput& in, int py, int x0, int x1, RowTarget row);
// [xl, xr]: the row's whole covered run in the triangle; [x0, x1]: the part to shade.
struct HybridRun {
  int step;  // segment length for the triangle (shade/hybrid.h), 1 = per-pixel Phong
  int xl, xr;
};
void hybrid_span_scalar(const PhongSpanInput& in, const HybridRun& run, int py, int x0, int x1, RowTarget row);

// The SIMD kernels on the process's ISA (exec/isa.h), for tests and benchmarks.
void gouraud_span(const GouraudSpanInput& in, bool srgb, int py, int x0, int x1, RowTarget row);
void phong_span(const PhongSpanInput& in, int py, int x0, int x1, RowTarget row);
void hybrid_span(const PhongSpanInput& in, const HybridRun& run, int py, int x0, int x1, RowTarget row);

// --normals adaptive | equal-angle (shade/normal_blocks.h); run.step is unused.
void normals_span_scalar(const PhongSpanInput& in, SpanNormals mode, float tol, const HybridRun& run,
                         int py, int x0, int x1, RowTarget row);
void normals_span(const PhongSpanInput& in, SpanNormals mode, float tol, const HybridRun& run, int py,
                  int x0, int x1, RowTarget row);

// quantize() (shade/lighting.h) as the SIMD kernels compute it: the same float operations,
// with the kernels' exp2/log2 for the sRGB curve.
uint8_t quantize_like_simd(float v, bool srgb);

}  // namespace fastshade
