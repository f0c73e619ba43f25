// Front end, after setup: hybrid's segment length per triangle (classify/segment_step.h),
// decided once and kept in the triangle's record. The hybrid kernel draws a triangle in every
// tile it covers, about 2.5 tiles a triangle on the 4K spot frame, and deciding there cost
// each of them about 0.4 us (0.2 us since the decision skips acos and cos and one pow;
// ce93b34).
#pragma once
#include <cstdint>
#include <vector>

#include "frame/frame.h"
#include "frame/method_needs.h"

namespace fastshade {

// Whether the hybrid kernel draws this set-up triangle in segments: wide enough (narrower
// ones are drawn per pixel, classify/segment_step.h kHybridMinWidthPx) and, for SpecularPath,
// on the specular path. Setup lists such triangles in Chunk::segment_pending.
bool draws_segments(const SetupTriangle& t, SegmentSteps which);

// Decides the segment plan of the triangles Chunk::segment_pending[first, last) of chunk
// `chunk` (listed by setup: wide enough for segments and on a path that draws them) and
// writes it into their flags (frame/frame.h kSegmentStepMask, kSplitLightMask); every other
// triangle keeps 0 (per-pixel Phong). A pure function of the triangle: the same for any thread count or tile
// size.
void decide_segment_steps(Frame& frame, uint32_t chunk, uint32_t first, uint32_t last);

// What the decisions came to, for the stats: triangles by log2 of their segment length, how
// many split a light, and how many segment ends (2+ px) go without the specular term. Empty
// where no triangle reached hybrid: --explain then prints no plan of zeros.
struct SegmentTally {
  std::vector<long long> by_log2_px;
  long long split = 0;
  long long no_specular = 0;
};
SegmentTally tally_segment_plans(const Frame& frame);

}  // namespace fastshade
