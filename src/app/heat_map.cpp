#include "app/heat_map.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdlib>

#include "fastshade/error.h"

namespace fastshade {

namespace {

// One stop per power of two from 1 LSB (2^0) to 64 LSB (2^6): hues a reader names at a glance.
constexpr std::array<Rgb8, 7> kStops = {{{45, 75, 200},
                                         {0, 160, 220},
                                         {60, 190, 80},
                                         {240, 220, 40},
                                         {245, 130, 20},
                                         {220, 30, 30},
                                         {255, 255, 255}}};
constexpr Rgb8 kExactObject = {48, 48, 48};  // no error, object pixel: a flat silhouette
constexpr Rgb8 kExactBackground = {0, 0, 0};

}  // namespace

Rgb8 heat_colour(int lsb) {
  const int top = static_cast<int>(kStops.size()) - 1;
  if (lsb >= (1 << top)) return kStops[top];
  // Position on the log2 axis: stop k at 2^k, linear in log2 between stops.
  const int k = std::bit_width(static_cast<unsigned>(std::max(lsb, 1))) - 1;
  const double frac = std::log2(static_cast<double>(std::max(lsb, 1))) - k;
  Rgb8 out;
  for (int c = 0; c < 3; ++c)
    out[c] = static_cast<uint8_t>(kStops[k][c] + frac * (kStops[k + 1][c] - kStops[k][c]) + 0.5);
  return out;
}

Image error_heat_map(const Image& image, const Image& reference, Rgb8 background) {
  if (image.width != reference.width || image.height != reference.height)
    throw InputError("heat map", "images differ in size");
  Image out{image.width, image.height, ImageBytes(image.rgb.size())};
  for (std::size_t p = 0; p < image.rgb.size(); p += 3) {
    int err = 0;
    bool object = false;
    for (int c = 0; c < 3; ++c) {
      err = std::max(err, std::abs(int(image.rgb[p + c]) - int(reference.rgb[p + c])));
      object = object || reference.rgb[p + c] != background[c];
    }
    const Rgb8 colour = err > 0 ? heat_colour(err) : object ? kExactObject : kExactBackground;
    std::copy(colour.begin(), colour.end(), out.rgb.begin() + p);
  }
  return out;
}

}  // namespace fastshade
