// The execution layer's tuning constants, with the reasoning that bounds each (the pipeline's
// shared limits are in core/limits.h).
#pragma once
#include <cstdint>

namespace fastshade::limits {

// Triangles per task of the segment-length pass (front/segment_steps.h): about 50-100 us of
// work at 0.2-0.4 us a triangle, far above a task's cost, and 16 tasks for a chunk of 4096.
inline constexpr uint32_t kSegmentStepBlock = 256;

// A tile's triangles sit wherever their chunk put them and their vertices wherever the mesh
// did: the tile loop fetches triangle i + 8's record, and the vertices of triangle i + 4, whose
// record the previous prefetch has brought in by then (b74c6a5; fetching the second line a
// 72-byte record may straddle measured no different, 728c582).
inline constexpr uint32_t kTilePrefetchTriangles = 8;
inline constexpr uint32_t kTilePrefetchVertices = 4;

// Empty tiles go to the workers in runs of this many, in tile order, which cost only their
// background. Each task's end is a locked add on the loop's shared count; with a task per tile
// a 4K frame paid it for 1,582 empty tiles too (79 % of the tile loop's own samples sat on it,
// perf; c92dd58). 16 empty 64-px tiles fill 192 KiB in about 10 us, small enough that a run
// left for last cannot unbalance the workers.
inline constexpr int kEmptyTilesPerTask = 16;

}  // namespace fastshade::limits
