// The SIMD target one renderer runs on, chosen per instance (as Intel's
// MaskedOcclusionCulling does), not per process: two renderers in one process may run
// different ISAs side by side. Every SIMD entry point takes it and dispatches with
// FASTSHADE_DISPATCH (core/dispatch.h) instead of HWY_DYNAMIC_DISPATCH, whose choice is global.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace fastshade {

struct SimdTarget {
  // The entry of every HWY_EXPORT table to call. 0 is Highway's own first entry, which runs
  // the best target this CPU supports: the default of kernels called outside a renderer.
  uint32_t table_index = 0;
  bool operator==(const SimdTarget&) const = default;
};

// "scalar" (Highway's portable fallback), "sse4", "avx2", "avx512" or "best". Throws
// InputError ("--isa: ...") for an unknown name or one this CPU or build cannot run.
SimdTarget simd_target(std::string_view isa);
std::string simd_target_name(SimdTarget target);  // "avx512"; the best one's name for 0
std::vector<std::string> available_isas();        // compiled and run by this CPU, best last

}  // namespace fastshade
