#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "classify/cone_batch.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <algorithm>
#include <bit>
#include <cmath>

#include <hwy/highway.h>

#include "classify/classify_limits.h"
#include "classify/cone_batch.h"
#include "core/dispatch.h"
#include "core/dot3-inl.h"
#include "core/mask_bits-inl.h"

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

// glm's dvec3 operations lane by lane, in glm's order (classify/highlight_bound.cpp's exact
// bounds are their scalar twins).
template <class D>
struct Vec3 {
  hn::Vec<D> x, y, z;
};
template <class D>
HWY_INLINE hn::Vec<D> Dot(D, const Vec3<D>& a, const Vec3<D>& b) {
  return Dot3<D>(a.x, a.y, a.z, b.x, b.y, b.z);
}
template <class D>
HWY_INLINE Vec3<D> Cross(const Vec3<D>& a, const Vec3<D>& b) {
  return {hn::Sub(hn::Mul(a.y, b.z), hn::Mul(b.y, a.z)), hn::Sub(hn::Mul(a.z, b.x), hn::Mul(b.z, a.x)),
          hn::Sub(hn::Mul(a.x, b.y), hn::Mul(b.x, a.y))};
}
template <class D>
HWY_INLINE Vec3<D> Minus(const Vec3<D>& a, const Vec3<D>& b) {
  return {hn::Sub(a.x, b.x), hn::Sub(a.y, b.y), hn::Sub(a.z, b.z)};
}
template <class D>
HWY_INLINE Vec3<D> Scaled(hn::Vec<D> s, const Vec3<D>& a) {
  return {hn::Mul(s, a.x), hn::Mul(s, a.y), hn::Mul(s, a.z)};
}
template <class D>
HWY_INLINE hn::Vec<D> Length(D d, const Vec3<D>& a) {
  return hn::Sqrt(Dot(d, a, a));
}

// arc_max, inside_cone, max_dot_over_triangle and min_length_over_triangle, lane by lane.
// std::max/min and hn::Max/Min differ only in which zero they return for +0 and -0, which no
// comparison below can tell apart.
template <class D, class V = hn::Vec<D>>
HWY_INLINE V ArcMax(D d, const Vec3<D>& a, const Vec3<D>& b, const Vec3<D>& x) {
  const V ends = hn::Max(Dot(d, a, x), Dot(d, b, x));
  const Vec3<D> k = Cross(a, b);
  const V k_len2 = Dot(d, k, k);
  const auto on_arc = hn::And(hn::And(hn::Gt(k_len2, hn::Zero(d)), hn::Gt(Dot(d, Cross(a, x), k), hn::Zero(d))),
                              hn::Gt(Dot(d, Cross(x, b), k), hn::Zero(d)));
  const Vec3<D> x_k = Cross(x, k);
  return hn::IfThenElse(on_arc, hn::Max(ends, hn::Sqrt(hn::Div(Dot(d, x_k, x_k), k_len2))), ends);
}
template <class D, class V = hn::Vec<D>>
HWY_INLINE V MaxDotOverTriangle(D d, const Vec3<D> n[3], const Vec3<D>& x) {
  const V volume = Dot(d, n[0], Cross(n[1], n[2]));
  auto inside = hn::Ne(volume, hn::Zero(d));
  V best = hn::Set(d, -1.0);
  for (int i = 0; i < 3; ++i) {
    const V mu = Dot(d, x, Cross(n[(i + 1) % 3], n[(i + 2) % 3]));
    inside = hn::AndNot(hn::Lt(hn::Mul(mu, volume), hn::Zero(d)), inside);
    best = hn::Max(best, ArcMax(d, n[i], n[(i + 1) % 3], x));
  }
  return hn::IfThenElse(inside, hn::Set(d, 1.0), hn::Min(best, hn::Set(d, 1.0)));
}
template <class D, class V = hn::Vec<D>>
HWY_INLINE V MinLengthOverTriangle(D d, const Vec3<D> n[3]) {
  const V zero = hn::Zero(d);
  V best = hn::Set(d, 1e300);
  for (int i = 0; i < 3; ++i) {
    const Vec3<D>& a = n[i];
    const Vec3<D> ab = Minus(n[(i + 1) % 3], a);
    const V len2 = Dot(d, ab, ab);
    const V t = hn::IfThenElseZero(hn::Gt(len2, zero),
                                   hn::Min(hn::Max(hn::Div(hn::Neg(Dot(d, a, ab)), len2), zero), hn::Set(d, 1.0)));
    const Vec3<D> ta = Scaled(t, ab);
    best = hn::Min(best, Length(d, Vec3<D>{hn::Add(a.x, ta.x), hn::Add(a.y, ta.y), hn::Add(a.z, ta.z)}));
  }
  const Vec3<D> normal = Cross(Minus(n[1], n[0]), Minus(n[2], n[0]));
  const V normal2 = Dot(d, normal, normal);
  const Vec3<D> p = Scaled(hn::Div(Dot(d, n[0], normal), normal2), normal);
  auto inside = hn::Gt(normal2, zero);
  for (int i = 0; i < 3; ++i)
    inside = hn::And(inside, hn::Ge(Dot(d, Cross(Minus(n[(i + 1) % 3], n[i]), Minus(p, n[i])), normal), zero));
  return hn::IfThenElse(inside, hn::Min(best, Length(d, p)), best);
}

