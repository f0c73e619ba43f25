// `hybrid`: Phong at the ends of segments of 2^m pixels along a row, linear in between, m
// chosen per triangle from the normal's turn and the highlight's nearness (classify/
// segment_step.h), by the front end (front/segment_steps.h).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shade/hybrid.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <algorithm>
#include <bit>

#include <hwy/highway.h>

#include "classify/segment_step.h"
#include "core/dispatch.h"
#include "light/brdf_variants.h"
#include "shade/methods.h"
#include "shade/phong-inl.h"
#include "shade/scalar_twin.h"
#include "shade/shade_limits.h"

HWY_BEFORE_NAMESPACE();
namespace fastshade {
namespace HWY_NAMESPACE {

// The rows of one triangle in one tile, with their segment ends shaded together: a row of a
// small triangle has only a few ends, which alone would fill a fraction of a vector (on a
// 16-lane target one vector of ends costs as much as Phong at every pixel of a short row).
// Rows are collected until the buffer is full; then Phong runs over all their ends in full
// vectors and every row is interpolated.
//
// A pixel x of a row whose whole run in the triangle is [xl, xr] lies in the segment from
// ea = clamp(g, xl, xr) to eb = clamp(g + step, xl, xr), g = x rounded down to a multiple of
// step, and takes ca + (x - ea) s with the slope s = (cb - ca) / (eb - ea) (0 if eb = ea):
// exactly what hybrid_span_scalar() computes. The ends are clamped to the row's run in the whole triangle,
// not this tile's part of it: Phong is only ever evaluated inside, and a pixel's value does
// not depend on the tiles. With a split light (classify/segment_step.h), the ends carry that
// light's N.L apart, interpolated alike and clamped per pixel: colour + kd colour_L max(N.L, 0).
template <bool kLocal, LobeKernel kLobe>
class HybridRows {
 public:
  // For one triangle: its planes (which must outlive the rows' flush) and segment plan.
  void start(const PhongSpanInput& in, int step, int split_light, bool specular) {
    in_ = &in;
    step_ = step;
    shift_ = std::countr_zero(static_cast<unsigned>(step));
    split_ = split_light;
    specular_ = specular;
    srgb_ = in.shade->srgb;
    if (split_ >= 0)
      for (int c = 0; c < 3; ++c) split_kd_[c] = in.shade->lights[split_].color[c] * in.material->kd[c];
  }

  // Inlined into the row walk: out of line (as GCC left it once per-pixel Phong chose the
  // output curve at run time) it cost hybrid 11 % on spot 4K.
  HWY_INLINE void add(int py, int xl, int xr, int x0, int x1, RowTarget target) {
    if (step_ == 1) {  // per-pixel Phong
      ShadeSpan(in_->bary, in_->depth, py, x0, x1, target,
                [&](auto d, const auto& o) { return PhongShade<kLocal, kLobe>(d, *in_, o); });
      return;
    }
    if (RowHidden(py, x0, x1, target)) return;
    // Segments start at the row's first covered pixel xl (every tile finds the same ends),
    // not at multiples of the step: a row as short as a segment then has two ends, not three.
    const int g0 = xl + ((x0 - xl) & ~(step_ - 1)), g_last = xl + ((x1 - xl) & ~(step_ - 1)) + step_;
    const int count = (g_last - g0) / step_ + 1;
    if (ends_ + count > kMaxEnds || rows_ == kMaxRows) flush();
    rows_at_[rows_++] = {py, xl, xr, x0, x1, ends_, target.depth, target.color, target.alpha_xor};
    for (int g = g0; g <= g_last; g += step_, ++ends_) {
      end_x_[ends_] = std::min(g, xr);
      end_dy_[ends_] = py - in_->bary.ay;
    }
  }

