// Per-target helpers shared by the SIMD shading kernels (Highway's "-inl.h" convention: this
// file is re-included once per target by every kernel's foreach_target pass).
#if defined(FASTSHADE_SHADE_SPAN_LOOP_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FASTSHADE_SHADE_SPAN_LOOP_INL_H_
#undef FASTSHADE_SHADE_SPAN_LOOP_INL_H_
#else
#define FASTSHADE_SHADE_SPAN_LOOP_INL_H_
#endif

#include <hwy/highway.h>

#include "shade/fast_math-inl.h"

#include "raster/triangle_in_tile.h"
#include "shade/method.h"

HWY_BEFORE_NAMESPACE();
namespace fastshade {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// row + gx * dx, clamped to the plane's vertex range: the same float operations, in the same
// order, as plane_at() in raster/planes.h.
template <class D, class V = hn::Vec<D>>
HWY_INLINE V EvalPlane(D d, const Plane& p, float row, V dx) {
  const V v = hn::Add(hn::Set(d, row), hn::Mul(hn::Set(d, p.gx), dx));
  return hn::Min(hn::Max(v, hn::Set(d, p.lo)), hn::Set(d, p.hi));
}

// clamp to [0, 1] (NaN becomes 0: x86 max returns its second operand), optional sRGB curve,
// floor(255 v + 0.5), as quantize() in shade/lighting.h.
template <bool kSrgb, class D, class V = hn::Vec<D>>
HWY_INLINE auto Quantize(D d, V v) {
  v = hn::Min(hn::Max(v, hn::Zero(d)), hn::Set(d, 1.0f));
  if constexpr (kSrgb) {
    const V linear = hn::Mul(v, hn::Set(d, 12.92f));
    const V safe = hn::Max(v, hn::Set(d, 1e-30f));
    const V curve = hn::Sub(
        hn::Mul(hn::Set(d, 1.055f), FastExp2(d, hn::Mul(FastLog2(d, safe), hn::Set(d, 1.0f / 2.4f)))),
        hn::Set(d, 0.055f));
    v = hn::IfThenElse(hn::Le(v, hn::Set(d, 0.0031308f)), linear, curve);
  }
  const V scaled = hn::Floor(hn::Add(hn::Mul(v, hn::Set(d, 255.0f)), hn::Set(d, 0.5f)));
  return hn::BitCast(hn::RebindToUnsigned<D>(), hn::ConvertTo(hn::RebindToSigned<D>(), scaled));
}

template <bool kSrgb, class D, class V = hn::Vec<D>>
HWY_INLINE auto PackRGBA(D d, V r, V g, V b) {
  const hn::RebindToUnsigned<D> du;
  const auto ri = Quantize<kSrgb>(d, r), gi = Quantize<kSrgb>(d, g), bi = Quantize<kSrgb>(d, b);
  return hn::Or(hn::Or(ri, hn::ShiftLeft<8>(gi)),
                hn::Or(hn::ShiftLeft<16>(bi), hn::Set(du, 0xFF000000u)));
}

// Walks one covered row span a vector at a time: depth test against the tile, then
// shade(d, dx, pass) for vectors with a lane that passes, then blended stores of colour and
// depth. dx is the lanes' pixel offset from the triangle's anchor, as float. Short spans (the
// many small triangles of a dense mesh) take vectors of 4 or 8 lanes: wider ones would be
// mostly masked off and, on CPUs that split 512-bit operations, cost twice as much.
template <class D, typename ShadeFn>
HWY_INLINE void ShadeSpanWith(D d, const TriangleInTile& tri, float depth_row, float* depth,
                              uint32_t* color, int x0, int x1, ShadeFn&& shade) {
  const hn::RebindToSigned<D> di;
  const hn::RebindToUnsigned<D> du;
  const int lanes = static_cast<int>(hn::Lanes(d));
  const auto iota = hn::Iota(di, 0);
  for (int x = x0; x <= x1; x += lanes) {
    const auto xi = hn::Add(hn::Set(di, x), iota);
    const auto inside = hn::RebindMask(d, hn::Lt(xi, hn::Set(di, x1 + 1)));
    const auto dx = hn::ConvertTo(d, hn::Sub(xi, hn::Set(di, tri.bary.ax)));
    const auto z = EvalPlane(d, tri.depth, depth_row, dx);
    const auto pass = hn::And(inside, hn::Lt(z, hn::LoadU(d, depth + x)));
    if (hn::AllFalse(d, pass)) continue;
    const auto rgba = shade(d, dx, pass);
    hn::BlendedStore(z, pass, d, depth + x);
    hn::BlendedStore(rgba, hn::RebindMask(du, pass), du, color + x);
  }
}

template <typename ShadeFn>
HWY_INLINE void ShadeSpan(TriangleInTile& tri, int py, int x0, int x1, const TileTarget& tt,
                          ShadeFn&& shade) {
  tri.set_up_planes();
  const float depth_row = row_value(tri.depth, tri.bary, py);
  float* depth = tt.depth + (py - tt.y_origin) * tt.stride - tt.x_origin;
  uint32_t* color = tt.color + (py - tt.y_origin) * tt.stride - tt.x_origin;
  const int n = x1 - x0 + 1;
  const hn::ScalableTag<float> d;
  if (n <= 4 && hn::Lanes(d) > 4) {
    ShadeSpanWith(hn::CappedTag<float, 4>(), tri, depth_row, depth, color, x0, x1, shade);
  } else if (n <= 8 && hn::Lanes(d) > 8) {
    ShadeSpanWith(hn::CappedTag<float, 8>(), tri, depth_row, depth, color, x0, x1, shade);
  } else {
    ShadeSpanWith(d, tri, depth_row, depth, color, x0, x1, shade);
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#endif  // include guard toggle
