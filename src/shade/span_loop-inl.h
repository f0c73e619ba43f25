// Per-target helpers shared by the SIMD shading kernels (Highway's "-inl.h" convention: this
// file is re-included once per target by every kernel's foreach_target pass).
#if defined(FASTSHADE_SHADE_SPAN_LOOP_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FASTSHADE_SHADE_SPAN_LOOP_INL_H_
#undef FASTSHADE_SHADE_SPAN_LOOP_INL_H_
#else
#define FASTSHADE_SHADE_SPAN_LOOP_INL_H_
#endif

#include <algorithm>
#include <bit>
#include <cmath>
#include <type_traits>

#include <hwy/highway.h>

#include "shade/shade_limits.h"
#include "core/mask_bits-inl.h"
#include "light/fast_math-inl.h"

#include "raster/row_masks-inl.h"
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
HWY_INLINE V EvalPlaneUnclamped(D d, const Plane& p, const LaneOffsets<D>& o) {
  const V gx = hn::Set(d, p.gx);
  const V seed = hn::Add(hn::Add(hn::Set(d, p.v0), hn::Mul(hn::Set(d, p.gy), o.dy)), hn::Mul(gx, o.block_dx));
  return hn::Add(seed, hn::Mul(gx, o.k));
}
template <class D, class V = hn::Vec<D>>
HWY_INLINE V EvalPlane(D d, const Plane& p, const LaneOffsets<D>& o) {
  return hn::Min(hn::Max(EvalPlaneUnclamped(d, p, o), hn::Set(d, p.lo)), hn::Set(d, p.hi));
}

// clamp to [0, 1] (NaN becomes 0: x86 max returns its second operand), optional sRGB curve,
// floor(255 v + 0.5), as quantize() in light/lighting.h; the level stays a float (exact).
template <bool kSrgb, class D, class V = hn::Vec<D>>
HWY_INLINE V QuantizeLevel(D d, V v) {
  v = hn::Min(hn::Max(v, hn::Zero(d)), hn::Set(d, 1.0f));
  if constexpr (kSrgb) {
    const V linear = hn::Mul(v, hn::Set(d, 12.92f));
    const V safe = hn::Max(v, hn::Set(d, 1e-30f));
    const V curve = hn::Sub(
        hn::Mul(hn::Set(d, 1.055f), FastExp2(d, hn::Mul(FastLog2(d, safe), hn::Set(d, 1.0f / 2.4f)))),
        hn::Set(d, 0.055f));
    v = hn::IfThenElse(hn::Le(v, hn::Set(d, 0.0031308f)), linear, curve);
  }
  return hn::Floor(hn::Add(hn::Mul(v, hn::Set(d, 255.0f)), hn::Set(d, 0.5f)));
}

// The three levels (integers 0..255 held exactly in floats) become the pixel without a
// float-to-integer conversion: 2^23 + x, for an integer x < 2^23, holds x exactly in its
// mantissa under the exponent bits 0x4B000000, so a bit cast reads x off. r + 256 g is such
// an x; b is another, shifted into place (its exponent bits shift out), and OR-ing the alpha
// byte covers the 0x4B of the first.
template <class D, class V = hn::Vec<D>>
HWY_INLINE auto PackLevels(D d, V r, V g, V b) {
  const hn::RebindToUnsigned<D> du;
  const V magic = hn::Set(d, 8388608.0f);  // 2^23
  const auto rg_bits = hn::BitCast(du, hn::Add(hn::Add(r, hn::Mul(g, hn::Set(d, 256.0f))), magic));
  const auto b_bits = hn::BitCast(du, hn::Add(b, magic));
  return hn::Or(hn::Or(rg_bits, hn::ShiftLeft<16>(b_bits)), hn::Set(du, 0xFF000000u));
}

// Colour channels in [0, 1] (clamped here) to the pixel.
template <bool kSrgb, class D, class V = hn::Vec<D>>
HWY_INLINE auto PackRGBA(D d, V r, V g, V b) {
  return PackLevels(d, QuantizeLevel<kSrgb>(d, r), QuantizeLevel<kSrgb>(d, g), QuantizeLevel<kSrgb>(d, b));
}

