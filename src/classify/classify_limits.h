// The classifier's and the hybrid step's tuning constants, with the reasoning that bounds each
// (the pipeline's shared limits are in core/limits.h).
#pragma once
#include <cstddef>

namespace fastshade::limits {

// A light whose specular term stays below this share of --spec-threshold counts as that share,
// without evaluating pow: at 1e-3 even a thousand such lights sum to one threshold.
inline constexpr double kNegligibleLightShare = 1e-3;

// Triangles narrower than this (whole bounding box, not a tile's part of it, so that every
// tile decides alike) take per-pixel Phong: a segment end costs as much as a pixel, and a
// batch of rows has a fixed cost. 16 beat 8 on both the bunny (0.95x) and the spot 4K frame
// (0.99x; c9d7a36).
inline constexpr int kHybridMinWidthPx = 16;

// A triangle whose specular terms, bounded at c_max and summed over lights as the step bound
// sums them, stay below this has its segment ends lit without them. 2^-24 is 1/65536 of an
// 8-bit step: a level can change only where the colour sits that close to a rounding boundary,
// and the bound charges the term to the tolerance, so the error proof holds as it did. At n = 100
// and ks = 0.5 it leaves out every triangle whose N.H stays below 0.85 (32 degrees from H): on
// the 4K spot frame, most of them (1712a65).
inline constexpr double kNegligibleSpecular = 0x1p-24;

// Below this |L + V| the half vector turns faster than any segment can follow (it is undefined
// where the light sits exactly behind the viewer): per-pixel Phong.
inline constexpr double kMinHalfVectorLength = 1e-3;

// Lanes may carry lights_with_highlight as a sum of powers of two in a double (exact below
// 2^53); materials lit by more lights leave the lanes the cheap look only.
inline constexpr std::size_t kMaxExactLaneLights = 32;

// Lanes the cheap cone look leaves are gathered into full vectors for the exact look, which
// costs ten times as much: block by block, so that the gathered copies (9 + 2 doubles a lane)
// stay within L1.
inline constexpr std::size_t kConeExactBlock = 256;

}  // namespace fastshade::limits
