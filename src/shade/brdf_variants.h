// Run-time (viewer, output curve, BRDF) to the template instantiation that bakes them in:
// kernels are compiled per variant so their loops carry no switch; the choice is made once
// per frame or per call.
#pragma once
#include <type_traits>

#include "shade/brdf.h"

namespace fastshade {

// Calls f(std::integral_constant<BrdfKind, K>()) for K = kind: the one switch from a run-time
// lobe to a compiled one.
template <typename F>
decltype(auto) with_brdf_kind(BrdfKind kind, F&& f) {
  switch (kind) {
    case BrdfKind::Exact: return f(std::integral_constant<BrdfKind, BrdfKind::Exact>());
    case BrdfKind::CosK: return f(std::integral_constant<BrdfKind, BrdfKind::CosK>());
    case BrdfKind::Schlick: return f(std::integral_constant<BrdfKind, BrdfKind::Schlick>());
    case BrdfKind::SchlickPow2: return f(std::integral_constant<BrdfKind, BrdfKind::SchlickPow2>());
    case BrdfKind::Quadratic: return f(std::integral_constant<BrdfKind, BrdfKind::Quadratic>());
    case BrdfKind::QuadraticFit: return f(std::integral_constant<BrdfKind, BrdfKind::QuadraticFit>());
    case BrdfKind::Poly2: return f(std::integral_constant<BrdfKind, BrdfKind::Poly2>());
    case BrdfKind::Poly3: break;
  }
  return f(std::integral_constant<BrdfKind, BrdfKind::Poly3>());
}

}  // namespace fastshade

// Defines NAME(bool local, bool srgb, BrdfKind kind) returning &FN<local, srgb, kind> as TYPE.
// Expand inside the per-target namespace.
#define FASTSHADE_DEFINE_VARIANT_PICKER(NAME, FN, TYPE)                                          \
  template <bool kLocal, bool kSrgb>                                                            \
  TYPE NAME##ForFlags(BrdfKind kind) {                                                          \
    return with_brdf_kind(kind, [](auto k) -> TYPE { return &FN<kLocal, kSrgb, decltype(k)::value>; }); \
  }                                                                                             \
  inline TYPE NAME(bool local, bool srgb, BrdfKind kind) {                                      \
    if (local) return srgb ? NAME##ForFlags<true, true>(kind) : NAME##ForFlags<true, false>(kind); \
    return srgb ? NAME##ForFlags<false, true>(kind) : NAME##ForFlags<false, false>(kind);          \
  }
