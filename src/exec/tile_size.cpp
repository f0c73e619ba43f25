#include "exec/tile_size.h"

#include <algorithm>

#include "core/limits.h"

namespace fastshade {

int sized_tile_px(int width, int height, int workers) {
  const long long wanted = static_cast<long long>(std::max(workers, 1)) * limits::kTilesPerWorker;
  int tile = limits::kSizedTileMaxPx;
  for (; tile > limits::kSizedTileMinPx; tile /= 2) {
    const long long tiles = static_cast<long long>((width + tile - 1) / tile) * ((height + tile - 1) / tile);
    if (tiles >= wanted) break;
  }
  return tile;
}

int resolve_tile_px(int tile_px, int width, int height, int workers) {
  return tile_px != 0 ? tile_px : sized_tile_px(width, height, workers);
}

}  // namespace fastshade
