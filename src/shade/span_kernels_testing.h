// For tests and benchmarks only: each span kernel on an ISA of the caller's choice
// (core/simd_target.h), and its scalar twin (beside its kernel: gouraud.cpp, phong.cpp,
// hybrid.cpp, phong_normals.cpp, diffuse_quotient.cpp; the per-pixel colour in
// phong_color_scalar.cpp), which runs the same float operations per pixel. The frame never
// calls these: its kernels are chosen once per frame by the method registry (shade/method.h).
#pragma once
#include <cstdint>

#include "core/simd_target.h"
#include "shade/diffuse_quotient.h"
#include "shade/pixel_queue.h"
#include "shade/span_kernels.h"

namespace fastshade {

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
void hybrid_span_scalar(const PhongSpanInput& in, const HybridRun& run, int py, int x0, int x1, RowTarget row);

// The SIMD kernels on the ISA `simd` (core/simd_target.h), for tests and benchmarks.
void gouraud_span(SimdTarget simd, const GouraudSpanInput& in, bool srgb, int py, int x0, int x1, RowTarget row);
void phong_span(SimdTarget simd, const PhongSpanInput& in, int py, int x0, int x1, RowTarget row);
void hybrid_span(SimdTarget simd, const PhongSpanInput& in, const HybridRun& run, int py, int x0, int x1, RowTarget row);

// --normals adaptive | equal-angle (shade/normal_blocks.h); run.step is unused.
void normals_span_scalar(const PhongSpanInput& in, PhongNormals mode, float tol, const HybridRun& run,
                         int py, int x0, int x1, RowTarget row);
void normals_span(SimdTarget simd, const PhongSpanInput& in, PhongNormals mode, float tol, const HybridRun& run, int py,
                  int x0, int x1, RowTarget row);

// quantize() (light/lighting.h) as the SIMD kernels compute it: the same float operations,
// with the kernels' exp2/log2 for the sRGB curve.
uint8_t quantize_like_simd(float v, bool srgb);

// The diffuse colour at one pixel before quantisation: the scalar twin of DiffuseQuotientColor
// (shade/diffuse_quotient-inl.h), the same float operations in the same order.
PhongColor diffuse_quotient_color_scalar(const PhongSpanInput& in, const DiffuseQuotient& dq,
                                         const PixelOffsets& o);

// A row span shaded with the quotient: scalar reference and the SIMD kernel on the ISA `simd`.
void diffuse_quotient_span_scalar(const PhongSpanInput& in, const DiffuseQuotient& dq, int py, int x0,
                                  int x1, RowTarget row);
void diffuse_quotient_span(SimdTarget simd, const PhongSpanInput& in, const DiffuseQuotient& dq, int py, int x0, int x1,
                           RowTarget row);

// The kernel on the ISA `simd`, and its scalar reference (the same float operations per
// entry, lighting all of them), for tests.
void light_pixel_queue(SimdTarget simd, PixelQueue& queue, const TileTarget& target, bool all);
void light_pixel_queue_scalar(PixelQueue& queue, const TileTarget& target);

}  // namespace fastshade
