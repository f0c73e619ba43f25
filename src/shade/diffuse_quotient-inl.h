// The diffuse quotient (shade/diffuse_quotient.h) in lanes, per target (Highway "-inl.h"):
// diffuse_quotient_color_scalar() is its twin, the same float operations in the same order.
#if defined(FASTSHADE_SHADE_DIFFUSE_QUOTIENT_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FASTSHADE_SHADE_DIFFUSE_QUOTIENT_INL_H_
#undef FASTSHADE_SHADE_DIFFUSE_QUOTIENT_INL_H_
#else
#define FASTSHADE_SHADE_DIFFUSE_QUOTIENT_INL_H_
#endif

#include <hwy/highway.h>

#include "shade/diffuse_quotient.h"
#include "light/fast_math-inl.h"
#include "shade/phong_color-inl.h"
#include "shade/span_loop-inl.h"

HWY_BEFORE_NAMESPACE();
namespace fastshade {
namespace HWY_NAMESPACE {

template <class D>
HWY_INLINE ColorVecs<D> DiffuseQuotientColor(D d, const PhongSpanInput& in, const DiffuseQuotient& dq,
                                             const LaneOffsets<D>& o) {
  using V = hn::Vec<D>;
  const MaterialConstants& m = *in.material;
  const ShadeConstants& k = *in.shade;
  const V x = hn::Sub(hn::Add(o.block_dx, o.k), hn::Set(d, dq.cx)), y = hn::Sub(o.dy, hn::Set(d, dq.cy));
  const V inner = hn::Add(hn::Add(hn::Set(d, dq.q[1]), hn::Mul(hn::Set(d, dq.q[2]), x)), hn::Mul(hn::Set(d, dq.q[3]), y));
  const V m2 = hn::Add(hn::Add(hn::Set(d, dq.q[0]), hn::Mul(x, inner)),
                       hn::Mul(y, hn::Add(hn::Set(d, dq.q[4]), hn::Mul(hn::Set(d, dq.q[5]), y))));
  const V inv = hn::IfThenElseZero(hn::Ge(m2, hn::Set(d, fast_math::kMinInvSqrtInput)), InvSqrt(d, m2));
  ColorVecs<D> acc{hn::Set(d, k.ambient.r), hn::Set(d, k.ambient.g), hn::Set(d, k.ambient.b)};
  for (int i = 0; i < dq.lights; ++i) {
    const V l_dot_m = hn::Add(hn::Add(hn::Set(d, dq.l[i][0]), hn::Mul(hn::Set(d, dq.l[i][1]), x)),
                              hn::Mul(hn::Set(d, dq.l[i][2]), y));
    const V diffuse = hn::Max(hn::Mul(l_dot_m, inv), hn::Zero(d));
    AddLight<false>(d, m, k.lights[i], diffuse, hn::Zero(d), acc);
  }
  return acc;
}

// The quotient's pixels, quantised and packed (PhongShade's counterpart).
template <class D>
HWY_INLINE auto DiffuseQuotientShade(D d, const PhongSpanInput& in, const DiffuseQuotient& dq,
                                     const LaneOffsets<D>& o) {
  const ColorVecs<D> c = DiffuseQuotientColor(d, in, dq, o);
  return PackRGBA(d, c.r, c.g, c.b, in.shade->srgb);
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#endif  // include guard toggle