// classifier.cpp diffuse_error: Gouraud's error bound of one light's diffuse term.
template <class D, class V = hn::Vec<D>>
HWY_INLINE V DiffuseError(D d, const Vec3<D> n[3], const Vec3<D>& l, V peak, V min_len) {
  const V zero = hn::Zero(d), one = hn::Set(d, 1.0);
  V lo = one, hi = hn::Set(d, -1.0);
  for (int k = 0; k < 3; ++k) {
    const V dl = Dot(d, n[k], l);
    lo = hn::Min(lo, dl);
    hi = hn::Max(hi, dl);
  }
  const V peak01 = hn::Min(hn::Max(peak, zero), one);
  const V all_lit = hn::Mul(peak01, hn::Sub(one, min_len));
  return hn::IfThenElse(hn::Le(hi, zero), zero, hn::IfThenElse(hn::Ge(lo, zero), all_lit, hn::Max(hi, peak01)));
}

template <class D>
struct Decided {
  hn::Mask<D> gouraud, specular, pixel_diffuse;
  hn::Vec<D> lights;  // specular lanes: classify()'s lights_with_highlight, as a double
};

// The cheap look's result: lanes it settles, and for the others (`exact`) what the exact look
// continues from. cheap: the cone is narrow enough for its bounds (NormalCone::cos_half > 0).
template <class D>
struct ConeLook {
  Decided<D> decided;
  hn::Mask<D> exact;
  hn::Vec<D> spec_cone, diffuse_cone, cheap;  // cheap: 1 or 0
};

template <class D>
HWY_INLINE void LoadNormals(D d, const NormalsSoA& soa, std::size_t i, Vec3<D> n[3]) {
  for (int k = 0; k < 3; ++k)
    n[k] = {hn::LoadU(d, soa.n[3 * k] + i), hn::LoadU(d, soa.n[3 * k + 1] + i), hn::LoadU(d, soa.n[3 * k + 2] + i)};
}


