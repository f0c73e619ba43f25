// `hybrid`: Phong at the ends of segments of 2^m pixels, linear in between, m chosen per
// 16-pixel block from the normal's turn and the highlight's nearness (shade/hybrid.h).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shade/hybrid.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <algorithm>
#include <bit>

#include <hwy/highway.h>

#include "shade/brdf_variants.h"
#include "shade/hybrid.h"
#include "shade/methods.h"
#include "shade/phong-inl.h"

HWY_BEFORE_NAMESPACE();
namespace fastshade {
namespace HWY_NAMESPACE {

// Triangles narrower than this (whole bounding box, not the tile's part of it, so that every
// tile decides alike) take per-pixel Phong: a segment end costs as much as a pixel.
inline constexpr int kHybridMinWidthPx = 8;

template <bool kLocal, bool kSrgb, BrdfKind kBrdf>
void HybridSpanImpl(const PhongSpanInput& in, const HybridRun& run, int py, int x0, int x1,
                    RowTarget row) {
  const hn::ScalableTag<float> d;
  const hn::RebindToSigned<decltype(d)> di;
  const int lanes = static_cast<int>(hn::Lanes(d));
  constexpr int kBlock = limits::kSeedBlockPx;
  constexpr int kMaxBlocks = limits::kMaxTilePx / kBlock + 1;
  constexpr int kMaxEnds = kMaxBlocks * (kBlock + 1) + HWY_MAX_BYTES / sizeof(float);
  const auto iota = hn::Iota(di, 0);
  const auto dy = hn::Set(d, static_cast<float>(py - in.bary.ay));
  // 1. Per block its segment length, and every segment end of the span in one list, so that
  //    the ends of many blocks share vectors: a block with 2 ends must not cost a vector.
  alignas(64) int32_t end_x[kMaxEnds];
  alignas(64) float end_r[kMaxEnds], end_g[kMaxEnds], end_b[kMaxEnds];
  int block_step[kMaxBlocks], block_first_end[kMaxBlocks];
  const int xb0 = x0 & ~(kBlock - 1);
  int ends = 0, blocks = 0;
  for (int xb = xb0; xb <= x1; xb += kBlock, ++blocks) {
    const int step = run.step;
    block_step[blocks] = step;
    block_first_end[blocks] = ends;
    if (step > 1)
      for (int j = 0; j * step <= kBlock; ++j) end_x[ends++] = segment_end(xb, j, step, run.xl, run.xr);
  }
  // 2. Phong at all the ends, a full vector at a time (the padding repeats the last end).
  for (int j = ends; j % lanes != 0; ++j) end_x[j] = ends > 0 ? end_x[ends - 1] : run.xl;
  for (int j = 0; j < ends; j += lanes) {
    const auto c = PhongColor<kLocal, kBrdf>(d, in, MakeLaneOffsets(d, in.bary, hn::Load(di, end_x + j), dy));
    hn::Store(c.r, d, end_r + j);
    hn::Store(c.g, d, end_g + j);
    hn::Store(c.b, d, end_b + j);
  }
  // 3. Pixels: per-pixel Phong where a block needs it, the segments' lines elsewhere.
  auto phong = [&](auto dd, const auto& o) { return PhongShade<kLocal, kSrgb, kBrdf>(dd, in, o); };
  for (int k = 0; k < blocks; ++k) {
    const int xb = xb0 + k * kBlock;
    const int lo = std::max(xb, x0), hi = std::min(xb + kBlock - 1, x1);
    const int step = block_step[k];
    if (step == 1) {
      ShadeSpanWith(d, in.bary, in.depth, py, lo, hi, row, phong);
      continue;
    }
    const int shift = std::countr_zero(static_cast<unsigned>(step));
    ShadeSpanAt(d, in.bary, in.depth, py, lo, hi, row, [&](auto, const auto&, int x) {
      const auto xi = hn::Add(hn::Set(di, x), iota);
      // Lanes past hi are clamped into the block: their ends stay inside the arrays.
      const auto i = hn::Min(hn::Sub(xi, hn::Set(di, xb)), hn::Set(di, kBlock - 1));
      const auto j0 = hn::ShiftRightSame(i, shift);
      const auto j1 = hn::Add(j0, hn::Set(di, 1));
      const int first_end = block_first_end[k];
      // The block's ends (at most 16 / step + 1) as vectors: lanes pick theirs by permuting
      // when they fit in one vector, by gathering otherwise (narrow vectors, short steps).
      const bool fits = kBlock / step + 1 <= lanes;
      auto pick = [&](const auto& v_or_ptr, const auto& j) {
        if constexpr (std::is_pointer_v<std::decay_t<decltype(v_or_ptr)>>) {
          return hn::GatherIndex(hn::Rebind<std::remove_const_t<std::remove_pointer_t<std::decay_t<decltype(v_or_ptr)>>>, decltype(d)>(),
                                 v_or_ptr, hn::Add(j, hn::Set(di, first_end)));
        } else {
          return hn::TableLookupLanes(v_or_ptr, hn::IndicesFromVec(hn::Rebind<hn::TFromV<std::decay_t<decltype(v_or_ptr)>>, decltype(d)>(), j));
        }
      };
      hn::Vec<decltype(di)> ea, eb;
      hn::Vec<decltype(d)> ra, rb, ga, gb, ba, bb;
      if (fits) {
        const auto vx = hn::LoadU(di, end_x + first_end);
        const auto vr = hn::LoadU(d, end_r + first_end), vg = hn::LoadU(d, end_g + first_end),
                   vb = hn::LoadU(d, end_b + first_end);
        ea = pick(vx, j0), eb = pick(vx, j1);
        ra = pick(vr, j0), rb = pick(vr, j1), ga = pick(vg, j0), gb = pick(vg, j1), ba = pick(vb, j0), bb = pick(vb, j1);
      } else {
        ea = pick(static_cast<const int32_t*>(end_x), j0), eb = pick(static_cast<const int32_t*>(end_x), j1);
        ra = pick(static_cast<const float*>(end_r), j0), rb = pick(static_cast<const float*>(end_r), j1);
        ga = pick(static_cast<const float*>(end_g), j0), gb = pick(static_cast<const float*>(end_g), j1);
        ba = pick(static_cast<const float*>(end_b), j0), bb = pick(static_cast<const float*>(end_b), j1);
      }
      const auto len = hn::ConvertTo(d, hn::Sub(eb, ea));
      const auto t = hn::IfThenElseZero(hn::Gt(len, hn::Zero(d)),
                                        hn::Div(hn::ConvertTo(d, hn::Sub(xi, ea)), hn::Max(len, hn::Set(d, 1.0f))));
      auto lerp = [&](const auto& a, const auto& b) { return hn::Add(a, hn::Mul(t, hn::Sub(b, a))); };
      return PackRGBA<kSrgb>(d, lerp(ra, rb), lerp(ga, gb), lerp(ba, bb));
    });
  }
}

template <bool kLocal, bool kSrgb, BrdfKind kBrdf>
void DrawHybrid(const Frame& frame, uint32_t entry, const TileTarget& tt) {
  const ShadeConstants& k = frame.shade;
  int step = 1;
  DrawByRowRuns<kLocal, kSrgb, kBrdf>(
      frame, entry, tt, kHybridMinWidthPx,
      [&](const PhongSpanInput& in) {
        const SetupTriangle& t = frame.triangle(entry);
        TriangleNormals normals;
        const float flip = (k.two_sided && (t.flags & kBackFacing)) ? -1.0f : 1.0f;
        for (int i = 0; i < 3; ++i) {
          normals.n[i] = flip * frame.vertex(entry, t.attr[i], &AttrArrays::n_view);
          normals.inv_w[i] = t.inv_w[i];
          normals.pos_view[i] =
              kLocal ? frame.vertex(entry, t.attr[i], &AttrArrays::pos_view) : glm::vec3(0.0f);
        }
        step = hybrid_triangle_step(in, normals, k.hybrid_tolerance);
      },
      [&](const PhongSpanInput& in, int xl, int xr, int py, int x0, int x1, RowTarget row) {
        HybridSpanImpl<kLocal, kSrgb, kBrdf>(in, {step, xl, xr}, py, x0, x1, row);
      });
}

using HybridSpanFn = void (*)(const PhongSpanInput&, const HybridRun&, int, int, int, RowTarget);
FASTSHADE_DEFINE_VARIANT_PICKER(SelectHybrid, DrawHybrid, DrawTriangleFn)
FASTSHADE_DEFINE_VARIANT_PICKER(PickHybridSpan, HybridSpanImpl, HybridSpanFn)

void HybridSpan(const PhongSpanInput& in, const HybridRun& run, int py, int x0, int x1, RowTarget row) {
  PickHybridSpan(in.shade->local_viewer, in.shade->srgb, in.material->lobe.kind)(in, run, py, x0, x1, row);
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace fastshade {

HWY_EXPORT(SelectHybrid);
HWY_EXPORT(HybridSpan);

DrawTriangleFn select_hybrid(const ShadeConstants& shade) {
  return HWY_DYNAMIC_DISPATCH(SelectHybrid)(shade.local_viewer, shade.srgb, shade.brdf.kind);
}

void hybrid_span(const PhongSpanInput& in, const HybridRun& run, int py, int x0, int x1, RowTarget row) {
  HWY_DYNAMIC_DISPATCH(HybridSpan)(in, run, py, x0, x1, row);
}

}  // namespace fastshade
#endif
