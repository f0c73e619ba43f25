#include "exec/tile_executor.h"

#include <algorithm>
#include <bit>
#include <vector>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>

#include "core/force_inline.h"
#include "exec/aov_pass.h"
#include "exec/exec_limits.h"
#include "exec/frame_profile.h"
#include "exec/tile_io.h"
#include "light/lighting.h"
#include "shade/pixel_queue.h"
#include "shade/shade_limits.h"

namespace fastshade {

namespace {

struct TileBuffers {  // one worker's scratch, sized for the largest tile, reused across tiles
  std::vector<uint32_t> color;
  std::vector<float> depth;
  AovTileScratch aov;  // sized on the first frame with AOVs
  PixelQueue queue;
  // This worker's share of the frame's counts: shared atomics were locked adds, six a tile.
  BackEndCounts counts;
  TileBuffers() {
    const std::size_t n = std::size_t(limits::kMaxTilePx) * limits::kMaxTilePx + limits::kScratchPadPx;
    color.resize(n);
    depth.resize(n);
  }
};

uint32_t background_rgba(const ShadeConstants& k) {
  return pack_rgba(quantize(k.background.r, k.srgb), quantize(k.background.g, k.srgb),
                   quantize(k.background.b, k.srgb));
}

// The background as one RGB8 row of the widest tile: empty tiles copy it, row by row.
std::vector<uint8_t> background_row(uint32_t rgba) {
  std::vector<uint8_t> row(std::size_t(limits::kMaxTilePx) * 3);
  for (std::size_t x = 0; x < row.size(); x += 3) {
    row[x] = uint8_t(rgba);
    row[x + 1] = uint8_t(rgba >> 8);
    row[x + 2] = uint8_t(rgba >> 16);
  }
  return row;
}

void fill_rect(SimdTarget simd, Image& image, const PixelRect& r, const std::vector<uint8_t>& row) {
  stream_rows(simd, row.data(), 0, image.rgb.data() + (std::size_t(r.y0) * image.width + r.x0) * 3, image.width * 3,
              (r.x1 - r.x0 + 1) * 3, r.y1 - r.y0 + 1);
}

// The records and vertices of triangles ahead (exec/exec_limits.h). Forced inline: GCC counts a
// function that only prefetches as pure, and a call to a pure function whose result is unused
// as dead, so before af36a55 no prefetch reached the binary (bunny raster 0.79x on 1 thread
// with them).
FASTSHADE_FORCE_INLINE void prefetch_ahead(const Frame& frame, uint32_t i, uint32_t end) {
  constexpr uint32_t kTriangleAhead = limits::kTilePrefetchTriangles, kVertexAhead = limits::kTilePrefetchVertices;
  if (i + kTriangleAhead < end) __builtin_prefetch(&frame.triangle(frame.bin_entries[i + kTriangleAhead]));
  if (i + kVertexAhead < end) {
    const uint32_t entry = frame.bin_entries[i + kVertexAhead];
    const SetupTriangle& t = frame.triangle(entry);
    for (AttrField field : {&AttrArrays::n_view, &AttrArrays::color})
      if (!(frame.attrs.*field).empty())
        for (uint32_t attr : t.attr) __builtin_prefetch(&frame.vertex(entry, attr, field));
  }
}

// A task of the back end: one tile with bins, or a run of up to limits::kEmptyTilesPerTask
// empty tiles (exec/exec_limits.h).
struct TileTask {
  int first, count;
  bool empty;
};

// The frame's tasks, tile order kept (the order matters only for which worker takes what).
void plan_tasks(const Frame& frame, std::vector<TileTask>& tasks) {
  tasks.clear();
  for (int tile = 0; tile < frame.grid.tile_count(); ++tile) {
    const bool empty = frame.tile_begin[tile] == frame.tile_begin[tile + 1];
    if (empty && !tasks.empty()) {
      TileTask& last = tasks.back();
      if (last.empty && last.count < limits::kEmptyTilesPerTask) {
        ++last.count;
        continue;
      }
    }
    tasks.push_back({tile, 1, empty});
  }
}

}  // namespace

struct TileExecutor::Scratch {
  tbb::enumerable_thread_specific<TileBuffers> per_thread;
  std::vector<TileTask> tasks;  // reused frame to frame
};

TileExecutor::TileExecutor() : scratch_(std::make_unique<Scratch>()) {}
TileExecutor::~TileExecutor() = default;

BackEndCounts TileExecutor::run(const Frame& frame, const TileDraw& draw, Image& image, uint64_t* tile_ns,
                                const AovFrame* aov) {
  const TileGrid& grid = frame.grid;
  const uint32_t background = background_rgba(frame.shade);
  const std::vector<uint8_t> background_rgb = background_row(background);
  const bool classified = !frame.tile_paths.empty();
  for (TileBuffers& buffers : scratch_->per_thread) buffers.counts = {};
  std::vector<TileTask>& tasks = scratch_->tasks;
  plan_tasks(frame, tasks);
  auto draw_tile = [&](int tile) {
    ItemTimer timer(tile_ns ? tile_ns + tile : nullptr);
    const int tx = tile % grid.tiles_x, ty = tile / grid.tiles_x;
    const PixelRect rect{tx * grid.tile_px, ty * grid.tile_px,
                         std::min((tx + 1) * grid.tile_px, grid.width) - 1,
                         std::min((ty + 1) * grid.tile_px, grid.height) - 1};
    const uint32_t begin = frame.tile_begin[tile], end = frame.tile_begin[tile + 1];
    if (begin == end) {  // an empty tile costs only its background
      fill_rect(frame.simd, image, rect, background_rgb);
      if (aov) write_empty_aovs(frame, *aov, rect);
      return;
    }
    TileBuffers& buffers = scratch_->per_thread.local();
    const int stride = grid.tile_px;
    const int w = rect.x1 - rect.x0 + 1;
    const int h = rect.y1 - rect.y0 + 1;
    clear_tile(frame.simd, buffers.color.data(), buffers.depth.data(), stride, background, w, h);
    TileTarget target{buffers.color.data(), buffers.depth.data(), stride, rect.x0,
                      rect.y0, rect, draw.path};
    target.pending = &buffers.queue;
    // A tile whose triangles all take one path runs that path's kernel alone, and every pixel
    // it draws is that path's: its pixels need no count by path.
    DrawTriangleFn tile_draw = draw.any;
    int single_path = -1;
    if (classified) {
      const unsigned paths = frame.tile_paths[tile];
      const int only = std::countr_zero(paths);
      if (std::has_single_bit(paths) && draw.path[only]) {
        tile_draw = draw.path[only];
        target.alpha_xor = path_alpha_xor(static_cast<ShadePath>(only));
        ++buffers.counts.single_path_tiles;
        single_path = only;
      }
    }
    for (uint32_t i = begin; i < end; ++i) {
      prefetch_ahead(frame, i, end);
      tile_draw(frame, frame.bin_entries[i], target);
    }
    light_pending(buffers.queue, target);
    if (aov) write_tile_aovs(frame, *aov, begin, end, rect, buffers.depth.data(), stride, buffers.aov);
    rgba_rows_to_rgb(frame.simd, buffers.color.data(), stride,
                     image.rgb.data() + (std::size_t(rect.y0) * image.width + rect.x0) * 3,
                     image.width * 3, w, h);
    TilePixelCounts tile_counts = count_tile_pixels(frame.simd, buffers.depth.data(), buffers.color.data(), stride, w, h,
                                                    classified && single_path < 0);
    if (single_path >= 0) tile_counts.path[single_path] = tile_counts.covered;
    BackEndCounts drawn;
    drawn.tiles_nonempty = 1;
    drawn.covered_pixels = tile_counts.covered;
    std::copy(std::begin(tile_counts.path), std::end(tile_counts.path), drawn.path_pixels);
    buffers.counts.add(drawn);
  };
  // One task at a time, handed out dynamically: tile costs vary by orders of magnitude.
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, tasks.size(), 1),
      [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t task = range.begin(); task != range.end(); ++task)
          for (int tile = tasks[task].first; tile != tasks[task].first + tasks[task].count; ++tile) draw_tile(tile);
      },
      tbb::simple_partitioner());
  BackEndCounts counts;
  for (const TileBuffers& buffers : scratch_->per_thread) counts.add(buffers.counts);
  return counts;
}

}  // namespace fastshade
