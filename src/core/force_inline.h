// For the small per-triangle helpers in headers that SIMD kernels call (edge functions, plane
// set-up): forced inline, each kernel compiles them for its own target (VEX-encoded, no call,
// their structs kept in registers) instead of sharing one out-of-line baseline (SSE2) copy.
// Only for functions whose result cannot depend on the target: integer or double arithmetic,
// no FMA contraction (-ffp-contract=off, CMakeLists.txt).
#pragma once

#define FASTSHADE_FORCE_INLINE inline __attribute__((always_inline))
