// `hybrid`: Phong at the ends of segments of 2^m pixels, linear in between, m chosen per
// 16-pixel block from the normal's turn and the highlight's nearness (shade/hybrid.h).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shade/hybrid.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <algorithm>
#include <bit>

#include <hwy/highway.h>

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
  const hn::RebindToUnsigned<decltype(d)> du;
  const int lanes = static_cast<int>(hn::Lanes(d));
  constexpr int kBlock = limits::kSeedBlockPx;
  const auto iota = hn::Iota(di, 0);
  const auto dy = hn::Set(d, static_cast<float>(py - in.bary.ay));
  auto phong = [&](auto dd, const auto& o) { return PhongShade<kLocal, kSrgb, kBrdf>(dd, in, o); };
  constexpr int kMaxEnds = kBlock + 1 + HWY_MAX_BYTES / sizeof(float);
  alignas(64) float end_r[kMaxEnds], end_g[kMaxEnds], end_b[kMaxEnds];
  alignas(64) int32_t end_x[kMaxEnds];
  for (int xb = x0 & ~(kBlock - 1); xb <= x1; xb += kBlock) {
    const int lo = std::max(xb, x0), hi = std::min(xb + kBlock - 1, x1);
    const int step = hybrid_step(in, xb, py, run.xl, run.xr, run.tol);
    if (step == 1) {
      ShadeSpanWith(d, in.bary, in.depth, py, lo, hi, row, phong);
      continue;
    }
    // Phong at the segment ends (shade/hybrid.h), a vector of ends at a time.
    const int ends = kBlock / step + 1;
    for (int j = 0; j < ends; ++j) end_x[j] = segment_end(xb, j, step, run.xl, run.xr);
    for (int j = ends; j < kMaxEnds; ++j) end_x[j] = end_x[ends - 1];
    for (int j = 0; j < ends; j += lanes) {
      const auto px = hn::Load(di, end_x + j);
      const auto c = PhongColor<kLocal, kBrdf>(d, in, MakeLaneOffsets(d, in.bary, px, dy));
      hn::Store(c.r, d, end_r + j);
      hn::Store(c.g, d, end_g + j);
      hn::Store(c.b, d, end_b + j);
    }
    const int shift = std::countr_zero(static_cast<unsigned>(step));
    for (int x = lo; x <= hi; x += lanes) {
      const auto xi = hn::Add(hn::Set(di, x), iota);
      const auto inside = hn::RebindMask(d, hn::Lt(xi, hn::Set(di, hi + 1)));
      const auto o = MakeLaneOffsets(d, in.bary, xi, dy);
      const auto z = EvalPlane(d, in.depth, o);
      const auto pass = hn::And(inside, hn::Lt(z, hn::LoadU(d, row.depth + x)));
      if (hn::AllFalse(d, pass)) continue;
      // Lanes past hi are clamped into the block: their ends stay inside the arrays.
      const auto i = hn::Min(hn::Sub(xi, hn::Set(di, xb)), hn::Set(di, kBlock - 1));
      const auto j0 = hn::ShiftRightSame(i, shift);
      const auto j1 = hn::Add(j0, hn::Set(di, 1));
      const auto ea = hn::GatherIndex(di, end_x, j0), eb = hn::GatherIndex(di, end_x, j1);
      const auto span = hn::ConvertTo(d, hn::Sub(eb, ea));
      const auto t = hn::IfThenElseZero(hn::Gt(span, hn::Zero(d)),
                                        hn::Div(hn::ConvertTo(d, hn::Sub(xi, ea)), hn::Max(span, hn::Set(d, 1.0f))));
      auto lerp = [&](const float* e) {
        const auto a = hn::GatherIndex(d, e, j0), b = hn::GatherIndex(d, e, j1);
        return hn::Add(a, hn::Mul(t, hn::Sub(b, a)));
      };
      const auto rgba = PackRGBA<kSrgb>(d, lerp(end_r), lerp(end_g), lerp(end_b));
      hn::BlendedStore(z, pass, d, row.depth + x);
      hn::BlendedStore(rgba, hn::RebindMask(du, pass), du, row.color + x);
    }
  }
}

