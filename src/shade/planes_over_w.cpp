#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shade/planes_over_w.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "core/dispatch.h"
#include "shade/planes_over_w-inl.h"
#include "shade/planes_over_w_testing.h"

HWY_BEFORE_NAMESPACE();
namespace fastshade {
namespace HWY_NAMESPACE {

void PlanesOverWFn(const Barycentrics& b, const glm::vec3* v, double scale, const float* inv_w, Plane* out) {
  PlanesOverW(b, v, scale, inv_w, out, out[3]);
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace fastshade {

HWY_EXPORT(PlanesOverWFn);

void planes_over_w(SimdTarget simd, const Barycentrics& b, const glm::vec3 v[3], double scale, const float inv_w[3], Plane out[4]) {
  FASTSHADE_DISPATCH(simd, PlanesOverWFn)(b, v, scale, inv_w, out);
}

}  // namespace fastshade
#endif
