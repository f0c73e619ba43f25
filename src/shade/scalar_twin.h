// What the span kernels' scalar twins share (each twin sits beside its SIMD kernel): the depth
// test, quantisation as the lanes do it, and the row loop of a lit span. Their per-pixel colour,
// the twin of shade/phong_color-inl.h, is in shade/phong_color_scalar.cpp.
#pragma once
#include <cstdint>

#include "shade/method.h"
#include "shade/span_kernels_testing.h"

namespace fastshade {

// Depth test and write for one pixel; true if it passes.
inline bool depth_pass(const Plane& depth_plane, const PixelOffsets& o, float& depth) {
  const float z = plane_at(depth_plane, o);
  if (!(z < depth)) return false;
  depth = z;
  return true;
}

inline uint32_t pack_quantized(const PhongColor& rgb, bool srgb) {
  return pack_rgba(quantize_like_simd(rgb.c[0], srgb), quantize_like_simd(rgb.c[1], srgb),
                   quantize_like_simd(rgb.c[2], srgb));
}

// The interpolated normal (n/w, any length) normalised as the kernels' Normalize does, then lit.
PhongColor phong_color_from_plane_normal_scalar(const PhongSpanInput& in, float nx, float ny, float nz,
                                                const PixelOffsets& o, int split_light = -1,
                                                float* split_n_dot_l = nullptr, bool specular = true);

// Depth test, colour(offsets) and quantisation of every pixel of a row span.
template <typename ColorFn>
void lit_span_scalar(const PhongSpanInput& in, int py, int x0, int x1, RowTarget row, ColorFn&& color) {
  const bool srgb = in.shade->srgb;
  for (int px = x0; px <= x1; ++px) {
    const PixelOffsets o = pixel_offsets(in.bary, px, py);
    if (!depth_pass(in.depth, o, row.depth[px])) continue;
    row.color[px] = pack_quantized(color(o), srgb);
  }
}

}  // namespace fastshade