// The same with the output curve chosen at run time: a branch per vector that goes the same
// way all frame. The per-pixel Blinn-Phong kernels take it instead of being compiled twice
// (light/brdf_variants.h says why their variants are few).
template <class D, class V = hn::Vec<D>>
HWY_INLINE auto PackRGBA(D d, V r, V g, V b, bool srgb) {
  return srgb ? PackRGBA<true>(d, r, g, b) : PackRGBA<false>(d, r, g, b);
}

// Walks one covered row span a vector at a time: depth test against the tile, then
// shade(d, offsets, x) for vectors with a lane that passes (x: the vector's first pixel),
// then colour and depth blended in registers and stored whole: the rows are the worker's own
// scratch (TileTarget), so lanes that fail write back what they read. AVX2's masked stores
// (vmaskmovps, vpmaskmovd) are microcoded on Zen 3: the gouraud span benchmark ran 200-232 ns
// with them and 129-144 ns without (64 px, kernels_bench; 9ad9f5d).
template <class D, typename ShadeFn>
HWY_INLINE void ShadeSpanAt(D d, const Barycentrics& bary, const Plane& depth_plane, int py,
                            int x0, int x1, RowTarget row, ShadeFn&& shade) {
  const hn::RebindToSigned<D> di;
  const hn::RebindToUnsigned<D> du;
  const int lanes = static_cast<int>(hn::Lanes(d));
  const auto step = hn::Set(di, lanes);
  const auto end = hn::Set(di, x1 + 1);
  auto xi = hn::Add(hn::Set(di, x0), hn::Iota(di, 0));
  auto o = MakeLaneOffsets(d, bary, xi, hn::Set(d, static_cast<float>(py - bary.ay)));
  // A vector as wide as a seed block meets the same in-block offsets k at every step, and
  // its block origins move by one block (exact: small integers in float).
  const bool block_wide = lanes == limits::kSeedBlockPx;
  const auto block_step = hn::Set(d, static_cast<float>(limits::kSeedBlockPx));
  for (int x = x0; x <= x1; x += lanes) {
    const auto inside = hn::RebindMask(d, hn::Lt(xi, end));
    const auto z = EvalPlane(d, depth_plane, o);
    const auto old_z = hn::LoadU(d, row.depth + x);
    const auto pass = hn::And(inside, hn::Lt(z, old_z));
    if (!hn::AllFalse(d, pass)) {
      const auto rgba = hn::Xor(shade(d, o, x), hn::Set(du, row.alpha_xor));
      hn::StoreU(hn::IfThenElse(pass, z, old_z), d, row.depth + x);
      hn::StoreU(hn::IfThenElse(hn::RebindMask(du, pass), rgba, hn::LoadU(du, row.color + x)), du, row.color + x);
    }
    xi = hn::Add(xi, step);
    if (block_wide) o.block_dx = hn::Add(o.block_dx, block_step);
    else o = MakeLaneOffsets(d, bary, xi, o.dy);
  }
}

// The same for shaders that need only the lanes' offsets: shade(d, offsets).
template <class D, typename ShadeFn>
HWY_INLINE void ShadeSpanWith(D d, const Barycentrics& bary, const Plane& depth_plane, int py,
                              int x0, int x1, RowTarget row, ShadeFn&& shade) {
  ShadeSpanAt(d, bary, depth_plane, py, x0, x1, row,
              [&](auto dd, const auto& o, int) { return shade(dd, o); });
}

// fn(d) with the narrowest float vector of 4, 8 or all lanes that holds n pixels: the many small
// triangles of a dense mesh would leave wider vectors mostly masked off, and on CPUs that split
// 512-bit operations those cost double.
template <typename Fn>
HWY_INLINE void WithNarrowestVector(size_t n, Fn&& fn) {
  const hn::ScalableTag<float> d;
  if (n <= 4 && hn::Lanes(d) > 4) {
    fn(hn::CappedTag<float, 4>());
  } else if (n <= 8 && hn::Lanes(d) > 8) {
    fn(hn::CappedTag<float, 8>());
  } else {
    fn(d);
  }
}

// A row span in the narrowest vectors that hold it. The rows must have limits::kScratchPadPx of slack
// past x1 (a vector reads and rewrites lanes past it).
template <typename ShadeFn>
HWY_INLINE void ShadeSpan(const Barycentrics& bary, const Plane& depth_plane, int py, int x0,
                          int x1, RowTarget row, ShadeFn&& shade) {
  WithNarrowestVector(x1 - x0 + 1, [&](auto d) { ShadeSpanWith(d, bary, depth_plane, py, x0, x1, row, shade); });
}

