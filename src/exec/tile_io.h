// Moving pixels between tiles and the framebuffer: the part of a frame that grows with the
// image, not the scene (at 3840x2160 it was most of a shading-dominated frame).
#pragma once
#include <cstdint>

namespace fastshade {

// Packed RGBA8 tile rows to RGB8 framebuffer rows (alpha dropped). SIMD on the chosen ISA.
void rgba_rows_to_rgb(const uint32_t* src, int src_stride_px, uint8_t* dst, int dst_stride_bytes,
                      int width, int rows);
// The scalar reference.
void rgba_rows_to_rgb_scalar(const uint32_t* src, int src_stride_px, uint8_t* dst,
                             int dst_stride_bytes, int width, int rows);

}  // namespace fastshade
