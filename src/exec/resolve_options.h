// RenderOptions, checked and parsed once: the method they name and their typed choices
// (frame/render_choices.h). validate() is resolve() with the result dropped.
#pragma once
#include "core/simd_target.h"
#include "fastshade/render.h"
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