inline RowTarget tile_row(const TileTarget& tt, int py) {
  return {tt.depth + (py - tt.y_origin) * tt.stride - tt.x_origin,
          tt.color + (py - tt.y_origin) * tt.stride - tt.x_origin, tt.alpha_xor};
}

inline constexpr int kMaxLanes = HWY_MAX_BYTES / sizeof(float);

// Depth z and colour rgba of the lanes that passed the depth test, to tile pixels lane_at[i]
// (a triangle's lanes hold distinct pixels, so the order of the stores does not matter).
template <class D, class V, class VU>
HWY_INLINE void StorePassed(D d, hn::Mask<D> pass, V z, VU rgba, const int32_t* lane_at, const TileTarget& tt) {
  const hn::RebindToUnsigned<D> du;
  alignas(64) float lane_z[kMaxLanes];
  alignas(64) uint32_t lane_rgba[kMaxLanes];
  hn::Store(z, d, lane_z);
  hn::Store(hn::Xor(rgba, hn::Set(du, tt.alpha_xor)), du, lane_rgba);
  for (uint64_t passed = MaskBits(d, pass); passed; passed &= passed - 1) {
    const int lane = std::countr_zero(passed);
    tt.depth[lane_at[lane]] = lane_z[lane];
    tt.color[lane_at[lane]] = lane_rgba[lane];
  }
}

// A shader whose lanes may wait to be lit with other triangles' (shade/pixel_queue-inl.h):
// ShadeLanes hands defer(d, pass, z, offsets, lane_at) the lanes that passed the depth test
// instead of shading and storing them; row spans still call shade(d, offsets) and store at once.
template <typename ShadeFn, typename DeferFn>
struct Deferring {
  ShadeFn& shade;
  DeferFn& defer;
  template <class D, class O>
  HWY_INLINE auto operator()(D d, const O& o) const {
    return shade(d, o);
  }
};
template <typename T>
inline constexpr bool kIsDeferring = false;
template <typename S, typename F>
inline constexpr bool kIsDeferring<Deferring<S, F>> = true;

// Covered pixels already in the first `count` lanes (lane_px, lane_py; lane_at their tile
// index and lane_z its depth; the arrays are a whole vector long): planes, depth test and
// shading of one vector, for ShadePackedWith and ShadeBox.
template <class D, typename ShadeFn>
HWY_INLINE void ShadeLanes(D d, TriangleInTile& tri, const TileTarget& tt, const int32_t* lane_px,
                           const int32_t* lane_py, const int32_t* lane_at, const float* lane_z, size_t count,
                           ShadeFn&& shade) {
  const hn::RebindToSigned<D> di;
  tri.set_up_planes();
  const auto dy = hn::ConvertTo(d, hn::Sub(hn::Load(di, lane_py), hn::Set(di, tri.bary.ay)));
  const auto o = MakeLaneOffsets(d, tri.bary, hn::Load(di, lane_px), dy);
  const auto z = EvalPlane(d, tri.depth, o);
  const auto pass = hn::And(hn::FirstN(d, count), hn::Lt(z, hn::Load(d, lane_z)));
  if (hn::AllFalse(d, pass)) return;
  if constexpr (kIsDeferring<std::remove_cvref_t<ShadeFn>>) shade.defer(d, pass, z, o, lane_at);
  else StorePassed(d, pass, z, shade(d, o), lane_at, tt);
}