  void flush() {
    if (rows_ == 0) return;
    const hn::ScalableTag<float> d;
    const hn::RebindToSigned<decltype(d)> di;
    const int lanes = static_cast<int>(hn::Lanes(d));
    for (int j = ends_; j <= ends_ + lanes; ++j)  // padding: the last end repeated
      end_x_[j] = end_x_[ends_ - 1], end_dy_[j] = end_dy_[ends_ - 1];
    specular_ ? light_ends<true>() : light_ends<false>();
    // Each end's segment to the next as a slope per pixel, once per end instead of a division
    // per pixel. The slopes of a row's last end (to the next row's first, or to the padding)
    // are never picked; the end past the last vector is zeroed so they stay finite.
    const int channels = split_ >= 0 ? 4 : 3;
    const int computed = (ends_ + lanes - 1) / lanes * lanes;
    for (int c = 0; c < channels; ++c) end_c_[c][computed] = 0.0f;
    for (int j = 0; j < ends_; j += lanes) {
      const auto len = hn::ConvertTo(d, hn::Sub(hn::LoadU(di, end_x_ + j + 1), hn::Load(di, end_x_ + j)));
      const auto has_len = hn::Gt(len, hn::Zero(d));
      const auto divisor = hn::Max(len, hn::Set(d, 1.0f));  // len where it counts
      for (int c = 0; c < channels; ++c) {
        const auto rise = hn::Sub(hn::LoadU(d, end_c_[c] + j + 1), hn::Load(d, end_c_[c] + j));
        hn::Store(hn::IfThenElseZero(has_len, hn::Div(rise, divisor)), d, end_slope_[c] + j);
      }
    }
    for (int r = 0; r < rows_; ++r) split_ >= 0 ? interpolate<true>(rows_at_[r]) : interpolate<false>(rows_at_[r]);
    rows_ = ends_ = 0;
  }

 private:
  // Phong at every end; kSpecular = false where the plan found the specular terms negligible.
  template <bool kSpecular>
  void light_ends() {
    const hn::ScalableTag<float> d;
    const hn::RebindToSigned<decltype(d)> di;
    const int lanes = static_cast<int>(hn::Lanes(d));
    for (int j = 0; j < ends_; j += lanes) {
      const auto o = MakeLaneOffsets(d, in_->bary, hn::Load(di, end_x_ + j), hn::ConvertTo(d, hn::Load(di, end_dy_ + j)));
      auto n_dot_l = hn::Zero(d);
      const auto c = split_ >= 0 ? PhongColor<kLocal, kLobe, kSpecular, true>(d, *in_, o, split_, &n_dot_l)
                                 : PhongColor<kLocal, kLobe, kSpecular>(d, *in_, o);
      hn::Store(c.r, d, end_c_[0] + j);
      hn::Store(c.g, d, end_c_[1] + j);
      hn::Store(c.b, d, end_c_[2] + j);
      hn::Store(n_dot_l, d, end_c_[3] + j);
    }
  }

  struct Row {  // trivially constructible: the buffer of rows costs nothing to create
    int py, xl, xr, x0, x1, first_end;
    float* depth;
    uint32_t* color;
    uint32_t alpha_xor;
  };

  // Whether no pixel of the row passes the depth test: then its segment ends need no Phong (a
  // closed mesh drawn without culling hides about half its rows behind rows drawn before).
  // Exact: nothing else draws into the tile before the flush that would use them, and
  // interpolate() tests the same depths again.
  bool RowHidden(int py, int x0, int x1, RowTarget target) const {
    const hn::ScalableTag<float> d;
    const hn::RebindToSigned<decltype(d)> di;
    const int lanes = static_cast<int>(hn::Lanes(d));
    const auto dy = hn::Set(d, static_cast<float>(py - in_->bary.ay));
    for (int x = x0; x <= x1; x += lanes) {
      const auto xi = hn::Add(hn::Set(di, x), hn::Iota(di, 0));
      const auto inside = hn::RebindMask(d, hn::Lt(xi, hn::Set(di, x1 + 1)));
      const auto z = EvalPlane(d, in_->depth, MakeLaneOffsets(d, in_->bary, xi, dy));
      if (!hn::AllFalse(d, hn::And(inside, hn::Lt(z, hn::LoadU(d, target.depth + x))))) return false;
    }
    return true;
  }

