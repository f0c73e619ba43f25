// Run-time (viewer, BRDF) to the template instantiation that bakes them in: kernels are
// compiled per variant so their loops carry no switch on the viewer and the default lobe; the
// choice is made once per frame or per call.
#pragma once
#include <type_traits>

#include "light/brdf.h"

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

// The lobe a per-pixel shading kernel is compiled for. The default lobe (exact c^n) is baked
// in; the seven approximations share one instantiation that switches on the material's
// BrdfKind per vector (SpecularLobe in light/brdf-inl.h), and the sRGB curve is a run-time
// flag (PackRGBA in shade/span_loop-inl.h). One instantiation per lobe and curve (32 per
// kernel, times 4 ISAs) made hybrid.cpp, phong.cpp and phong_normals.cpp take 5-7 minutes
// each to compile; now they take about a minute. The branches go the same way all frame:
// alternated on spot 4K, phong, hybrid, auto and the approximations stayed within noise
// (docs/BUILDING.md, "Build time").
enum class LobeKernel {
  Exact,   // exp2(n log2 c), the default --brdf
  ByKind,  // any BrdfKind, chosen per vector from the material's lobe
};

inline LobeKernel lobe_kernel(BrdfKind kind) {
  return kind == BrdfKind::Exact ? LobeKernel::Exact : LobeKernel::ByKind;
}

}  // namespace fastshade

// Defines NAME(bool local, BrdfKind kind) returning &FN<local, lobe_kernel(kind)> as TYPE.
// Expand inside the per-target namespace.
#define FASTSHADE_DEFINE_VARIANT_PICKER(NAME, FN, TYPE)                                          \
  template <bool kLocal>                                                                        \
  TYPE NAME##ForViewer(BrdfKind kind) {                                                         \
    return lobe_kernel(kind) == LobeKernel::Exact ? &FN<kLocal, LobeKernel::Exact>               \
                                                  : &FN<kLocal, LobeKernel::ByKind>;             \
  }                                                                                             \
  inline TYPE NAME(bool local, BrdfKind kind) {                                                 \
    return local ? NAME##ForViewer<true>(kind) : NAME##ForViewer<false>(kind);                  \
  }
