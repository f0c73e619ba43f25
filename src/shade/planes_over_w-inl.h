// The attribute planes of one triangle at once, one quantity per double lane (per-target,
// Highway "-inl.h"): make_plane() in raster/planes.h is the scalar reference, bit for bit.
// Every shaded triangle of a dense mesh sets up four planes (three components over w and 1/w):
// that set-up was a fifth of the dragon's gouraud back end, three quarters of it the planes in
// scalar doubles (callgrind; a930516).
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

// Lanes c, c + 1, ... of (v.x, v.y, v.z, 1), built in registers: stored as four floats and
// loaded as one vector, they waited on a store that cannot be forwarded (perf; d0aa0e4).
template <class DF>
HWY_INLINE hn::Vec<DF> ComponentsOf(DF df, const glm::vec3& v, std::size_t c) {
  const auto lane = hn::Iota(df, static_cast<float>(c));
  auto out = hn::Set(df, 1.0f);
  out = hn::IfThenElse(hn::Eq(lane, hn::Set(df, 2.0f)), hn::Set(df, v.z), out);
  out = hn::IfThenElse(hn::Eq(lane, hn::Set(df, 1.0f)), hn::Set(df, v.y), out);
  return hn::IfThenElse(hn::Eq(lane, hn::Zero(df)), hn::Set(df, v.x), out);
}

// components[c] = make_plane(b, q0, q1, q2) with q_i = (scale * v_i[c]) * inv_w_i in double
// for c = 0, 1, 2, and one_over_w the plane of inv_w itself: the same double operations in the
// same order (no FMA: -ffp-contract=off), and min/max that keep the first of equal values as
// std::min({...}) and std::max({...}) do, so a signed zero cannot differ either. A scale of +-1
// in float times v, as Phong's normals use it, is exact, so the product in double is the same
// value. The planes are written where the caller keeps them: a copy of a plane array written
// field by field is another load that store forwarding cannot serve.
HWY_INLINE void PlanesOverW(const Barycentrics& b, const glm::vec3 v[3], double scale, const float inv_w[3],
                            Plane components[3], Plane& one_over_w) {
  const hn::CappedTag<double, 4> d;
  const hn::Rebind<float, decltype(d)> df;
  constexpr std::size_t kQuantities = 4;
  alignas(32) float v0[kQuantities], gx[kQuantities], gy[kQuantities], lo[kQuantities], hi[kQuantities];
  for (std::size_t c = 0; c < kQuantities; c += hn::Lanes(d)) {
    const auto lane_scale = hn::IfThenElse(hn::Lt(hn::Iota(d, static_cast<double>(c)), hn::Set(d, 3.0)),
                                           hn::Set(d, scale), hn::Set(d, 1.0));
    hn::Vec<decltype(d)> q[3];
    for (int i = 0; i < 3; ++i)
      q[i] = hn::Mul(hn::Mul(lane_scale, hn::PromoteTo(d, ComponentsOf(df, v[i], c))),
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
  for (std::size_t c = 0; c < 3; ++c) components[c] = {v0[c], gx[c], gy[c], lo[c], hi[c]};
  one_over_w = {v0[3], gx[3], gy[3], lo[3], hi[3]};
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#endif  // include guard toggle
