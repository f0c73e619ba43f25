// glm::dot's order, (x + y) + z, lane by lane (per-target, Highway "-inl.h"): the SIMD kernels'
// dot products, which their scalar twins compute with glm::dot.
#if defined(FASTSHADE_CORE_DOT3_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FASTSHADE_CORE_DOT3_INL_H_
#undef FASTSHADE_CORE_DOT3_INL_H_
#else
#define FASTSHADE_CORE_DOT3_INL_H_
#endif

#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace fastshade {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

template <class D, class V = hn::Vec<D>>
HWY_INLINE V Dot3(V ax, V ay, V az, V bx, V by, V bz) {
  return hn::Add(hn::Add(hn::Mul(ax, bx), hn::Mul(ay, by)), hn::Mul(az, bz));
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#endif  // include guard toggle