  // A vector of `lanes` pixels meets at most lanes / step + 1 segments (step >= 2), whose
  // start colours and slopes fit in one vector each: lanes pick their segment's by permuting
  // the vectors loaded at the vector's first segment. Lanes past x1 (masked off) take x1's,
  // so every pick is one of the row's segments.
  template <bool kSplit>
  void interpolate(const Row& row) {
    const RowTarget target{row.depth, row.color, row.alpha_xor};
    // The vector's first pixel x comes in a register: the lanes' pixels and the first lane's
    // segment need no conversion from the offsets and no extract, which fed the loads' address.
    WithNarrowestVector(row.x1 - row.x0 + 1, [&](auto dv) {
      ShadeSpanAt(dv, in_->bary, in_->depth, row.py, row.x0, row.x1, target, [&](auto d, const auto&, int x) {
        const hn::RebindToSigned<decltype(d)> di;
        // Pixels relative to the row's first, where its segments start (add() above).
        const auto from_xl = hn::Sub(hn::Min(hn::Add(hn::Iota(di, 0), hn::Set(di, x)), hn::Set(di, row.x1)),
                                     hn::Set(di, row.xl));
        const auto seg = hn::ShiftRightSame(from_xl, shift_);
        const int first_seg = (x - row.xl) >> shift_;
        const int at = row.first_end + first_seg - ((row.x0 - row.xl) >> shift_);
        const auto pick = hn::IndicesFromVec(d, hn::Sub(seg, hn::Set(di, first_seg)));
        const auto dx = hn::ConvertTo(d, hn::And(from_xl, hn::Set(di, step_ - 1)));  // x - its segment's start
        auto channel = [&](int c) {
          const auto ca = hn::TableLookupLanes(hn::LoadU(d, end_c_[c] + at), pick);
          return hn::Add(ca, hn::Mul(dx, hn::TableLookupLanes(hn::LoadU(d, end_slope_[c] + at), pick)));
        };
        if constexpr (kSplit) {
          const auto n_dot_l = hn::Max(channel(3), hn::Zero(d));
          auto lit = [&](int c) { return hn::Add(channel(c), hn::Mul(hn::Set(d, split_kd_[c]), n_dot_l)); };
          return PackRGBA(d, lit(0), lit(1), lit(2), srgb_);
        } else {
          return PackRGBA(d, channel(0), channel(1), channel(2), srgb_);
        }
      });
    });
  }

