#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "classify/cone_batch.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <algorithm>

#include <hwy/highway.h>

#include "classify/cone_batch.h"
#include "core/dot3-inl.h"

HWY_BEFORE_NAMESPACE();
namespace fastshade {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// NormalCone::max_dot: cos(max(0, angle(axis, x) - half)).
template <class D, class V = hn::Vec<D>>
HWY_INLINE V ConeMaxDot(D d, V ca, V cos_half, V sin_half) {
  const V one = hn::Set(d, 1.0);
  const V off = hn::Add(hn::Mul(ca, cos_half),
                        hn::Mul(hn::Sqrt(hn::Max(hn::Zero(d), hn::Sub(one, hn::Mul(ca, ca)))), sin_half));
  return hn::IfThenElse(hn::Ge(ca, cos_half), one, off);
}

template <class D>
struct Decided {
  hn::Mask<D> gouraud, specular;
  hn::Vec<D> light;  // specular lanes: the first light a vertex term reaches the threshold for
};

// Classifier::classify up to its first exact bound, lane by lane. Comments name the scalar
// steps (classify/classifier.cpp, highlight_bound.cpp).
template <class D>
HWY_INLINE Decided<D> DecideLanes(D d, const ConeBatchTerms& t, const NormalsSoA& soa, std::size_t i) {
  using V = hn::Vec<D>;
  V n[9];
  for (int k = 0; k < 9; ++k) n[k] = hn::LoadU(d, soa.n[k] + i);
  const V zero = hn::Zero(d), one = hn::Set(d, 1.0);
  // NormalCone: axis = (n0 + n1 + n2) / |.|, cos_half = min axis . n_k.
  V axis[3];
  for (int c = 0; c < 3; ++c) axis[c] = hn::Add(hn::Add(n[c], n[3 + c]), n[6 + c]);
  const V len = hn::Sqrt(Dot3<D>(axis[0], axis[1], axis[2], axis[0], axis[1], axis[2]));
  auto settled = hn::Gt(len, zero);
  for (V& a : axis) a = hn::Div(a, len);
  auto dot_n = [&](int k, const V x[3]) { return Dot3<D>(n[3 * k], n[3 * k + 1], n[3 * k + 2], x[0], x[1], x[2]); };
  const V cos_half = hn::Min(hn::Min(dot_n(0, axis), dot_n(1, axis)), dot_n(2, axis));
  const V sin_half = hn::Sqrt(hn::Max(zero, hn::Sub(one, hn::Mul(cos_half, cos_half))));
  settled = hn::And(settled, hn::Gt(cos_half, zero));  // the cheap bounds need a narrow cone
  const double lights = static_cast<double>(t.lights.size());
  // Vertex terms: a vertex alone reaching the threshold means a highlight (the first light
  // in order that does is the one reported).
  auto specular = hn::Lt(one, zero);  // none
  V first_light = zero;
  for (std::size_t k = 0; k < t.lights.size(); ++k) {
    const ConeLight& light = t.lights[k];
    if (!(light.spec_weight > 0.0)) continue;
    const V h[3] = {hn::Set(d, light.h[0]), hn::Set(d, light.h[1]), hn::Set(d, light.h[2])};
    const V c_vertex = hn::Max(hn::Max(dot_n(0, h), dot_n(1, h)), dot_n(2, h));
    const auto reaches = hn::AndNot(specular, hn::Ge(c_vertex, hn::Set(d, light.cos_alone)));
    first_light = hn::IfThenElse(reaches, hn::Set(d, static_cast<double>(std::min<std::size_t>(k, 63))), first_light);
    specular = hn::Or(specular, reaches);
  }
  settled = hn::AndNot(specular, settled);
  // specular(cone): each light's term as a bound without pow; a term that may reach its share
  // of the threshold is the exact bounds' job.
  V spec = zero;
  for (const ConeLight& light : t.lights) {
    if (light.spec_weight <= 0.0) continue;
    const V h[3] = {hn::Set(d, light.h[0]), hn::Set(d, light.h[1]), hn::Set(d, light.h[2])};
    const V c_max = ConeMaxDot(d, Dot3<D>(axis[0], axis[1], axis[2], h[0], h[1], h[2]), cos_half, sin_half);
    settled = hn::And(settled, hn::Lt(c_max, hn::Set(d, light.cos_share)));
    const V term = hn::IfThenElse(hn::Le(c_max, hn::Set(d, light.cos_negligible)),
                                  hn::Set(d, t.negligible_share * t.spec_threshold),
                                  hn::Set(d, t.spec_threshold / lights));
    spec = hn::Add(spec, hn::IfThenElseZero(hn::Gt(c_max, zero), term));
  }
  settled = hn::And(settled, hn::Lt(spec, hn::Set(d, t.spec_threshold)));
  if (t.paper_rule) return {settled, specular, first_light};
  // diffuse(cone): min |sum lambda n| >= cos_half; diffuse_error per light.
  V diffuse = zero;
  for (const ConeLight& light : t.lights) {
    if (light.diffuse_weight <= 0.0) continue;
    const V l[3] = {hn::Set(d, light.l[0]), hn::Set(d, light.l[1]), hn::Set(d, light.l[2])};
    const V peak = ConeMaxDot(d, Dot3<D>(axis[0], axis[1], axis[2], l[0], l[1], l[2]), cos_half, sin_half);
    V lo = one, hi = hn::Set(d, -1.0);
    for (int k = 0; k < 3; ++k) {
      const V dl = dot_n(k, l);
      lo = hn::Min(lo, dl);
      hi = hn::Max(hi, dl);
    }
    const V peak01 = hn::Min(hn::Max(peak, zero), one);
    const V all_lit = hn::Mul(peak01, hn::Sub(one, cos_half));
    const V error = hn::IfThenElse(hn::Le(hi, zero), zero,
                                   hn::IfThenElse(hn::Ge(lo, zero), all_lit, hn::Max(hi, peak01)));
    diffuse = hn::Add(diffuse, hn::Mul(hn::Set(d, light.diffuse_weight), error));
  }
  return {hn::And(settled, hn::Le(hn::Add(diffuse, spec), hn::Set(d, t.gouraud_budget))), specular, first_light};
}

void DecidePathsBatch(const ConeBatchTerms& terms, const NormalsSoA& normals, std::size_t count,
                      ShadePath* path, uint8_t* light) {
  const hn::ScalableTag<double> d;
  const std::size_t lanes = hn::Lanes(d);
  constexpr std::size_t kMaxLanes = HWY_MAX_BYTES / sizeof(double);
  std::size_t i = 0;
  auto write = [&](const auto& decided, std::size_t n) {
    uint8_t gouraud[8] = {}, specular[8] = {};
    hn::StoreMaskBits(d, decided.gouraud, gouraud);
    hn::StoreMaskBits(d, decided.specular, specular);
    alignas(64) double first_light[kMaxLanes];
    hn::Store(decided.light, d, first_light);
    for (std::size_t k = 0; k < n; ++k) {
      const bool is_specular = (specular[k / 8] >> (k % 8)) & 1, is_gouraud = (gouraud[k / 8] >> (k % 8)) & 1;
      path[i + k] = is_specular ? ShadePath::Specular : is_gouraud ? ShadePath::GouraudDiffuse : ShadePath::Unclassified;
      light[i + k] = static_cast<uint8_t>(first_light[k]);
    }
  };
  for (; i + lanes <= count; i += lanes) write(DecideLanes(d, terms, normals, i), lanes);
  if (i == count) return;
  // The tail: copied into full vectors of a harmless triangle (all normals +z).
  alignas(64) double tail[9][kMaxLanes];
  NormalsSoA tail_soa;
  for (int k = 0; k < 9; ++k) {
    for (std::size_t j = 0; j < lanes; ++j) tail[k][j] = i + j < count ? normals.n[k][i + j] : (k % 3 == 2 ? 1.0 : 0.0);
    tail_soa.n[k] = tail[k];
  }
  write(DecideLanes(d, terms, tail_soa, 0), count - i);
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace fastshade {

HWY_EXPORT(DecidePathsBatch);

void decide_paths_batch(const ConeBatchTerms& terms, const NormalsSoA& normals, std::size_t count,
                        ShadePath* path, uint8_t* light) {
  HWY_DYNAMIC_DISPATCH(DecidePathsBatch)(terms, normals, count, path, light);
}

}  // namespace fastshade
#endif
