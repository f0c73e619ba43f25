#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "front/triangle_fate.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <algorithm>
#include <cstring>

#include <hwy/highway.h>

#include "core/dispatch.h"
#include "core/limits.h"
#include "core/mask_bits-inl.h"
#include "frame/edge_function.h"
#include "front/triangle_fate.h"

HWY_BEFORE_NAMESPACE();
namespace fastshade {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// decide_triangle() in double lanes: every quantity is an integer below 2^53 (limits.h: deltas
// of 24 bits, products of 48; doubled coordinates of 25 bits, edge values below 2^51), so each
// is exact in a double, whatever the order of operations (or an FMA) the compiler picks, and the
// answers are the scalar int64 ones. The box is found in int32 lanes alongside.
void DecideTriangles(const TriangleColumns& in, int count, int width, int height, bool cull_back,
                     TriangleFates& out) {
  const hn::ScalableTag<double> d;
  const hn::Rebind<int32_t, decltype(d)> di;
  const int lanes = static_cast<int>(hn::Lanes(d));
  std::memset(out.kept, 0, sizeof(out.kept));
  std::memset(out.back, 0, sizeof(out.back));
  out.dropped = out.culled = 0;
  const auto half = hn::Set(di, limits::kSubpixelOne / 2);
  const auto round_up = hn::Set(di, limits::kSubpixelOne - 1);
  const auto zero_i = hn::Zero(di);
  const auto last_x = hn::Set(di, width - 1), last_y = hn::Set(di, height - 1);
  const auto zero = hn::Zero(d), one = hn::Set(d, 1.0), two = hn::Set(d, 2.0);
  const auto unit = hn::Set(di, static_cast<int32_t>(kEdgeUnitsPerPixel));
  const auto centre = hn::Set(di, static_cast<int32_t>(kEdgeUnitsPerPixel / 2));
  for (int i = 0; i < count; i += lanes) {
    const auto valid = hn::FirstN(d, static_cast<size_t>(count - i));
    hn::Vec<decltype(di)> xi[3], yi[3];
    hn::Vec<decltype(d)> x[3], y[3];
    for (int v = 0; v < 3; ++v) {
      xi[v] = hn::LoadU(di, in.x_fx[v] + i);
      yi[v] = hn::LoadU(di, in.y_fx[v] + i);
      x[v] = hn::PromoteTo(d, xi[v]);
      y[v] = hn::PromoteTo(d, yi[v]);
    }
    const auto area = hn::Sub(hn::Mul(hn::Sub(x[1], x[0]), hn::Sub(y[2], y[0])),
                              hn::Mul(hn::Sub(x[2], x[0]), hn::Sub(y[1], y[0])));
    const auto degenerate = hn::Eq(area, zero);
    const auto back = hn::Gt(area, zero);
    const auto px0 = hn::Max(hn::ShiftRight<limits::kSubpixelBits>(hn::Add(
                                 hn::Sub(hn::Min(hn::Min(xi[0], xi[1]), xi[2]), half), round_up)), zero_i);
    const auto py0 = hn::Max(hn::ShiftRight<limits::kSubpixelBits>(hn::Add(
                                 hn::Sub(hn::Min(hn::Min(yi[0], yi[1]), yi[2]), half), round_up)), zero_i);
    const auto px1 = hn::Min(hn::ShiftRight<limits::kSubpixelBits>(
                                 hn::Sub(hn::Max(hn::Max(xi[0], xi[1]), xi[2]), half)), last_x);
    const auto py1 = hn::Min(hn::ShiftRight<limits::kSubpixelBits>(
                                 hn::Sub(hn::Max(hn::Max(yi[0], yi[1]), yi[2]), half)), last_y);
    // Compared as doubles: masks keep their lane count, not their lane size, across types.
    const auto bx0 = hn::PromoteTo(d, px0), by0 = hn::PromoteTo(d, py0);
    const auto bx1 = hn::PromoteTo(d, px1), by1 = hn::PromoteTo(d, py1);
    const auto empty = hn::Or(hn::Gt(bx0, bx1), hn::Gt(by0, by1));
    const auto single = hn::And(hn::Eq(bx0, bx1), hn::Eq(by0, by1));
    // The one candidate centre against the wound triangle (a, v1, v2), doubled coordinates:
    // E = dx (Y - ya) - dy (X - xa) >= threshold for each edge a -> b, as Edge::covers.
    const auto cx = hn::PromoteTo(d, hn::Add(hn::Mul(px0, unit), centre));
    const auto cy = hn::PromoteTo(d, hn::Add(hn::Mul(py0, unit), centre));
    const hn::Vec<decltype(d)> wx[3] = {hn::Mul(two, x[0]), hn::Mul(two, hn::IfThenElse(back, x[1], x[2])),
                                        hn::Mul(two, hn::IfThenElse(back, x[2], x[1]))};
    const hn::Vec<decltype(d)> wy[3] = {hn::Mul(two, y[0]), hn::Mul(two, hn::IfThenElse(back, y[1], y[2])),
                                        hn::Mul(two, hn::IfThenElse(back, y[2], y[1]))};
    auto edge_covers = [&](int k) {
      const int p = (k + 1) % 3, q = (k + 2) % 3;
      const auto dx = hn::Sub(wx[q], wx[p]), dy = hn::Sub(wy[q], wy[p]);
      const auto e = hn::Sub(hn::Mul(dx, hn::Sub(cy, wy[p])), hn::Mul(dy, hn::Sub(cx, wx[p])));
      const auto top_left = hn::Or(hn::Lt(dy, zero), hn::And(hn::Eq(dy, zero), hn::Gt(dx, zero)));
      return hn::Ge(e, hn::IfThenZeroElse(top_left, one));
    };
    const auto covers = hn::And(hn::And(edge_covers(0), edge_covers(1)), edge_covers(2));
    auto culled = hn::Or(empty, hn::AndNot(covers, single));
    if (cull_back) culled = hn::Or(culled, back);
    culled = hn::AndNot(degenerate, hn::And(valid, culled));
    const auto dropped = hn::And(valid, degenerate);
    const auto kept = hn::AndNot(hn::Or(dropped, culled), valid);
    out.dropped += static_cast<int>(hn::CountTrue(d, dropped));
    out.culled += static_cast<int>(hn::CountTrue(d, culled));
    // lanes divides 64, so a vector's bits never straddle two words.
    out.kept[i / 64] |= MaskBits(d, kept) << (i % 64);
    out.back[i / 64] |= MaskBits(d, hn::And(kept, back)) << (i % 64);
    hn::StoreU(px0, di, out.x0 + i);
    hn::StoreU(py0, di, out.y0 + i);
    hn::StoreU(px1, di, out.x1 + i);
    hn::StoreU(py1, di, out.y1 + i);
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace fastshade {

static_assert(kFateBlock % 64 == 0 && kFatePad >= HWY_MAX_BYTES / sizeof(double));

HWY_EXPORT(DecideTriangles);

namespace {

bool covers_centre(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, int px, int py) {
  const int64_t x = pixel_centre_fx(px), y = pixel_centre_fx(py);
  auto edge = [](const ScreenVertex& p, const ScreenVertex& q) {  // doubled coordinates
    return make_edge(2 * int64_t(p.x_fx), 2 * int64_t(p.y_fx), 2 * int64_t(q.x_fx), 2 * int64_t(q.y_fx));
  };
  return edge(b, c).covers(x, y) && edge(c, a).covers(x, y) && edge(a, b).covers(x, y);
}

}  // namespace

TriangleDecision decide_triangle(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c,
                                 int width, int height, bool cull_back) {
  const int64_t area = (int64_t(b.x_fx) - a.x_fx) * (int64_t(c.y_fx) - a.y_fx) -
                       (int64_t(c.x_fx) - a.x_fx) * (int64_t(b.y_fx) - a.y_fx);
  TriangleDecision out{TriangleFate::kCulled, {}};
  if (area == 0) {
    out.fate = TriangleFate::kDropped;
    return out;
  }
  // GL's front face is counter-clockwise with y up, i.e. negative area with y down.
  const bool back_facing = area > 0;
  if (back_facing && cull_back) return out;
  const int32_t half = limits::kSubpixelOne / 2;
  PixelBox& box = out.box;
  box.x0 = std::max((std::min({a.x_fx, b.x_fx, c.x_fx}) - half + limits::kSubpixelOne - 1) >> limits::kSubpixelBits, 0);
  box.y0 = std::max((std::min({a.y_fx, b.y_fx, c.y_fx}) - half + limits::kSubpixelOne - 1) >> limits::kSubpixelBits, 0);
  box.x1 = std::min((std::max({a.x_fx, b.x_fx, c.x_fx}) - half) >> limits::kSubpixelBits, width - 1);
  box.y1 = std::min((std::max({a.y_fx, b.y_fx, c.y_fx}) - half) >> limits::kSubpixelBits, height - 1);
  if (box.x0 > box.x1 || box.y0 > box.y1) return out;  // covers no pixel centre
  // Most triangles of a dense mesh have one candidate pixel centre; testing it here keeps those
  // that miss it out of the bins. The rasterizer's winding: front faces swap their last two.
  const ScreenVertex& v1 = back_facing ? b : c;
  const ScreenVertex& v2 = back_facing ? c : b;
  if (box.x0 == box.x1 && box.y0 == box.y1 && !covers_centre(a, v1, v2, box.x0, box.y0)) return out;
  out.fate = back_facing ? TriangleFate::kBack : TriangleFate::kFront;
  return out;
}

void decide_triangles(SimdTarget simd, const TriangleColumns& in, int count, int width, int height, bool cull_back,
                      TriangleFates& out) {
  FASTSHADE_DISPATCH(simd, DecideTriangles)(in, count, width, height, cull_back, out);
}

void decide_triangles_scalar(const TriangleColumns& in, int count, int width, int height, bool cull_back,
                             TriangleFates& out) {
  std::memset(out.kept, 0, sizeof(out.kept));
  std::memset(out.back, 0, sizeof(out.back));
  out.dropped = out.culled = 0;
  for (int i = 0; i < count; ++i) {
    ScreenVertex v[3];
    for (int k = 0; k < 3; ++k) v[k] = {in.x_fx[k][i], in.y_fx[k][i], 0.0f, 0.0f};
    const TriangleDecision t = decide_triangle(v[0], v[1], v[2], width, height, cull_back);
    out.dropped += t.fate == TriangleFate::kDropped;
    out.culled += t.fate == TriangleFate::kCulled;
    if (t.fate == TriangleFate::kFront || t.fate == TriangleFate::kBack) {
      out.kept[i / 64] |= uint64_t(1) << (i % 64);
      if (t.fate == TriangleFate::kBack) out.back[i / 64] |= uint64_t(1) << (i % 64);
      out.x0[i] = t.box.x0, out.y0[i] = t.box.y0, out.x1[i] = t.box.x1, out.y1[i] = t.box.y1;
    }
  }
}

}  // namespace fastshade
#endif