  static constexpr int kMaxEnds = limits::kHybridMaxEnds;
  static constexpr int kMaxRows = kMaxEnds / 2;  // a row has at least two ends
  static constexpr int kPad = 2 * HWY_MAX_BYTES / sizeof(float);  // keeps every array 64-byte aligned
  // No member is initialised beyond these: the buffers are written before they are read, and
  // zeroing them (as std::optional's storage was) cost 12 KB of memset per triangle and tile.
  const PhongSpanInput* in_ = nullptr;
  int step_ = 1, shift_ = 0, split_ = -1;
  bool specular_ = true, srgb_ = false;
  float split_kd_[3];  // the split light's colour times kd, per channel
  int rows_ = 0, ends_ = 0;
  Row rows_at_[kMaxRows];
  alignas(64) int32_t end_x_[kMaxEnds + kPad], end_dy_[kMaxEnds + kPad];
  alignas(64) float end_c_[4][kMaxEnds + kPad];  // colour, and the split light's N.L
  alignas(64) float end_slope_[4][kMaxEnds + kPad];  // their change per pixel to the next end
};

template <bool kLocal, LobeKernel kLobe>
void HybridSpanImpl(const PhongSpanInput& in, const HybridRun& run, int py, int x0, int x1,
                    RowTarget row) {
  HybridRows<kLocal, kLobe> rows;
  rows.start(in, run.step, run.split_light, run.specular);
  rows.add(py, run.xl, run.xr, x0, x1, row);
  rows.flush();
}

template <bool kLocal, LobeKernel kLobe>
void DrawHybrid(const Frame& frame, uint32_t entry, const TileTarget& tt) {
  HybridRows<kLocal, kLobe> rows;  // started once `in` is ready
  DrawByRowRuns<kLocal, kLobe>(
      frame, entry, tt, limits::kHybridMinWidthPx,
      [&](const PhongSpanInput& in) {
        const SetupTriangle& t = frame.triangle(entry);
        rows.start(in, Frame::segment_step_px(t), Frame::split_light(t), Frame::segment_specular(t));
      },
      [&](const PhongSpanInput&, int xl, int xr, int py, int x0, int x1, RowTarget row) {
        rows.add(py, xl, xr, x0, x1, row);
      },
      [&](const PhongSpanInput&) { rows.flush(); });
}

using HybridSpanFn = void (*)(const PhongSpanInput&, const HybridRun&, int, int, int, RowTarget);
FASTSHADE_DEFINE_VARIANT_PICKER(SelectHybrid, DrawHybrid, DrawTriangleFn)
FASTSHADE_DEFINE_VARIANT_PICKER(PickHybridSpan, HybridSpanImpl, HybridSpanFn)

void HybridSpan(const PhongSpanInput& in, const HybridRun& run, int py, int x0, int x1, RowTarget row) {
  PickHybridSpan(in.shade->local_viewer, in.material->lobe.kind)(in, run, py, x0, x1, row);
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace fastshade {

HWY_EXPORT(SelectHybrid);
HWY_EXPORT(HybridSpan);

DrawTriangleFn select_hybrid(SimdTarget simd, const ShadeConstants& shade) {
  return FASTSHADE_DISPATCH(simd, SelectHybrid)(shade.local_viewer, shade.brdf.kind);
}

void hybrid_span(SimdTarget simd, const PhongSpanInput& in, const HybridRun& run, int py, int x0, int x1, RowTarget row) {
  FASTSHADE_DISPATCH(simd, HybridSpan)(in, run, py, x0, x1, row);
}


// The scalar twin of HybridSpan.
void hybrid_span_scalar(const PhongSpanInput& in, const HybridRun& run, int py, int x0, int x1,
                        RowTarget row) {
  const bool srgb = in.shade->srgb;
  const int step = run.step;
  for (int px = x0; px <= x1; ++px) {
    const PixelOffsets o = pixel_offsets(in.bary, px, py);
    if (!depth_pass(in.depth, o, row.depth[px])) continue;
    PhongColor rgb;
    if (step == 1) {
      rgb = phong_color_scalar(in, o);
    } else {
      const int ea = run.xl + ((px - run.xl) & ~(step - 1)), eb = std::min(ea + step, run.xr);
      float da = 0.0f, db = 0.0f;  // the split light's N.L at the ends
      const PhongColor ca = phong_color_scalar(in, pixel_offsets(in.bary, ea, py), run.split_light, &da, run.specular);
      const PhongColor cb = phong_color_scalar(in, pixel_offsets(in.bary, eb, py), run.split_light, &db, run.specular);
      // The slope per pixel, then the offset from ea: the SIMD kernel's operations in order.
      const float len = static_cast<float>(eb - ea), dx = static_cast<float>(px - ea);
      auto along = [&](float a, float b) { return a + dx * (eb > ea ? (b - a) / len : 0.0f); };
      for (int ch = 0; ch < 3; ++ch) rgb.c[ch] = along(ca.c[ch], cb.c[ch]);
      if (run.split_light >= 0) {
        const float n_dot_l = std::max(along(da, db), 0.0f);
        const LightView& light = in.shade->lights[run.split_light];
        for (int ch = 0; ch < 3; ++ch) rgb.c[ch] = rgb.c[ch] + (light.color[ch] * in.material->kd[ch]) * n_dot_l;
      }
    }
    row.color[px] = pack_quantized(rgb, srgb);
  }
}

}  // namespace fastshade
#endif
