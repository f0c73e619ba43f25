// Front end, last stage: sort every chunk's triangles into per-tile bins, keeping draw order.
#pragma once
#include "frame/frame.h"

namespace fastshade {

// Counts one chunk's triangles per tile (into chunk.tile_counts) and, for a classified frame,
// which shading paths each tile holds (chunk.tile_paths); notes each triangle's tile if it
// has only one (chunk.only_tile). Parallel over chunks; run right after the chunk's setup,
// while its records are still in cache (a dense mesh's are tens of MB in all).
void count_chunk_bins(const TileGrid& grid, bool classified, Chunk& chunk);

// Lays out frame.tile_begin, merges the chunks' tile paths into frame.tile_paths, and turns
// every chunk's counts into its write cursors: tiles x chunks additions, parallel over blocks
// of limits::kBinPlanTiles tiles, and a serial prefix sum over tiles.
void plan_bins(Frame& frame);

// Writes one chunk's entries at its cursors, reading the records of triangles that span
// several tiles only. Parallel over chunks.
void fill_chunk_bins(Frame& frame, uint32_t chunk_index);

}  // namespace fastshade
