// The shading kernels' tuning constants, with the reasoning that bounds each (the pipeline's
// shared limits are in core/limits.h).
#pragma once

namespace fastshade::limits {

// A tile's colour and depth scratch carries this many pixels of slack past its last row, so a
// vector may read and blend lanes past a row's end (shade/span_loop-inl.h): at least the widest
// vector's 16 lanes; 64 keeps both arrays whole cache lines longer.
inline constexpr int kScratchPadPx = 64;

// Boxes up to this many pixels are tested whole before coverage: a dense mesh's triangles are
// boxes of 1-9 pixels, and the test stops at the first pixel that could still change.
inline constexpr int kHiddenBoxTestPx = 16;

// Triangles narrower than this (whole bounding box: every tile decides alike) normalise per
// pixel: a block's end normals would cost as much as the pixels.
inline constexpr int kBlockNormalsMinWidthPx = 8;

// Hybrid lights the segment ends of a triangle's rows together, in full vectors: a batch holds
// up to this many ends (a row has at least two). 256 ends take 10 KiB of colour, slope and
// position arrays, inside L1 with the tile's rows; a triangle with more flushes mid-way (2c2d24b).
inline constexpr int kHybridMaxEnds = 256;

// Lights a quotient holds planes for; a frame with more keeps the normalised planes (a light's
// plane is 12 bytes of the per-triangle set-up, which this bounds).
inline constexpr int kDiffuseQuotientMaxLights = 8;

// Largest ratio R = T / Q_min a triangle may have, where T bounds the magnitudes of the
// quadratic's terms over the triangle's box, (|s| + |g_x| h_x + |g_y| h_y)² with s the normal
// over w at the centre, g its gradients and h the box's half extents, and Q_min bounds |m|²
// from below (the least entry of the Gram matrix of the vertices' normals over w). Evaluated in
// float, |m|² errs by at most 7u T (rounded coefficients, six roundings of partial sums bounded
// by T), so 1/|m| by 3.5u R + 2u; L·m by 5u sqrt(T), which over |m| is 5u sqrt(R); the product
// 1u. At R = 64: (3.5 · 64 + 5 · 8 + 3)u = 267u = 1.6e-5, 0.004 LSB, under half the 0.01 LSB
// reserve (docs/STABILITY.md, B4).
inline constexpr double kDiffuseQuotientMaxTermRatio = 64.0;

}  // namespace fastshade::limits
