// The attribute planes of one triangle at once, one quantity per double lane (per-target,
// Highway "-inl.h"): make_plane() in raster/planes.h is the scalar reference, bit for bit.
// Every shaded triangle of a dense mesh sets up four planes (three components over w and 1/w):
// that set-up was a fifth of the dragon's gouraud back end, three quarters of it the planes in
// scalar doubles (callgrind, docs/PERFORMANCE.md session 9).
#if defined(FASTSHADE_SHADE_PLANES_OVER_W_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FASTSHADE_SHADE_PLANES_OVER_W_INL_H_
#undef FASTSHADE_SHADE_PLANES_OVER_W_INL_H_
#else
#define FASTSHADE_SHADE_PLANES_OVER_W_INL_H_
#endif

#include <cstddef>

#include <glm/vec3.hpp>
#include <hwy/highway.h>

#include "raster/planes.h"

HWY_BEFORE_NAMESPACE();
namespace fastshade {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// out[c] = make_plane(b, q0, q1, q2) with q_i = (scale * v_i[c]) * inv_w_i in double for the
// components c = 0, 1, 2, and out[3] the plane of inv_w itself: the same double operations in
// the same order (no FMA: -ffp-contract=off), and min/max that keep the first of equal
// values as std::min({...}) and std::max({...}) do, so a signed zero cannot differ either.
// A scale of +-1 in float times v, as Phong's normals use it, is exact, so the product in
// double is the same value.
HWY_INLINE void PlanesOverW(const Barycentrics& b, const glm::vec3 v[3], double scale, const float inv_w[3],
                            Plane out[4]) {
  const hn::CappedTag<double, 4> d;
  const hn::Rebind<float, decltype(d)> df;
  constexpr std::size_t kQuantities = 4;
  alignas(32) const float component[3][kQuantities] = {
      {v[0].x, v[0].y, v[0].z, 1.0f}, {v[1].x, v[1].y, v[1].z, 1.0f}, {v[2].x, v[2].y, v[2].z, 1.0f}};
  alignas(32) const double lane_scale[kQuantities] = {scale, scale, scale, 1.0};
  alignas(32) float v0[kQuantities], gx[kQuantities], gy[kQuantities], lo[kQuantities], hi[kQuantities];
  for (std::size_t c = 0; c < kQuantities; c += hn::Lanes(d)) {
    hn::Vec<decltype(d)> q[3];
    for (int i = 0; i < 3; ++i)
      q[i] = hn::Mul(hn::Mul(hn::Load(d, lane_scale + c), hn::PromoteTo(d, hn::Load(df, component[i] + c))),
                     hn::Set(d, static_cast<double>(inv_w[i])));
    auto dot = [&](const double* lambda) {
      return hn::Add(hn::Add(hn::Mul(q[0], hn::Set(d, lambda[0])), hn::Mul(q[1], hn::Set(d, lambda[1]))),
                     hn::Mul(q[2], hn::Set(d, lambda[2])));
    };
    hn::Store(hn::DemoteTo(df, dot(b.at_anchor)), df, v0 + c);
    hn::Store(hn::DemoteTo(df, dot(b.d_dx)), df, gx + c);
    hn::Store(hn::DemoteTo(df, dot(b.d_dy)), df, gy + c);
    auto low = q[0], high = q[0];
    for (int i = 1; i < 3; ++i) {
      low = hn::IfThenElse(hn::Lt(q[i], low), q[i], low);
      high = hn::IfThenElse(hn::Lt(high, q[i]), q[i], high);
    }
    hn::Store(hn::DemoteTo(df, low), df, lo + c);
    hn::Store(hn::DemoteTo(df, high), df, hi + c);
  }
  for (std::size_t c = 0; c < kQuantities; ++c) out[c] = {v0[c], gx[c], gy[c], lo[c], hi[c]};
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#endif  // include guard toggle
