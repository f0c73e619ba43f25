// Per-target helpers shared by the SIMD shading kernels (Highway's "-inl.h" convention: this
// file is re-included once per target by every kernel's foreach_target pass).
#if defined(FASTSHADE_SHADE_SPAN_LOOP_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FASTSHADE_SHADE_SPAN_LOOP_INL_H_
#undef FASTSHADE_SHADE_SPAN_LOOP_INL_H_
#else
#define FASTSHADE_SHADE_SPAN_LOOP_INL_H_
#endif

#include <hwy/contrib/math/math-inl.h>
#include <hwy/highway.h>

#include "raster/triangle_in_tile.h"
#include "shade/method.h"

HWY_BEFORE_NAMESPACE();
namespace fastshade {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DF = hn::ScalableTag<float>;
using DI = hn::RebindToSigned<DF>;
using DU = hn::RebindToUnsigned<DF>;
using VF = hn::Vec<DF>;
using MF = hn::Mask<DF>;

// row + gx * dx, clamped to the plane's vertex range: the same float operations, in the same
// order, as plane_at() in raster/planes.h.
HWY_INLINE VF EvalPlane(DF d, const Plane& p, float row, VF dx) {
  const VF v = hn::Add(hn::Set(d, row), hn::Mul(hn::Set(d, p.gx), dx));
  return hn::Min(hn::Max(v, hn::Set(d, p.lo)), hn::Set(d, p.hi));
}

// max(c, 0)^n as exp(n log c), zero where c <= 0. The exponent is held above -103 so Exp
// stays in range; exp(-103) is below the smallest float step anyway.
HWY_INLINE VF SpecularPower(DF d, VF c, float n) {
  const VF c1 = hn::Min(c, hn::Set(d, 1.0f));
  const MF positive = hn::Gt(c1, hn::Zero(d));
  const VF safe = hn::IfThenElse(positive, c1, hn::Set(d, 1.0f));
  const VF e = hn::Max(hn::Mul(hn::Set(d, n), hn::Log(d, safe)), hn::Set(d, -103.0f));
  return hn::IfThenElseZero(positive, hn::Exp(d, e));
}

// clamp to [0, 1] (NaN becomes 0: x86 max returns its second operand), optional sRGB curve,
// floor(255 v + 0.5), as quantize() in shade/lighting.h.
template <bool kSrgb>
HWY_INLINE hn::Vec<DU> Quantize(DF d, VF v) {
  v = hn::Min(hn::Max(v, hn::Zero(d)), hn::Set(d, 1.0f));
  if constexpr (kSrgb) {
    const VF linear = hn::Mul(v, hn::Set(d, 12.92f));
    const VF safe = hn::Max(v, hn::Set(d, 1e-30f));
    const VF curve = hn::Sub(
        hn::Mul(hn::Set(d, 1.055f), hn::Exp(d, hn::Mul(hn::Log(d, safe), hn::Set(d, 1.0f / 2.4f)))),
        hn::Set(d, 0.055f));
    v = hn::IfThenElse(hn::Le(v, hn::Set(d, 0.0031308f)), linear, curve);
  }
  const VF scaled = hn::Floor(hn::Add(hn::Mul(v, hn::Set(d, 255.0f)), hn::Set(d, 0.5f)));
  return hn::BitCast(DU(), hn::ConvertTo(DI(), scaled));
}

template <bool kSrgb>
HWY_INLINE hn::Vec<DU> PackRGBA(DF d, VF r, VF g, VF b) {
  const DU du;
  const auto ri = Quantize<kSrgb>(d, r), gi = Quantize<kSrgb>(d, g), bi = Quantize<kSrgb>(d, b);
  return hn::Or(hn::Or(ri, hn::ShiftLeft<8>(gi)),
                hn::Or(hn::ShiftLeft<16>(bi), hn::Set(du, 0xFF000000u)));
}

// Walks one covered row span a vector at a time: depth test against the tile, then
// shade(dx, pass) for lanes that pass, then blended stores of colour and depth. dx is the
// lanes' pixel offset from the triangle's anchor, as float.
template <typename ShadeFn>
HWY_INLINE void ShadeSpan(const TriangleInTile& tri, int py, int x0, int x1, const TileTarget& tt,
                          ShadeFn&& shade) {
  const DF d;
  const DI di;
  const DU du;
  const int lanes = static_cast<int>(hn::Lanes(d));
  const float depth_row = row_value(tri.depth, tri.bary, py);
  float* depth = tt.depth + (py - tt.y_origin) * tt.stride - tt.x_origin;
  uint32_t* color = tt.color + (py - tt.y_origin) * tt.stride - tt.x_origin;
  const auto iota = hn::Iota(di, 0);
  for (int x = x0; x <= x1; x += lanes) {
    const auto xi = hn::Add(hn::Set(di, x), iota);
    const MF inside = hn::RebindMask(d, hn::Lt(xi, hn::Set(di, x1 + 1)));
    const VF dx = hn::ConvertTo(d, hn::Sub(xi, hn::Set(di, tri.bary.ax)));
    const VF z = EvalPlane(d, tri.depth, depth_row, dx);
    const MF pass = hn::And(inside, hn::Lt(z, hn::LoadU(d, depth + x)));
    if (hn::AllFalse(d, pass)) continue;
    const auto rgba = shade(dx, pass);
    hn::BlendedStore(z, pass, d, depth + x);
    hn::BlendedStore(rgba, hn::RebindMask(du, pass), du, color + x);
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#endif  // include guard toggle
