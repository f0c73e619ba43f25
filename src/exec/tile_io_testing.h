// For tests only: the scalar twins of the tile I/O kernels (exec/tile_io.h), the same
// results byte for byte.
#pragma once
#include <cstdint>

#include "exec/tile_io.h"

namespace fastshade {

void rgba_rows_to_rgb_scalar(const uint32_t* src, int src_stride_px, uint8_t* dst,
                             int dst_stride_bytes, int width, int rows);
void clear_tile_scalar(uint32_t* color, float* depth, int stride_px, uint32_t background, int width,
                       int rows);
TilePixelCounts count_tile_pixels_scalar(const float* depth, const uint32_t* color, int stride_px,
                                         int width, int rows, bool by_path);

}  // namespace fastshade
