#include "front/binning.h"

#include <algorithm>

#include <tbb/parallel_for.h>

#include "frame/edge_function.h"

namespace fastshade {

namespace {

// Calls visit(tile) for every tile the triangle may cover, in row-major order.
template <typename Visit>
void for_each_tile(const TileGrid& grid, const SetupTriangle& t, Visit&& visit) {
  const int s = grid.tile_shift;
  const int tx0 = t.px_min[0] >> s, tx1 = t.px_max[0] >> s;
  const int ty0 = t.px_min[1] >> s, ty1 = t.px_max[1] >> s;
  if (tx0 == tx1 && ty0 == ty1) {  // the common case: inside one tile
    visit(ty0 * grid.tiles_x + tx0);
    return;
  }
  // A long diagonal triangle's bounding box holds many tiles it never touches.
  const TriangleEdges edges = triangle_edges(t);
  for (int ty = ty0; ty <= ty1; ++ty)
    for (int tx = tx0; tx <= tx1; ++tx) {
      const int x0 = tx << s, y0 = ty << s;
      if (may_cover(edges, x0, y0, x0 + grid.tile_px - 1, y0 + grid.tile_px - 1))
        visit(ty * grid.tiles_x + tx);
    }
}

}  // namespace

void count_chunk_bins(const TileGrid& grid, bool classified, Chunk& chunk) {
  chunk.tile_counts.assign(grid.tile_count(), 0);
  chunk.only_tile.resize(chunk.triangles.size());
  uint32_t* counts = chunk.tile_counts.data();
  chunk.tile_paths.assign(classified ? grid.tile_count() : 0, 0);
  uint8_t* paths = chunk.tile_paths.data();
  for (uint32_t i = 0; i < chunk.triangles.size(); ++i) {
    const SetupTriangle& t = chunk.triangles[i];
    const uint8_t bit = classified ? uint8_t(1u << static_cast<int>(Frame::path_of(t))) : 0;
    int tiles = 0, last = 0;
    for_each_tile(grid, t, [&](int tile) {
      ++counts[tile];
      if (classified) paths[tile] |= bit;
      ++tiles;
      last = tile;
    });
    chunk.only_tile[i] = tiles == 1 ? static_cast<uint32_t>(last) : kSeveralTiles;
  }
}

void plan_bins(Frame& frame) {
  const int tiles = frame.grid.tile_count();
  const int blocks = (tiles + limits::kBinPlanTiles - 1) / limits::kBinPlanTiles;
  std::vector<uint32_t>& begin = frame.tile_begin;
  begin.assign(tiles + 1, 0);
  const bool classified = !frame.chunks.empty() && !frame.chunks[0].tile_paths.empty();
  frame.tile_paths.assign(classified ? tiles : 0, 0);
  // Tile by tile across all chunks would touch a cache line per chunk and tile; a block of
  // tiles reads each chunk's counters in order instead.
  tbb::parallel_for(0, blocks, [&](int block) {  // every tile's count, into begin[tile + 1]
    const int first = block * limits::kBinPlanTiles, last = std::min(first + limits::kBinPlanTiles, tiles);
    for (const Chunk& chunk : frame.chunks)
      for (int tile = first; tile < last; ++tile) {
        begin[tile + 1] += chunk.tile_counts[tile];
        if (classified) frame.tile_paths[tile] |= chunk.tile_paths[tile];
      }
  });
  for (int tile = 0; tile < tiles; ++tile) begin[tile + 1] += begin[tile];
  tbb::parallel_for(0, blocks, [&](int block) {
    const int first = block * limits::kBinPlanTiles, last = std::min(first + limits::kBinPlanTiles, tiles);
    uint32_t cursor[limits::kBinPlanTiles];
    std::copy(begin.begin() + first, begin.begin() + last, cursor);
    for (Chunk& chunk : frame.chunks)  // in draw order
      for (int tile = first; tile < last; ++tile) {
        const uint32_t n = chunk.tile_counts[tile];
        chunk.tile_counts[tile] = cursor[tile - first];  // from now on: where this chunk writes
        cursor[tile - first] += n;
      }
  });
  frame.bin_entries.resize(begin[tiles]);
}

void fill_chunk_bins(Frame& frame, uint32_t chunk_index) {
  Chunk& chunk = frame.chunks[chunk_index];
  uint32_t* cursor = chunk.tile_counts.data();
  uint32_t* entries = frame.bin_entries.data();
  for (uint32_t i = 0; i < chunk.triangles.size(); ++i) {
    const uint32_t entry = bin_entry(chunk_index, i);
    const uint32_t only = chunk.only_tile[i];  // most triangles: no need to read the record again
    if (only != kSeveralTiles) entries[cursor[only]++] = entry;
    else for_each_tile(frame.grid, chunk.triangles[i], [&](int tile) { entries[cursor[tile]++] = entry; });
  }
}

}  // namespace fastshade
