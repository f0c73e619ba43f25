// Run-time (viewer, output curve, BRDF) to the template instantiation that bakes them in:
// kernels are compiled per variant so their loops carry no switch; the choice is made once
// per frame. Expand inside the per-target namespace.
#pragma once

// Defines NAME(bool local, bool srgb, BrdfKind kind) returning &FN<local, srgb, kind> as TYPE.
#define FASTSHADE_DEFINE_VARIANT_PICKER(NAME, FN, TYPE)                          \
  template <bool kLocal, bool kSrgb>                                            \
  TYPE NAME##ForFlags(BrdfKind kind) {                                          \
    switch (kind) {                                                             \
      case BrdfKind::Exact: return &FN<kLocal, kSrgb, BrdfKind::Exact>;         \
      case BrdfKind::CosK: return &FN<kLocal, kSrgb, BrdfKind::CosK>;           \
      case BrdfKind::Schlick: return &FN<kLocal, kSrgb, BrdfKind::Schlick>;     \
      case BrdfKind::SchlickPow2: return &FN<kLocal, kSrgb, BrdfKind::SchlickPow2>; \
      case BrdfKind::Quadratic: return &FN<kLocal, kSrgb, BrdfKind::Quadratic>; \
      case BrdfKind::QuadraticFit: return &FN<kLocal, kSrgb, BrdfKind::QuadraticFit>; \
      case BrdfKind::Poly2: return &FN<kLocal, kSrgb, BrdfKind::Poly2>;         \
      case BrdfKind::Poly3: return &FN<kLocal, kSrgb, BrdfKind::Poly3>;         \
    }                                                                           \
    return nullptr;                                                             \
  }                                                                             \
  inline TYPE NAME(bool local, bool srgb, BrdfKind kind) {                      \
    if (local) return srgb ? NAME##ForFlags<true, true>(kind) : NAME##ForFlags<true, false>(kind); \
    return srgb ? NAME##ForFlags<false, true>(kind) : NAME##ForFlags<false, false>(kind);          \
  }