// A narrow triangle's covered pixels, packed into lanes whatever their row: a 6-pixel
// triangle is one vector instead of three nearly empty row vectors. A row's covered pixels are
// one run (triangles are convex), appended to small arrays a whole vector at a time: pixel
// coordinates, tile index and the tile depth, copied from the row. The arrays are emptied a
// vector at a time. A vector whose tile depths are all at or nearer than the triangle's
// nearest vertex draws nothing (HiddenAlready's test, vector by vector) and is skipped before
// the planes are set up: a dense mesh hides many of its triangles. The lanes' offsets are the
// span path's (MakeLaneOffsets), so a pixel gets the same bits whichever path drew it.
template <class D, typename ShadeFn>
HWY_INLINE void ShadePackedWith(D d, TriangleInTile& tri, const TileTarget& tt,
                                const uint32_t* row_bits, ShadeFn&& shade) {
  const hn::RebindToSigned<D> di;
  const int lanes = static_cast<int>(hn::Lanes(d));
  // A run of len pixels appended at n < lanes writes len / lanes + 1 whole vectors, so every
  // lane up to the end of the vector after the last full one holds a written value (valid
  // coordinates and indices, masked off past the count).
  constexpr int kSlots = 2 * kMaxLanes + 32;  // a run is at most a row mask: 32 bits
  alignas(64) int32_t lane_px[kSlots], lane_py[kSlots], lane_at[kSlots];
  alignas(64) float lane_z[kSlots];
  const SetupTriangle& t = *tri.tri;
  const auto nearest = hn::Set(d, std::min({t.depth[0], t.depth[1], t.depth[2]}));
  auto flush = [&](int first, int n) {
    const auto nearer = hn::Gt(hn::Load(d, lane_z + first), nearest);
    if (hn::AllFalse(d, hn::And(hn::FirstN(d, static_cast<size_t>(n)), nearer))) return;
    ShadeLanes(d, tri, tt, lane_px + first, lane_py + first, lane_at + first, lane_z + first,
               static_cast<size_t>(n), shade);
  };
  const PixelRect& r = tri.rect;
  const auto iota = hn::Iota(di, 0);
  int n = 0;
  for (int py = r.y0; py <= r.y1; ++py) {
    const uint32_t bits = row_bits[py - r.y0];
    if (bits == 0) continue;
    const int x_first = r.x0 + std::countr_zero(bits);
    const int len = std::popcount(bits);
    const int row_at = (py - tt.y_origin) * tt.stride - tt.x_origin;
    const float* run_z = tt.depth + (row_at + x_first);
    for (int k = 0; k <= len; k += lanes) {
      const auto px = hn::Add(iota, hn::Set(di, x_first + k));
      hn::StoreU(px, di, lane_px + n + k);
      hn::StoreU(hn::Set(di, py), di, lane_py + n + k);
      hn::StoreU(hn::Add(px, hn::Set(di, row_at)), di, lane_at + n + k);
      hn::StoreU(hn::LoadU(d, run_z + k), d, lane_z + n + k);
    }
    n += len;
    if (n < lanes) continue;
    int first = 0;
    for (; n >= lanes; first += lanes, n -= lanes) flush(first, lanes);
    // The rest moves to the front: the vector after the last full one, written whole above.
    hn::Store(hn::Load(di, lane_px + first), di, lane_px);
    hn::Store(hn::Load(di, lane_py + first), di, lane_py);
    hn::Store(hn::Load(di, lane_at + first), di, lane_at);
    hn::Store(hn::Load(d, lane_z + first), d, lane_z);
  }
  if (n > 0) flush(0, n);
}

// Whether no pixel of the triangle's box can pass the depth test, decided before its edges
// or planes are set up: the depth plane is clamped to the vertex depths (raster/planes.h), so
// no pixel of the triangle is nearer than its nearest vertex, and where every pixel of the box
// already holds that depth or a nearer one, the triangle draws nothing. Dense meshes drawn in
// mesh order hide many triangles behind ones drawn before; the answer is exact, so images do
// not change. (ShadePackedWith makes the same test on the covered pixels it packs.)
HWY_INLINE bool HiddenAlready(const TriangleInTile& tri, const TileTarget& tt) {
  const SetupTriangle& t = *tri.tri;
  const float nearest = std::min({t.depth[0], t.depth[1], t.depth[2]});
  const PixelRect& r = tri.rect;
  for (int py = r.y0; py <= r.y1; ++py) {
    const float* depth = tt.depth + (py - tt.y_origin) * tt.stride - tt.x_origin;
    for (int px = r.x0; px <= r.x1; ++px)
      if (depth[px] > nearest) return false;
  }
  return true;
}

