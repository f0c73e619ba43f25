// The front end's tuning constants, with the reasoning that bounds each (the pipeline's shared
// limits are in core/limits.h).
#pragma once
#include <cstdint>

namespace fastshade::limits {

// The vertices of a dense mesh's triangle sit wherever the mesh put them: set-up fetches those
// of the triangle this many on (dragon_871k's front end, 1 thread: none 12.6 ms, 8 ahead 11.9,
// 07c2f16; on a Zen 5 guest 8 ahead 17.1, 32 ahead 16.6, e74827e).
inline constexpr uint32_t kSetupPrefetchTriangles = 32;

}  // namespace fastshade::limits
