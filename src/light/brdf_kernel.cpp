// eval_brdf(): the SIMD BRDF kernels over arrays, on the chosen ISA (tests, brdf-table).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "light/brdf_kernel.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "core/dispatch.h"
#include "light/brdf-inl.h"
#include "light/brdf_variants.h"

HWY_BEFORE_NAMESPACE();
namespace fastshade {
namespace HWY_NAMESPACE {

template <BrdfKind K>
void EvalArray(const BrdfParams& p, const float* c, float* out, size_t count) {
  const hn::ScalableTag<float> d;
  const size_t lanes = hn::Lanes(d);
  size_t i = 0;
  for (; i + lanes <= count; i += lanes) hn::StoreU(Brdf<K>(d, hn::LoadU(d, c + i), p), d, out + i);
  if (i < count) {  // the tail through a padded copy: never read or write past the arrays
    alignas(64) float in_tail[HWY_MAX_BYTES / sizeof(float)] = {};
    alignas(64) float out_tail[HWY_MAX_BYTES / sizeof(float)];
    for (size_t j = i; j < count; ++j) in_tail[j - i] = c[j];
    hn::Store(Brdf<K>(d, hn::Load(d, in_tail), p), d, out_tail);
    for (size_t j = i; j < count; ++j) out[j] = out_tail[j - i];
  }
}

void EvalBrdf(const BrdfParams& p, const float* c, float* out, size_t count) {
  with_brdf_kind(p.kind, [&](auto kind) { EvalArray<decltype(kind)::value>(p, c, out, count); });
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace fastshade {
HWY_EXPORT(EvalBrdf);
void eval_brdf(SimdTarget simd, const BrdfParams& p, const float* c, float* out, std::size_t count) {
  FASTSHADE_DISPATCH(simd, EvalBrdf)(p, c, out, count);
}
}  // namespace fastshade
#endif
