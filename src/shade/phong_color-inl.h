// Blinn-Phong's colour from interpolated normals, per target (Highway "-inl.h"): shared by
// the phong and hybrid kernels and the pixel queue.
#if defined(FASTSHADE_SHADE_PHONG_COLOR_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FASTSHADE_SHADE_PHONG_COLOR_INL_H_
#undef FASTSHADE_SHADE_PHONG_COLOR_INL_H_
#else
#define FASTSHADE_SHADE_PHONG_COLOR_INL_H_
#endif

#include <hwy/highway.h>

#include "core/dot3-inl.h"
#include "light/brdf-inl.h"
#include "shade/span_kernels.h"
#include "shade/span_loop-inl.h"

HWY_BEFORE_NAMESPACE();
namespace fastshade {
namespace HWY_NAMESPACE {

// Scales (x, y, z) to unit length; a zero vector (or one too short for InvSqrt) becomes zero.
template <class D, class V = hn::Vec<D>>
HWY_INLINE void Normalize(D d, V& x, V& y, V& z) {
  const V len2 = Dot3<D>(x, y, z, x, y, z);
  const V inv = hn::IfThenElseZero(hn::Ge(len2, hn::Set(d, fast_math::kMinInvSqrtInput)), InvSqrt(d, len2));
  x = hn::Mul(x, inv);
  y = hn::Mul(y, inv);
  z = hn::Mul(z, inv);
}

template <class D>
struct ColorVecs {
  hn::Vec<D> r, g, b;
};

// One light's share of the colour, channel by channel: acc + colour × (kd diffuse + ks specular).
// Diffuse only (kSpecular = false) adds no ks × 0 term, so no cost (the sum is the same: x + 0 = x).
template <bool kSpecular, class D, class V = hn::Vec<D>>
HWY_INLINE void AddLight(D d, const MaterialConstants& m, const LightView& light, V diffuse, V specular,
                         ColorVecs<D>& acc) {
  auto channel = [&](V sum, int c) {
    const V kd_diffuse = hn::Mul(hn::Set(d, m.kd[c]), diffuse);
    const V lit = kSpecular ? hn::Add(kd_diffuse, hn::Mul(hn::Set(d, m.ks[c]), specular)) : kd_diffuse;
    return hn::Add(sum, hn::Mul(hn::Set(d, light.color[c]), lit));
  };
  acc.r = channel(acc.r, 0);
  acc.g = channel(acc.g, 1);
  acc.b = channel(acc.b, 2);
}

// Blinn-Phong at the lanes' pixels before quantisation; phong_color_scalar() is its twin.
// kSpecular = false: the diffuse-only colour (`auto`'s per-pixel diffuse path). kSplit (hybrid's
// split light, classify/segment_step.h): light split_light's diffuse term is left out and its
// unclamped N.L written to *split_n_dot_l.
template <bool kLocal, LobeKernel kLobe, bool kSpecular = true, bool kSplit = false, class D, class V = hn::Vec<D>>
HWY_INLINE ColorVecs<D> PhongColorFromNormal(D d, const PhongSpanInput& in, V nx, V ny, V nz,
                                             const LaneOffsets<D>& o, int split_light = -1,
                                             V* split_n_dot_l = nullptr);

template <bool kLocal, LobeKernel kLobe, bool kSpecular = true, bool kSplit = false, class D, class V = hn::Vec<D>>
HWY_INLINE ColorVecs<D> PhongColor(D d, const PhongSpanInput& in, const LaneOffsets<D>& o, int split_light = -1,
                                   V* split_n_dot_l = nullptr) {
  V nx = EvalPlane(d, in.n[0], o), ny = EvalPlane(d, in.n[1], o), nz = EvalPlane(d, in.n[2], o);
  Normalize(d, nx, ny, nz);
  return PhongColorFromNormal<kLocal, kLobe, kSpecular, kSplit>(d, in, nx, ny, nz, o, split_light, split_n_dot_l);
}

// Blinn-Phong for unit normals in lanes; phong_color_from_normal_scalar() is its twin.
template <bool kLocal, LobeKernel kLobe, bool kSpecular, bool kSplit, class D, class V>
HWY_INLINE ColorVecs<D> PhongColorFromNormal(D d, const PhongSpanInput& in, V nx, V ny, V nz,
                                             const LaneOffsets<D>& o, int split_light, V* split_n_dot_l) {
  const MaterialConstants& m = *in.material;
  const ShadeConstants& k = *in.shade;
  V vx, vy, vz;  // toward the eye (local viewer only)
  if constexpr (kLocal && kSpecular) {
    const V w = hn::Div(hn::Set(d, 1.0f), EvalPlane(d, in.inv_w, o));
    vx = hn::Neg(hn::Mul(EvalPlane(d, in.p[0], o), w));
    vy = hn::Neg(hn::Mul(EvalPlane(d, in.p[1], o), w));
    vz = hn::Neg(hn::Mul(EvalPlane(d, in.p[2], o), w));
    Normalize(d, vx, vy, vz);
  }
  ColorVecs<D> acc{hn::Set(d, k.ambient.r), hn::Set(d, k.ambient.g), hn::Set(d, k.ambient.b)};
  for (int index = 0; index < static_cast<int>(k.lights.size()); ++index) {
    const LightView& light = k.lights[index];
    const V lx = hn::Set(d, light.l_view.x), ly = hn::Set(d, light.l_view.y),
            lz = hn::Set(d, light.l_view.z);
    const V n_dot_l = Dot3<D>(nx, ny, nz, lx, ly, lz);
    V diffuse = hn::Max(n_dot_l, hn::Zero(d));
    if constexpr (kSplit) {
      if (index == split_light) {
        *split_n_dot_l = n_dot_l;
        diffuse = hn::Zero(d);
      }
    }
    V specular = hn::Zero(d);
    if constexpr (kSpecular) {
      V hx, hy, hz;
      if constexpr (kLocal) {
        hx = hn::Add(lx, vx);
        hy = hn::Add(ly, vy);
        hz = hn::Add(lz, vz);
        Normalize(d, hx, hy, hz);
      } else {
        hx = hn::Set(d, light.h_view.x);
        hy = hn::Set(d, light.h_view.y);
        hz = hn::Set(d, light.h_view.z);
      }
      specular = SpecularLobe<kLobe>(d, Dot3<D>(nx, ny, nz, hx, hy, hz), m.lobe);
    }
    AddLight<kSpecular>(d, m, light, diffuse, specular, acc);
  }
  return acc;
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#endif  // include guard toggle
