// The execution layer's tuning constants, with the reasoning that bounds each (the pipeline's
// shared limits are in core/limits.h).
#pragma once
#include <cstdint>
#include <utility>

#include "fastshade/options.h"

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

// `auto`'s cost model (exec/auto_cost.h). Classifying saves, on each pixel it sends down the
// diffuse paths, the difference between per-pixel Phong and Gouraud, and costs per triangle:
// vertex lighting, the classifier's bounds, the per-path dispatch. It pays where triangles are
// large enough, and how large depends on how cheap the ISA makes per-pixel Phong. The sample
// keeps the estimate near 0.1 ms whatever the mesh.
inline constexpr std::size_t kAutoCostSampleTriangles = 4096;
// The smallest mean triangle (pixels, sampled_triangle_px) at which `auto` classifies, per ISA.
// Measured as auto's frame time over phong's (1 thread, 5 alternated rounds) on spot, bunny,
// lucy_100k and dragon_871k at 480 to 3840 px wide, i.e. 0.1 to 430 px a triangle
// (docs/CLASSIFIER.md, "When auto classifies"): each threshold sits between the largest size
// where auto lost and the smallest where it won. scalar: lost at 15 (1.01), won at 27 (0.95);
// sse4: lost at 27 (1.02), won at 51 (0.79); avx2: lost at 27 (1.05), won at 51 (0.98);
// avx512: lost at 51 (1.04), won at 108 (0.86).
inline constexpr std::pair<Isa, double> kAutoClassifyMinPx[] = {
    {Isa::Scalar, 20.0}, {Isa::Sse4, 40.0}, {Isa::Avx2, 48.0}, {Isa::Avx512, 80.0}};

}  // namespace fastshade::limits
