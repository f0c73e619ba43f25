// RenderOptions, checked once: the method they name, the SIMD target, and the options as the
// layers below read them. validate() is resolve() with the result dropped.
#pragma once
#include "core/simd_target.h"
#include "fastshade/options.h"
#include "shade/method.h"

namespace fastshade {

struct ResolvedOptions {
  const Method* method = nullptr;
  SimdTarget simd;  // --isa
  RenderOptions options;
};

// Throws InputError ("--tile: ...") for an option out of range, a value outside its enum, an
// ISA this CPU cannot run, or a combination the method refuses.
ResolvedOptions resolve(const RenderOptions& options);

}  // namespace fastshade
