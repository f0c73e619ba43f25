// Division-free transcendental helpers for the SIMD kernels (per-target, Highway "-inl.h").
// Highway's Log divides and its Exp is longer than 8-bit output needs; these keep the
// divider (one per 10-15 cycles for 512-bit vectors on Zen 4) free for the normalisation.
#if defined(FASTSHADE_LIGHT_FAST_MATH_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FASTSHADE_LIGHT_FAST_MATH_INL_H_
#undef FASTSHADE_LIGHT_FAST_MATH_INL_H_
#else
#define FASTSHADE_LIGHT_FAST_MATH_INL_H_
#endif

#include <hwy/highway.h>

#include "light/fast_math.h"

HWY_BEFORE_NAMESPACE();
namespace fastshade {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// log2(x) for finite x > 0: exponent from the bits, mantissa m folded into [sqrt(1/2),
// sqrt(2)), then t * P(t) with t = m - 1 (fast_math.h: relative error 2.7e-8, below float
// rounding, and relative, so exact near x = 1 where the specular term lives).
template <class D, class V = hn::Vec<D>>
HWY_INLINE V FastLog2(D d, V x) {
  const hn::RebindToSigned<D> di;
  const auto bits = hn::BitCast(di, x);
  auto exponent = hn::Sub(hn::ShiftRight<23>(bits), hn::Set(di, 127));
  V m = hn::BitCast(d, hn::Or(hn::And(bits, hn::Set(di, 0x007FFFFF)), hn::Set(di, 0x3F800000)));
  const auto big = hn::Gt(m, hn::Set(d, 1.41421356f));
  m = hn::IfThenElse(big, hn::Mul(m, hn::Set(d, 0.5f)), m);
  exponent = hn::Add(exponent, hn::IfThenElseZero(hn::RebindMask(di, big), hn::Set(di, 1)));
  const V t = hn::Sub(m, hn::Set(d, 1.0f));
  V p = hn::Set(d, fast_math::kLog2Poly[0]);
  for (int i = 1; i < 9; ++i) p = hn::MulAdd(p, t, hn::Set(d, fast_math::kLog2Poly[i]));
  return hn::MulAdd(t, p, hn::ConvertTo(d, exponent));
}

// 2^y for y <= 0, clamped at 2^-126 (far below an 8-bit step): 2^floor(y) from the bits
// times 2^f, f in [0, 1), by a degree-6 polynomial (fast_math.h, relative error 2.6e-9).
template <class D, class V = hn::Vec<D>>
HWY_INLINE V FastExp2(D d, V y) {
  const hn::RebindToSigned<D> di;
  y = hn::Max(y, hn::Set(d, fast_math::kExp2Min));
  const V whole = hn::Floor(y);
  const V f = hn::Sub(y, whole);
  V p = hn::Set(d, fast_math::kExp2Poly[0]);
  for (int i = 1; i < 7; ++i) p = hn::MulAdd(p, f, hn::Set(d, fast_math::kExp2Poly[i]));
  const auto scale = hn::ShiftLeft<23>(hn::ConvertTo(di, whole));
  return hn::BitCast(d, hn::Add(hn::BitCast(di, p), scale));
}

// fast_math::inv_sqrt in lanes, bit for bit: sqrt, then a division, both correctly rounded, so
// a pixel gets the same bits whatever width shaded it. Before 636009e this was an
// integer-shift estimate and three Newton steps, 14 multiplies and subtractions on the FP pipes
// that the rest of a shading kernel also needs. Sqrt and division run on the divider instead,
// beside that work.
template <class D, class V = hn::Vec<D>>
HWY_INLINE V InvSqrt(D d, V x) {
  return hn::Div(hn::Set(d, 1.0f), hn::Sqrt(x));
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#endif  // include guard toggle