template <bool kLocal, bool kSrgb, BrdfKind kBrdf>
void DrawHybrid(const Frame& frame, uint32_t entry, const TileTarget& tt) {
  TriangleInTile tri;
  if (!prepare_triangle(frame.triangle(entry), tt.rect, tri)) return;
  const SetupTriangle& t = *tri.tri;
  const ShadeConstants& k = frame.shade;
  PhongSpanInput in;
  in.material = &k.materials[t.material];
  in.shade = &k;
  bool ready = false;
  auto set_up = [&] {
    in.bary = tri.bary;
    in.depth = tri.depth;
    set_up_phong_planes<kLocal>(frame, entry, t, tri.bary, in);
    ready = true;
  };
  if (t.px_max[0] - t.px_min[0] + 1 < kHybridMinWidthPx) {
    ShadeTriangle(tri, tt, [&](auto d, const auto& o) {
      if (!ready) set_up();
      return PhongShade<kLocal, kSrgb, kBrdf>(d, in, o);
    });
    return;
  }
  // Rows through the whole triangle (tile rows only): a row's covered run decides its
  // segment ends, whatever tile this is.
  const PixelRect rows{t.px_min[0], tri.rect.y0, t.px_max[0], tri.rect.y1};
  for_each_span(tri.edges, rows, [&](int py, int xl, int xr) {
    const int x0 = std::max(xl, tri.rect.x0), x1 = std::min(xr, tri.rect.x1);
    if (x0 > x1) return;
    tri.set_up_planes();
    if (!ready) set_up();
    HybridSpanImpl<kLocal, kSrgb, kBrdf>(in, {k.hybrid_tolerance, xl, xr}, py, x0, x1, tile_row(tt, py));
  });
}

#define FASTSHADE_BRDF_CASES(F, L, S)                                      \
  switch (kind) {                                                          \
    case BrdfKind::Exact: return F<L, S, BrdfKind::Exact>;                 \
    case BrdfKind::CosK: return F<L, S, BrdfKind::CosK>;                   \
    case BrdfKind::Schlick: return F<L, S, BrdfKind::Schlick>;             \
    case BrdfKind::SchlickPow2: return F<L, S, BrdfKind::SchlickPow2>;     \
    case BrdfKind::Quadratic: return F<L, S, BrdfKind::Quadratic>;         \
    case BrdfKind::QuadraticFit: return F<L, S, BrdfKind::QuadraticFit>;   \
    case BrdfKind::Poly2: return F<L, S, BrdfKind::Poly2>;                 \
    case BrdfKind::Poly3: return F<L, S, BrdfKind::Poly3>;                 \
  }                                                                        \
  return nullptr;

template <bool kLocal, bool kSrgb>
DrawTriangleFn PickDraw(BrdfKind kind) { FASTSHADE_BRDF_CASES(&DrawHybrid, kLocal, kSrgb) }

using HybridSpanFn = void (*)(const PhongSpanInput&, const HybridRun&, int, int, int, RowTarget);
template <bool kLocal, bool kSrgb>
HybridSpanFn PickSpan(BrdfKind kind) { FASTSHADE_BRDF_CASES(&HybridSpanImpl, kLocal, kSrgb) }
#undef FASTSHADE_BRDF_CASES

DrawTriangleFn SelectHybrid(bool local, bool srgb, BrdfKind kind) {
  if (local) return srgb ? PickDraw<true, true>(kind) : PickDraw<true, false>(kind);
  return srgb ? PickDraw<false, true>(kind) : PickDraw<false, false>(kind);
}

void HybridSpan(const PhongSpanInput& in, const HybridRun& run, int py, int x0, int x1, RowTarget row) {
  const bool local = in.shade->local_viewer, srgb = in.shade->srgb;
  const BrdfKind kind = in.material->lobe.kind;
  const HybridSpanFn fn = local ? (srgb ? PickSpan<true, true>(kind) : PickSpan<true, false>(kind))
                                : (srgb ? PickSpan<false, true>(kind) : PickSpan<false, false>(kind));
  fn(in, run, py, x0, x1, row);
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
