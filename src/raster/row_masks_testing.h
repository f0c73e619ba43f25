// The SIMD coverage kernels (raster/row_masks-inl.h) on the ISA `simd`, for tests: the
// kernels inline the per-target versions.
#pragma once
#include <cstdint>

#include "core/simd_target.h"
#include "raster/spans.h"

namespace fastshade {

// bits[r]: covered columns of row rect.y0 + r (bit k: column rect.x0 + k); returns how many
// pixels are covered. rect must be narrower than kNarrowRectPx.
int row_masks(SimdTarget simd, const TriangleEdges& te, const PixelRect& rect, uint32_t* bits);
// The same from BoxCovered (one vector for the whole rectangle); -1 if the rectangle does
// not fit the ISA's vector. The triangle must pass box_lanes_exact.
int box_masks(SimdTarget simd, const TriangleEdges& te, const PixelRect& rect, uint32_t* bits);

}  // namespace fastshade
