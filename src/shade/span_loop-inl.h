// Per-target helpers shared by the SIMD shading kernels (Highway's "-inl.h" convention: this
// file is re-included once per target by every kernel's foreach_target pass).
#if defined(FASTSHADE_SHADE_SPAN_LOOP_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FASTSHADE_SHADE_SPAN_LOOP_INL_H_
#undef FASTSHADE_SHADE_SPAN_LOOP_INL_H_
#else
#define FASTSHADE_SHADE_SPAN_LOOP_INL_H_
#endif

#include <bit>
#include <cmath>
#include <cstring>

#include <hwy/highway.h>

#include "shade/fast_math-inl.h"

#include "raster/triangle_in_tile.h"
#include "shade/method.h"
#include "shade/span_kernels.h"

HWY_BEFORE_NAMESPACE();
namespace fastshade {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The lanes' pixel offsets (raster/planes.h PixelOffsets), shared by every plane of a vector.
template <class D>
struct LaneOffsets {
  hn::Vec<D> block_dx, k, dy;
};

template <class D, class VI>
HWY_INLINE LaneOffsets<D> MakeLaneOffsets(D d, const Barycentrics& b, VI px, hn::Vec<D> dy) {
  const hn::RebindToSigned<D> di;
  const auto xb = hn::And(px, hn::Set(di, ~(limits::kSeedBlockPx - 1)));
  return {hn::ConvertTo(d, hn::Sub(xb, hn::Set(di, b.ax))), hn::ConvertTo(d, hn::Sub(px, xb)), dy};
}

// plane_at() in raster/planes.h, lane by lane: the same float operations in the same order,
// so a pixel gets the same bits whether its row or its block was walked, at any width.
template <class D, class V = hn::Vec<D>>
HWY_INLINE V EvalPlane(D d, const Plane& p, const LaneOffsets<D>& o) {
  const V gx = hn::Set(d, p.gx);
  const V seed = hn::Add(hn::Add(hn::Set(d, p.v0), hn::Mul(hn::Set(d, p.gy), o.dy)), hn::Mul(gx, o.block_dx));
  const V v = hn::Add(seed, hn::Mul(gx, o.k));
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
// shade(d, offsets, x) for vectors with a lane that passes (x: the vector's first pixel),
// then blended stores of colour and depth.
template <class D, typename ShadeFn>
HWY_INLINE void ShadeSpanAt(D d, const Barycentrics& bary, const Plane& depth_plane, int py,
                            int x0, int x1, RowTarget row, ShadeFn&& shade) {
  const hn::RebindToSigned<D> di;
  const hn::RebindToUnsigned<D> du;
  const int lanes = static_cast<int>(hn::Lanes(d));
  const auto iota = hn::Iota(di, 0);
  const auto dy = hn::Set(d, static_cast<float>(py - bary.ay));
  for (int x = x0; x <= x1; x += lanes) {
    const auto xi = hn::Add(hn::Set(di, x), iota);
    const auto inside = hn::RebindMask(d, hn::Lt(xi, hn::Set(di, x1 + 1)));
    const auto o = MakeLaneOffsets(d, bary, xi, dy);
    const auto z = EvalPlane(d, depth_plane, o);
    const auto pass = hn::And(inside, hn::Lt(z, hn::LoadU(d, row.depth + x)));
    if (hn::AllFalse(d, pass)) continue;
    const auto rgba = hn::Xor(shade(d, o, x), hn::Set(du, row.alpha_xor));
    hn::BlendedStore(z, pass, d, row.depth + x);
    hn::BlendedStore(rgba, hn::RebindMask(du, pass), du, row.color + x);
  }
}

// The same for shaders that need only the lanes' offsets: shade(d, offsets).
template <class D, typename ShadeFn>
HWY_INLINE void ShadeSpanWith(D d, const Barycentrics& bary, const Plane& depth_plane, int py,
                              int x0, int x1, RowTarget row, ShadeFn&& shade) {
  ShadeSpanAt(d, bary, depth_plane, py, x0, x1, row,
              [&](auto dd, const auto& o, int) { return shade(dd, o); });
}

// Short spans (the many small triangles of a dense mesh) take vectors of 4 or 8 lanes: wider
// ones would be mostly masked off and, on CPUs that split 512-bit operations, cost double.
// The rows must have kScratchPadPx of slack past x1 (a vector may read and blend past it).
template <typename ShadeFn>
HWY_INLINE void ShadeSpan(const Barycentrics& bary, const Plane& depth_plane, int py, int x0,
                          int x1, RowTarget row, ShadeFn&& shade) {
  const int n = x1 - x0 + 1;
  const hn::ScalableTag<float> d;
  if (n <= 4 && hn::Lanes(d) > 4) {
    ShadeSpanWith(hn::CappedTag<float, 4>(), bary, depth_plane, py, x0, x1, row, shade);
  } else if (n <= 8 && hn::Lanes(d) > 8) {
    ShadeSpanWith(hn::CappedTag<float, 8>(), bary, depth_plane, py, x0, x1, row, shade);
  } else {
    ShadeSpanWith(d, bary, depth_plane, py, x0, x1, row, shade);
  }
}

inline RowTarget tile_row(const TileTarget& tt, int py) {
  return {tt.depth + (py - tt.y_origin) * tt.stride - tt.x_origin,
          tt.color + (py - tt.y_origin) * tt.stride - tt.x_origin, tt.alpha_xor};
}

// Triangles at most 4 pixels wide in this tile are shaded in blocks of 4 columns by
// lanes / 4 rows, so one vector covers what would be several nearly empty row vectors. The
// few covered pixels move between tile and lanes one by one: cheaper here than gathers.
inline constexpr int kBlockColumns = 4;

template <typename ShadeFn>
HWY_INLINE void ShadeBlocks(TriangleInTile& tri, const TileTarget& tt, ShadeFn&& shade) {
  const hn::ScalableTag<float> d;
  const hn::RebindToSigned<decltype(d)> di;
  const hn::RebindToUnsigned<decltype(d)> du;
  constexpr int kMaxLanes = HWY_MAX_BYTES / sizeof(float);
  const int lanes = static_cast<int>(hn::Lanes(d));
  const int rows_per_block = lanes / kBlockColumns;
  const PixelRect& r = tri.rect;
  uint16_t row_bits[limits::kMaxTilePx];
  for_each_row_mask(tri.edges, r, [&](int py, uint32_t bits) { row_bits[py - r.y0] = uint16_t(bits); });
  const auto iota = hn::Iota(di, 0);
  const auto lane_dx = hn::And(iota, hn::Set(di, kBlockColumns - 1));
  const auto lane_dy = hn::ShiftRight<2>(iota);
  static_assert(kBlockColumns == 4, "lane_dy shifts by log2(kBlockColumns)");
  for (int y = r.y0; y <= r.y1; y += rows_per_block) {
    uint32_t covered = 0;
    for (int k = 0; k < rows_per_block && y + k <= r.y1; ++k)
      covered |= uint32_t(row_bits[y + k - r.y0]) << (kBlockColumns * k);
    if (!covered) continue;
    tri.set_up_planes();
    const auto px = hn::Add(lane_dx, hn::Set(di, r.x0));
    const auto dy = hn::ConvertTo(d, hn::Add(lane_dy, hn::Set(di, y - tri.bary.ay)));
    const auto o = MakeLaneOffsets(d, tri.bary, px, dy);
    const auto z = EvalPlane(d, tri.depth, o);
    alignas(64) float lane_depth[kMaxLanes];
    alignas(64) float lane_z[kMaxLanes];
    alignas(64) uint32_t lane_rgba[kMaxLanes];
    hn::Store(hn::Set(d, -HUGE_VALF), d, lane_depth);  // uncovered lanes fail the test
    auto pixel = [&](int lane) {
      const int px = r.x0 + (lane & (kBlockColumns - 1)), py = y + (lane >> 2);
      return std::size_t((py - tt.y_origin) * tt.stride + (px - tt.x_origin));
    };
    for (uint32_t bits = covered; bits; bits &= bits - 1) {
      const int lane = std::countr_zero(bits);
      lane_depth[lane] = tt.depth[pixel(lane)];
    }
    const auto pass = hn::Lt(z, hn::Load(d, lane_depth));
    if (hn::AllFalse(d, pass)) continue;
    hn::Store(z, d, lane_z);
    hn::Store(hn::Xor(shade(d, o), hn::Set(du, tt.alpha_xor)), du, lane_rgba);
    uint8_t pass_bytes[8] = {};
    hn::StoreMaskBits(d, pass, pass_bytes);
    uint32_t passed = 0;
    std::memcpy(&passed, pass_bytes, sizeof(passed));
    for (uint32_t bits = passed & ((lanes < 32) ? ((1u << lanes) - 1) : ~0u); bits; bits &= bits - 1) {
      const int lane = std::countr_zero(bits);
      tt.depth[pixel(lane)] = lane_z[lane];
      tt.color[pixel(lane)] = lane_rgba[lane];
    }
  }
}

// Every covered pixel of the triangle in this tile: blocks for narrow triangles when vectors
// hold at least two block rows, row spans otherwise.
template <typename ShadeFn>
HWY_INLINE void ShadeTriangle(TriangleInTile& tri, const TileTarget& tt, ShadeFn&& shade) {
  const hn::ScalableTag<float> d;
  if (tri.rect.x1 - tri.rect.x0 < kBlockColumns && hn::Lanes(d) >= 2 * kBlockColumns) {
    ShadeBlocks(tri, tt, shade);
    return;
  }
  for_each_span(tri.edges, tri.rect, [&](int py, int x0, int x1) {
    tri.set_up_planes();
    ShadeSpan(tri.bary, tri.depth, py, x0, x1, tile_row(tt, py), shade);
  });
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#endif  // include guard toggle
