// The tile size a frame uses when the options leave it open (--tile 0): sized from the image
// and the worker count, once per renderer (the reasoning is at limits::kTilesPerWorker).
#pragma once

namespace fastshade {

// The largest power of two in [kSizedTileMinPx, kSizedTileMaxPx] whose grid over a
// width x height image has at least kTilesPerWorker tiles per worker; the smallest if none has.
int sized_tile_px(int width, int height, int workers);

// tile_px as the options hold it (0 = sized_tile_px), resolved for this image and workers.
int resolve_tile_px(int tile_px, int width, int height, int workers);

}  // namespace fastshade
