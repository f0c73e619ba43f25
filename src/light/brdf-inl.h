// The BRDF approximations as SIMD kernels (per-target, Highway "-inl.h"): the same float
// operations in the same order as brdf_one() in light/brdf.cpp, the scalar reference.
#if defined(FASTSHADE_LIGHT_BRDF_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FASTSHADE_LIGHT_BRDF_INL_H_
#undef FASTSHADE_LIGHT_BRDF_INL_H_
#else
#define FASTSHADE_LIGHT_BRDF_INL_H_
#endif

#include <numbers>

#include <hwy/contrib/math/math-inl.h>
#include <hwy/highway.h>

#include "light/brdf.h"
#include "light/brdf_variants.h"  // LobeKernel
#include "light/fast_math-inl.h"

HWY_BEFORE_NAMESPACE();
namespace fastshade {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The specular lobe for N.H values c (any float; NaN and c <= 0 give 0), kind fixed at compile
// time so the shading loops carry no switch.
template <BrdfKind K, class D, class V = hn::Vec<D>>
HWY_INLINE V Brdf(D d, V c_in, const BrdfParams& p) {
  const V one = hn::Set(d, 1.0f);
  // The mask before the clamp: x86 min returns its second operand for NaN, so a NaN would
  // become 1 there; Gt is false for NaN.
  const auto positive = hn::Gt(c_in, hn::Zero(d));
  const V safe = hn::IfThenElse(positive, hn::Min(c_in, one), one);
  V r;
  if constexpr (K == BrdfKind::Exact) {
    r = FastExp2(d, hn::Mul(hn::Set(d, p.n), FastLog2(d, safe)));
  } else if constexpr (K == BrdfKind::CosK) {
    const V t = hn::Mul(hn::Set(d, p.scale), hn::Acos(d, safe));
    const V v = hn::Cos(d, t);
    r = v;
    for (int i = 1; i < p.k; ++i) r = hn::Mul(r, v);
    r = hn::IfThenElseZero(hn::Lt(t, hn::Set(d, static_cast<float>(std::numbers::pi / 2))), r);
  } else if constexpr (K == BrdfKind::Schlick) {
    r = hn::Div(safe, hn::Add(hn::Mul(hn::Set(d, p.n), hn::Sub(one, safe)), safe));
  } else if constexpr (K == BrdfKind::SchlickPow2) {
    const V nx = hn::Mul(hn::Set(d, p.n_reduced), hn::Sub(one, safe));
    V delta = hn::Div(nx, hn::Add(nx, safe));
    for (int i = 0; i < p.squarings; ++i) delta = hn::Mul(delta, hn::Sub(hn::Set(d, 2.0f), delta));
    r = hn::Sub(one, delta);
  } else if constexpr (K == BrdfKind::Quadratic || K == BrdfKind::QuadraticFit) {
    const V u = hn::Max(hn::Add(hn::Mul(hn::Set(d, p.scale), hn::Sub(safe, one)), one), hn::Zero(d));
    r = hn::Mul(u, u);
  } else {  // Poly2, Poly3
    const V x = hn::Sub(one, safe);
    V v = hn::Add(hn::Set(d, p.poly[2]), hn::Mul(x, hn::Set(d, p.poly[3])));
    v = hn::Add(hn::Set(d, p.poly[1]), hn::Mul(x, v));
    v = hn::Add(hn::Set(d, p.poly[0]), hn::Mul(x, v));
    r = hn::IfThenElseZero(hn::Lt(x, hn::Set(d, p.x_root)), hn::Min(hn::Max(v, hn::Zero(d)), one));
  }
  return hn::IfThenElseZero(positive, r);
}

// The lobe of a shading kernel compiled for kLobe (light/brdf_variants.h): Brdf<Exact>, or
// Brdf of the material's kind, switched per call.
template <LobeKernel kLobe, class D, class V = hn::Vec<D>>
HWY_INLINE V SpecularLobe(D d, V c, const BrdfParams& p) {
  if constexpr (kLobe == LobeKernel::Exact) {
    return Brdf<BrdfKind::Exact>(d, c, p);
  } else {
    // Written out, not through with_brdf_kind: that template is compiled outside this target's
    // attributes, and a vector passed through it crashes (AVX-512 values in an SSE2 function).
    switch (p.kind) {
      case BrdfKind::Exact: return Brdf<BrdfKind::Exact>(d, c, p);
      case BrdfKind::CosK: return Brdf<BrdfKind::CosK>(d, c, p);
      case BrdfKind::Schlick: return Brdf<BrdfKind::Schlick>(d, c, p);
      case BrdfKind::SchlickPow2: return Brdf<BrdfKind::SchlickPow2>(d, c, p);
      case BrdfKind::Quadratic: return Brdf<BrdfKind::Quadratic>(d, c, p);
      case BrdfKind::QuadraticFit: return Brdf<BrdfKind::QuadraticFit>(d, c, p);
      case BrdfKind::Poly2: return Brdf<BrdfKind::Poly2>(d, c, p);
      case BrdfKind::Poly3: break;
    }
    return Brdf<BrdfKind::Poly3>(d, c, p);
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#endif  // include guard toggle
