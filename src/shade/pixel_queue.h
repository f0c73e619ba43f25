// Pixels of small triangles that passed the depth test, waiting to be lit a full vector at a
// time: a dense mesh's triangle covers one or two pixels, so lighting it alone fills a
// sixteenth of an AVX-512 vector (dragon_871k `phong`: a quarter of the frame went to
// four-lane vectors). Lanes are lit in the order they came, and colours are stored in that
// order, so a pixel that two triangles passed ends with the later one's colour, as if each
// had been stored at once; depths are written at once, for the tests that follow.
#pragma once
#include <cstdint>

#include "core/limits.h"
#include "frame/shade_constants.h"

namespace fastshade {

struct TileTarget;
struct PixelQueue;
// Lights the queue's entries and stores their colours into the tile: all of them, or (all =
// false) whole vectors only, keeping the rest at the front of the queue.
using LightQueueFn = void (*)(PixelQueue& queue, const TileTarget& target, bool all);

struct PixelQueue {
  // Interpolated normals (n/w from the planes, not yet normalised) and tile pixel indices.
  // Zeroed once: a partial vector reads entries past the count, which must be plain numbers.
  alignas(64) float nx[limits::kPixelQueueCapacity] = {}, ny[limits::kPixelQueueCapacity] = {},
                    nz[limits::kPixelQueueCapacity] = {};
  alignas(64) int32_t at[limits::kPixelQueueCapacity] = {};
  int count = 0;
  // What the waiting entries are lit with: one material and the frame's lights and viewer (a
  // viewer at infinity: entries carry no position). A triangle of another material lights
  // the queue before it adds to it.
  const MaterialConstants* material = nullptr;
  const ShadeConstants* shade = nullptr;
  LightQueueFn light = nullptr;
  // The tag the entries are stored with (TileTarget::alpha_xor of the triangles that queued
  // them): `auto` lights the queue before another path draws, with that path's target.
  uint32_t alpha_xor = 0;
};

// Lights whatever waits (the tile executor calls it before a tile's colours leave scratch).
inline void light_pending(PixelQueue& queue, const TileTarget& target) {
  if (queue.count > 0) queue.light(queue, target, true);
}

}  // namespace fastshade
