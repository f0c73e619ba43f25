// Error heat maps: where a method's image departs from the reference, and by how much.
#pragma once
#include <array>
#include <cstdint>

#include "fastshade/image.h"

namespace fastshade {

using Rgb8 = std::array<uint8_t, 3>;

// The colour of a per-pixel error of `lsb` 8-bit steps (> 0), on a log scale with a stop at each
// power of two: 1 blue, 2 cyan, 4 green, 8 yellow, 16 orange, 32 red, 64 and more white.
Rgb8 heat_colour(int lsb);

// Per pixel, the largest channel difference between `image` and `reference` (same size),
// coloured by heat_colour. Pixels without error are dark grey where the reference shows an
// object (differs from `background`) and black elsewhere, so the silhouette stays visible and
// the file compresses well.
Image error_heat_map(const Image& image, const Image& reference, Rgb8 background);

}  // namespace fastshade