// Classifier::classify up to its first exact bound, lane by lane: the vertex terms, then the
// normal cone's cheap bounds. Comments name the scalar steps (classify/classifier.cpp,
// highlight_bound.cpp).
template <class D>
HWY_INLINE ConeLook<D> ConeLanes(D d, const ConeBatchTerms& t, const Vec3<D> n[3]) {
  using V = hn::Vec<D>;
  const V zero = hn::Zero(d), one = hn::Set(d, 1.0);
  const auto none = hn::Lt(one, zero);
  // NormalCone: axis = (n0 + n1 + n2) / |.|, cos_half = min axis . n_k; the cheap bounds need
  // a cone narrower than a hemisphere.
  Vec3<D> axis{hn::Add(hn::Add(n[0].x, n[1].x), n[2].x), hn::Add(hn::Add(n[0].y, n[1].y), n[2].y),
               hn::Add(hn::Add(n[0].z, n[1].z), n[2].z)};
  const V len = Length(d, axis);
  axis = {hn::Div(axis.x, len), hn::Div(axis.y, len), hn::Div(axis.z, len)};
  const V cos_half = hn::Min(hn::Min(Dot(d, n[0], axis), Dot(d, n[1], axis)), Dot(d, n[2], axis));
  const V sin_half = hn::Sqrt(hn::Max(zero, hn::Sub(one, hn::Mul(cos_half, cos_half))));
  const auto cheap = hn::And(hn::Gt(len, zero), hn::Gt(cos_half, zero));
  const double lights = static_cast<double>(t.lights.size());
  // Vertex terms: a vertex alone reaching the threshold means a highlight (the first light
  // in order that does is the one reported).
  auto vertex_specular = none;
  V vertex_light = zero;
  for (std::size_t k = 0; k < t.lights.size(); ++k) {
    const ConeLight& light = t.lights[k];
    if (!(light.spec_weight > 0.0)) continue;
    const Vec3<D> h{hn::Set(d, light.h[0]), hn::Set(d, light.h[1]), hn::Set(d, light.h[2])};
    const V c_vertex = hn::Max(hn::Max(Dot(d, n[0], h), Dot(d, n[1], h)), Dot(d, n[2], h));
    const auto reaches = hn::AndNot(vertex_specular, hn::Ge(c_vertex, hn::Set(d, light.cos_alone)));
    vertex_light = hn::IfThenElse(reaches, hn::Set(d, std::ldexp(1.0, static_cast<int>(std::min<std::size_t>(k, 63)))),
                                  vertex_light);
    vertex_specular = hn::Or(vertex_specular, reaches);
  }
  // specular(cone): each light's term as a bound without pow; one that may reach its share
  // of the threshold counts as infinite (the exact bound decides).
  V spec_cone = zero;
  for (const ConeLight& light : t.lights) {
    if (light.spec_weight <= 0.0) continue;
    const Vec3<D> h{hn::Set(d, light.h[0]), hn::Set(d, light.h[1]), hn::Set(d, light.h[2])};
    const V c_max = ConeMaxDot(d, Dot(d, axis, h), cos_half, sin_half);
    const V below_share = hn::IfThenElse(hn::Le(c_max, hn::Set(d, light.cos_negligible)),
                                         hn::Set(d, t.negligible_share * t.spec_threshold),
                                         hn::Set(d, t.spec_threshold / lights));
    const V term = hn::IfThenElse(hn::Lt(c_max, hn::Set(d, light.cos_share)), below_share, hn::Set(d, HUGE_VAL));
    spec_cone = hn::Add(spec_cone, hn::IfThenElseZero(hn::Gt(c_max, zero), term));
  }
  // diffuse(cone): min |sum lambda n| >= cos_half; diffuse_error per light.
  V diffuse_cone = zero;
  for (const ConeLight& light : t.lights) {
    if (light.diffuse_weight <= 0.0) continue;
    const Vec3<D> l{hn::Set(d, light.l[0]), hn::Set(d, light.l[1]), hn::Set(d, light.l[2])};
    const V peak = ConeMaxDot(d, Dot(d, axis, l), cos_half, sin_half);
    diffuse_cone = hn::Add(diffuse_cone, hn::Mul(hn::Set(d, light.diffuse_weight), DiffuseError(d, n, l, peak, cos_half)));
  }
  const auto cone_below = hn::And(cheap, hn::Lt(spec_cone, hn::Set(d, t.spec_threshold)));
  const auto within =
      t.paper_rule ? cone_below : hn::And(cone_below, hn::Le(hn::Add(diffuse_cone, spec_cone), hn::Set(d, t.gouraud_budget)));
  const auto settled = hn::Or(vertex_specular, within);
  return {{hn::AndNot(vertex_specular, within), vertex_specular, none, vertex_light},
          hn::AndNot(settled, hn::Not(none)), spec_cone, diffuse_cone, hn::IfThenElseZero(cheap, one)};
}

// The exact specular bound of classify() (Classifier::specular without the cone): per light
// the edge maxima and interior test of N.H, then the term, with std::pow (scalar, so that its
// bits are classify()'s) in the lanes of `want` where it is not negligible.
template <class D, class V = hn::Vec<D>>
HWY_INLINE V ExactSpecular(D d, const ConeBatchTerms& t, const Vec3<D> n[3], hn::Mask<D> want, V& lights) {
  constexpr std::size_t kLanes = HWY_MAX_BYTES / sizeof(double);
  V spec = hn::Zero(d);
  lights = hn::Zero(d);
  for (std::size_t k = 0; k < t.lights.size(); ++k) {
    const ConeLight& light = t.lights[k];
    if (!(light.spec_weight > 0.0)) continue;
    const V c = MaxDotOverTriangle(d, n, Vec3<D>{hn::Set(d, light.h[0]), hn::Set(d, light.h[1]), hn::Set(d, light.h[2])});
    V term = hn::IfThenZeroElse(hn::Le(c, hn::Zero(d)), hn::Set(d, t.negligible_share * t.spec_threshold));
    const auto powed = hn::And(want, hn::Gt(c, hn::Set(d, light.cos_negligible)));
    if (!hn::AllFalse(d, powed)) {
      alignas(64) double value[kLanes];
      hn::Store(c, d, value);
      for (uint64_t lanes = MaskBits(d, powed); lanes; lanes &= lanes - 1) {
        const int j = std::countr_zero(lanes);
        value[j] = light.spec_weight * std::pow(std::min(value[j], 1.0), t.shininess);
      }
      term = hn::IfThenElse(powed, hn::Load(d, value), term);
    }
    spec = hn::Add(spec, term);
    lights = hn::Add(lights, hn::IfThenElseZero(hn::Ge(term, hn::Set(d, t.spec_threshold)),
                                                hn::Set(d, std::ldexp(1.0, static_cast<int>(k)))));
  }
  return spec;
}

