// Moving pixels between tiles and the framebuffer: the part of a frame that grows with the
// image, not the scene (at 3840x2160 it was most of a shading-dominated frame).
#pragma once
#include <cstdint>

#include "core/simd_target.h"
#include "frame/shade_path.h"

namespace fastshade {

// Rows of bytes into the framebuffer (src_stride_bytes 0: the same row every time), whole
// cache lines with non-temporal stores and the partial lines at a row's ends with ordinary
// ones: what an empty tile writes.
void stream_rows(SimdTarget simd, const uint8_t* src, int src_stride_bytes, uint8_t* dst, int dst_stride_bytes,
                 int row_bytes, int rows);
// Packed RGBA8 tile rows to RGB8 framebuffer rows (alpha dropped). SIMD on the chosen ISA,
// stored as stream_rows() does.
void rgba_rows_to_rgb(SimdTarget simd, const uint32_t* src, int src_stride_px, uint8_t* dst, int dst_stride_bytes,
                      int width, int rows);

// A tile's scratch before its triangles: the background colour at the cleared depth 1.0, rows
// of `width` pixels `stride_px` apart. SIMD on the chosen ISA: the baseline build's std::fill_n
// of both arrays took 1.2 instructions a pixel, 3 % of a 4K gouraud frame's back end.
void clear_tile(SimdTarget simd, uint32_t* color, float* depth, int stride_px, uint32_t background, int width, int rows);
// What a finished tile holds: pixels drawn (depth below the cleared 1.0) and, where `by_path`,
// how many of them each shading path drew (the alpha byte carries path p as p; untagged pixels
// keep 0xFF). At 4K the scalar loop was a sixth of a classified frame's back end.
struct TilePixelCounts {
  long long covered = 0;
  long long path[kShadePathCount] = {};
};
TilePixelCounts count_tile_pixels(SimdTarget simd, const float* depth, const uint32_t* color, int stride_px, int width,
                                  int rows, bool by_path);

}  // namespace fastshade
