// The SIMD target one renderer runs on, chosen per instance (as Intel's
// MaskedOcclusionCulling does), not per process: two renderers in one process may run
// different ISAs side by side. Every SIMD entry point takes it and dispatches with
// FASTSHADE_DISPATCH (core/dispatch.h) instead of HWY_DYNAMIC_DISPATCH, whose choice is global.
#pragma once
#include <cstdint>
#include <string>

#include "fastshade/options.h"

namespace fastshade {

struct SimdTarget {
  // The entry of every HWY_EXPORT table to call. 0 is Highway's own first entry, which runs
  // the best target this CPU supports: the default of kernels called outside a renderer.
  uint32_t table_index = 0;
  bool operator==(const SimdTarget&) const = default;
};

// Throws InputError ("--isa: ...") for an ISA this CPU or build cannot run. available_isas()
// (include/fastshade/options.h) lists those it can.
SimdTarget simd_target(Isa isa);
// The named ISA a target runs (Isa::Best for a target outside the four, from the build's
// HWY_TARGETS), and its name: "avx512"; the best one's for table index 0.
Isa simd_target_isa(SimdTarget target);
std::string simd_target_name(SimdTarget target);

}  // namespace fastshade