// A dense mesh's small boxes (box_layout fits a vector, the triangle box_lanes_exact), in
// vectors of d's width: the box's tile depths in one gather, HiddenAlready on the whole box
// before the edges are set up, coverage in one vector (BoxCovered), HiddenAlready on the covered
// pixels, then those compressed into the first lanes and shaded in the narrowest vector that
// holds them. No loop over rows or pixels.
template <class D, typename ShadeFn>
HWY_INLINE void ShadeBox(D d, TriangleInTile& tri, const TileTarget& tt, BoxLayout layout, ShadeFn&& shade) {
  const hn::RebindToSigned<D> di;
  const PixelRect& r = tri.rect;
  const auto box = BoxPixels(di, layout);
  const int stride_shift = std::countr_zero(static_cast<unsigned>(tt.stride));
  const auto at = hn::IfThenElseZero(  // lanes outside the box: a valid index
      box.inside, hn::Add(hn::ShiftLeftSame(hn::Add(box.row, hn::Set(di, r.y0 - tt.y_origin)), stride_shift),
                          hn::Add(box.col, hn::Set(di, r.x0 - tt.x_origin))));
  const auto tile_z = hn::GatherIndex(d, tt.depth, at);
  const SetupTriangle& t = *tri.tri;
  const auto nearer = hn::RebindMask(di, hn::Gt(tile_z, hn::Set(d, std::min({t.depth[0], t.depth[1], t.depth[2]}))));
  if (hn::AllFalse(di, hn::And(box.inside, nearer))) return;
  const auto covered = BoxCovered(di, triangle_edges(t), r, box);
  if (hn::AllFalse(di, hn::And(covered, nearer))) return;
  const size_t count = hn::CountTrue(di, covered);
  alignas(64) int32_t lane_px[kMaxLanes], lane_py[kMaxLanes], lane_at[kMaxLanes];
  alignas(64) float lane_z[kMaxLanes];
  hn::Store(hn::Compress(hn::Add(box.col, hn::Set(di, r.x0)), covered), di, lane_px);
  hn::Store(hn::Compress(hn::Add(box.row, hn::Set(di, r.y0)), covered), di, lane_py);
  hn::Store(hn::IfThenElseZero(hn::FirstN(di, count), hn::Compress(at, covered)), di, lane_at);
  hn::Store(hn::Compress(tile_z, hn::RebindMask(d, covered)), d, lane_z);
  WithNarrowestVector(count, [&](auto dc) { ShadeLanes(dc, tri, tt, lane_px, lane_py, lane_at, lane_z, count, shade); });
}

// Narrow triangles whose box ShadeBox cannot take: SIMD row masks, then the covered pixels in
// the narrowest vectors that hold them.
template <typename ShadeFn>
HWY_INLINE void ShadePacked(TriangleInTile& tri, const TileTarget& tt, ShadeFn&& shade) {
  uint32_t row_bits[limits::kMaxTilePx];
  const int covered = RowMasks(triangle_edges(*tri.tri), tri.rect, row_bits);
  if (covered == 0) return;
  WithNarrowestVector(covered, [&](auto d) { ShadePackedWith(d, tri, tt, row_bits, shade); });
}

// Every covered pixel of the triangle in this tile (placed by place_in_tile: its edges are set
// up here): one box vector or packed lanes for narrow triangles, row spans otherwise.
template <typename ShadeFn>
HWY_INLINE void ShadeTriangle(TriangleInTile& tri, const TileTarget& tt, ShadeFn&& shade) {
  const PixelRect& r = tri.rect;
  if (r.x1 - r.x0 < kNarrowRectPx) {
    const BoxLayout layout = box_layout(r);
    if (layout.lanes <= static_cast<int>(hn::Lanes(hn::ScalableTag<int32_t>())) && box_lanes_exact(*tri.tri)) {
      WithNarrowestVector(layout.lanes, [&](auto d) { ShadeBox(d, tri, tt, layout, shade); });
      return;
    }
    if ((r.x1 - r.x0 + 1) * (r.y1 - r.y0 + 1) <= limits::kHiddenBoxTestPx && HiddenAlready(tri, tt)) return;
    ShadePacked(tri, tt, shade);
    return;
  }
  tri.edges = triangle_edges(*tri.tri);
  for_each_span(tri.edges, tri.rect, [&](int py, int x0, int x1) {
    tri.set_up_planes();
    ShadeSpan(tri.bary, tri.depth, py, x0, x1, tile_row(tt, py), shade);
  });
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#endif  // include guard toggle