// The exact diffuse bound of classify() (Classifier::diffuse without the cone).
template <class D, class V = hn::Vec<D>>
HWY_INLINE V ExactDiffuse(D d, const ConeBatchTerms& t, const Vec3<D> n[3]) {
  const V min_len = MinLengthOverTriangle(d, n);
  V diffuse = hn::Zero(d);
  for (const ConeLight& light : t.lights) {
    if (!(light.diffuse_weight > 0.0)) continue;
    const Vec3<D> l{hn::Set(d, light.l[0]), hn::Set(d, light.l[1]), hn::Set(d, light.l[2])};
    diffuse = hn::Add(diffuse, hn::Mul(hn::Set(d, light.diffuse_weight),
                                       DiffuseError(d, n, l, MaxDotOverTriangle(d, n, l), min_len)));
  }
  return diffuse;
}

// The rest of classify() for lanes the cheap look left (`want`), in its order: the exact
// specular bound where the cone had none (or one at the threshold), then both exact bounds
// where the cone's sum exceeds the budget.
template <class D, class V = hn::Vec<D>>
HWY_INLINE Decided<D> ExactLanes(D d, const ConeBatchTerms& t, const Vec3<D> n[3], hn::Mask<D> want, V spec_cone,
                                 V diffuse_cone, V cheap_flag) {
  const auto none = hn::Lt(hn::Set(d, 1.0), hn::Zero(d));
  const V threshold = hn::Set(d, t.spec_threshold), budget = hn::Set(d, t.gouraud_budget);
  const auto cheap = hn::Gt(cheap_flag, hn::Zero(d));
  V lights;
  const V spec_exact = ExactSpecular(d, t, n, want, lights);
  const V spec = hn::IfThenElse(hn::And(cheap, hn::Lt(spec_cone, threshold)), spec_cone, spec_exact);
  const auto specular = hn::Ge(spec, threshold);
  if (t.paper_rule) return {hn::Not(specular), specular, none, lights};
  // Only lanes whose diffuse bound classify() takes exactly pay for it.
  const V diffuse = hn::IfThenElse(cheap, diffuse_cone, hn::Set(d, HUGE_VAL));
  const auto redo = hn::Gt(hn::Add(diffuse, spec), budget);  // also every lane without a cone
  const auto need_diffuse = hn::AndNot(specular, hn::And(want, redo));
  const V diffuse_exact = hn::AllFalse(d, need_diffuse) ? hn::Zero(d) : ExactDiffuse(d, t, n);
  const V spec_final = hn::IfThenElse(redo, spec_exact, spec);
  const V diffuse_final = hn::IfThenElse(redo, diffuse_exact, diffuse);
  const auto within = hn::Le(hn::Add(diffuse_final, spec_final), budget);
  return {hn::AndNot(specular, within), specular, hn::AndNot(specular, hn::Not(within)), lights};
}

// Lanes past a batch's end hold a harmless triangle: all three normals +z.
constexpr double kPadNormals[9] = {0, 0, 1, 0, 0, 1, 0, 0, 1};

void DecidePathsBatch(const ConeBatchTerms& terms, const NormalsSoA& normals, std::size_t count,
                      ShadePath* path, uint64_t* lights) {
  using D = hn::ScalableTag<double>;
  const D d;
  const std::size_t lanes = hn::Lanes(d);
  constexpr std::size_t kMaxLanes = HWY_MAX_BYTES / sizeof(double);
  auto write = [&](const Decided<D>& decided, hn::Mask<D> valid, auto index_of) {
    const uint64_t gouraud = MaskBits(d, decided.gouraud), specular = MaskBits(d, decided.specular),
                   pixel = MaskBits(d, decided.pixel_diffuse);
    alignas(64) double light_bits[kMaxLanes];
    hn::Store(decided.lights, d, light_bits);
    for (uint64_t in = MaskBits(d, valid); in; in &= in - 1) {
      const int k = std::countr_zero(in);
      auto bit = [&](uint64_t bits) { return (bits >> k) & 1; };
      const std::size_t t = index_of(k);
      path[t] = bit(specular) ? ShadePath::Specular
                : bit(gouraud) ? ShadePath::GouraudDiffuse
                : bit(pixel)   ? ShadePath::PixelDiffuse
                               : ShadePath::Unclassified;
      lights[t] = static_cast<uint64_t>(light_bits[k]);
    }
  };
  constexpr std::size_t kBlock = limits::kConeExactBlock;
  alignas(64) double rest_n[9][kBlock + kMaxLanes], rest_spec[kBlock + kMaxLanes], rest_diffuse[kBlock + kMaxLanes],
      rest_cheap[kBlock + kMaxLanes];
  uint32_t rest_index[kBlock];
  alignas(64) double tail[9][kMaxLanes];
  NormalsSoA tail_soa, rest_soa;
  for (int k = 0; k < 9; ++k) tail_soa.n[k] = tail[k], rest_soa.n[k] = rest_n[k];
  const bool exact_lanes = terms.lights.size() <= limits::kMaxExactLaneLights;
  for (std::size_t block = 0; block < count; block += kBlock) {
    const std::size_t block_end = std::min(count, block + kBlock);
    std::size_t rest = 0;
    for (std::size_t i = block; i < block_end; i += lanes) {
      const std::size_t n_valid = std::min(lanes, block_end - i);
      const NormalsSoA* soa = &normals;
      std::size_t at = i;
      if (n_valid < lanes) {  // the tail: copied into a full vector, padded
        for (int k = 0; k < 9; ++k)
          for (std::size_t j = 0; j < lanes; ++j) tail[k][j] = j < n_valid ? normals.n[k][i + j] : kPadNormals[k];
        soa = &tail_soa;
        at = 0;
      }
      Vec3<D> n[3];
      LoadNormals(d, *soa, at, n);
      const ConeLook<D> look = ConeLanes(d, terms, n);
      const auto valid = hn::FirstN(d, n_valid);
      write(look.decided, valid, [&](std::size_t k) { return i + k; });
      const auto left = hn::And(valid, look.exact);
      if (!exact_lanes || hn::AllFalse(d, left)) continue;
      alignas(64) double spec[kMaxLanes], diffuse[kMaxLanes], cheap[kMaxLanes];
      hn::Store(look.spec_cone, d, spec);
      hn::Store(look.diffuse_cone, d, diffuse);
      hn::Store(look.cheap, d, cheap);
      for (uint64_t bits = MaskBits(d, left); bits; bits &= bits - 1) {
        const int k = std::countr_zero(bits);
        for (int c = 0; c < 9; ++c) rest_n[c][rest] = soa->n[c][at + k];
        rest_spec[rest] = spec[k], rest_diffuse[rest] = diffuse[k], rest_cheap[rest] = cheap[k];
        rest_index[rest++] = static_cast<uint32_t>(i + k);
      }
    }
    for (std::size_t j = rest; j % lanes != 0; ++j) {  // pad to whole vectors, lanes masked off
      for (int c = 0; c < 9; ++c) rest_n[c][j] = kPadNormals[c];
      rest_spec[j] = rest_diffuse[j] = 0.0, rest_cheap[j] = 1.0;
    }
    for (std::size_t j = 0; j < rest; j += lanes) {
      Vec3<D> n[3];
      LoadNormals(d, rest_soa, j, n);
      const auto valid = hn::FirstN(d, rest - j);
      write(ExactLanes(d, terms, n, valid, hn::Load(d, rest_spec + j), hn::Load(d, rest_diffuse + j), hn::Load(d, rest_cheap + j)),
            valid, [&](std::size_t k) { return rest_index[j + k]; });
    }
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace fastshade {

HWY_EXPORT(DecidePathsBatch);

void decide_paths_batch(SimdTarget simd, const ConeBatchTerms& terms, const NormalsSoA& normals, std::size_t count,
                        ShadePath* path, uint64_t* lights) {
  FASTSHADE_DISPATCH(simd, DecidePathsBatch)(terms, normals, count, path, lights);
}

}  // namespace fastshade
#endif
