// The vertex transform in lanes: glm's mat4 * vec4 as (m0 x + m1 y) + (m2 z + m3 w), its
// mat3 * vec3 as (m0 x + m1 y) + m2 z, normalize as v * (1 / sqrt((x x + y y) + z z)), and
// project() in double with round-half-even for lrint: the same operations in the same order
// as the scalar reference, so the same bits (tests/front/vertex_transform_test.cpp).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "front/vertex_transform.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "core/dispatch.h"

#include <glm/geometric.hpp>

#include "front/vertex_transform.h"

HWY_BEFORE_NAMESPACE();
namespace fastshade {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Row r of m * (x, y, z, w) in glm's order.
template <class V>
HWY_INLINE V Mat4Row(const glm::mat4& m, int r, V x, V y, V z, V w) {
  const hn::DFromV<V> d;
  return hn::Add(hn::Add(hn::Mul(hn::Set(d, m[0][r]), x), hn::Mul(hn::Set(d, m[1][r]), y)),
                 hn::Add(hn::Mul(hn::Set(d, m[2][r]), z), hn::Mul(hn::Set(d, m[3][r]), w)));
}

// Lanes of double (projection) beside lanes of float (everything else), one vertex each.
void TransformVertices(const VertexTransform& xf, const glm::vec3* positions, const glm::vec3* normals,
                       std::size_t count, const VertexOutputs& out) {
  const hn::ScalableTag<double> dd;
  const hn::Rebind<float, decltype(dd)> df;
  const hn::Rebind<int32_t, decltype(dd)> di;
  const hn::Rebind<uint32_t, decltype(dd)> du;
  using VF = hn::Vec<decltype(df)>;
  const std::size_t lanes = hn::Lanes(dd);
  const Viewport& vp = xf.viewport;
  std::size_t i = 0;
  for (; i + lanes <= count; i += lanes) {
    VF x, y, z;
    hn::LoadInterleaved3(df, &positions[i].x, x, y, z);
    const VF one = hn::Set(df, 1.0f);
    const VF view[4] = {Mat4Row(xf.model_view, 0, x, y, z, one), Mat4Row(xf.model_view, 1, x, y, z, one),
                        Mat4Row(xf.model_view, 2, x, y, z, one), Mat4Row(xf.model_view, 3, x, y, z, one)};
    VF clip[4];
    for (int r = 0; r < 4; ++r) clip[r] = Mat4Row(xf.proj, r, view[0], view[1], view[2], view[3]);
    hn::StoreInterleaved4(clip[0], clip[1], clip[2], clip[3], df, &out.clip[i].x);
    // vertex_flags(): the outcode, then whether the vertex lies outside near/far or the guard band.
    const VF cx = clip[0], cy = clip[1], cz = clip[2], cw = clip[3], neg_w = hn::Neg(cw);
    auto bit = [&](auto mask, uint32_t value) { return hn::IfThenElseZero(hn::RebindMask(du, mask), hn::Set(du, value)); };
    auto flags = hn::Or(hn::Or(hn::Or(bit(hn::Lt(cx, neg_w), 1), bit(hn::Gt(cx, cw), 2)),
                               hn::Or(bit(hn::Lt(cy, neg_w), 4), bit(hn::Gt(cy, cw), 8))),
                        hn::Or(bit(hn::Lt(cz, neg_w), 16), bit(hn::Gt(cz, cw), 32)));
    const auto inside = hn::And(hn::And(hn::Ge(cz, neg_w), hn::Le(cz, cw)),
                                hn::And(hn::Le(hn::Abs(cx), hn::Mul(hn::Set(df, vp.guard_x), cw)),
                                        hn::Le(hn::Abs(cy), hn::Mul(hn::Set(df, vp.guard_y), cw))));
    flags = hn::Or(flags, bit(hn::Not(inside), kNeedsClip));
    const auto finite = hn::And(hn::And(hn::IsFinite(cx), hn::IsFinite(cy)), hn::And(hn::IsFinite(cz), hn::IsFinite(cw)));
    flags = hn::IfThenElse(hn::RebindMask(du, finite), flags, hn::Set(du, kNonFinite));
    alignas(64) uint32_t flag_lanes[HWY_MAX_BYTES / sizeof(double)];
    hn::Store(flags, du, flag_lanes);
    for (std::size_t k = 0; k < lanes; ++k) out.flags[i + k] = static_cast<uint8_t>(flag_lanes[k]);
    // project(): lanes that need clipping compute garbage here, which setup never reads.
    const auto inv_w = hn::Div(hn::Set(dd, 1.0), hn::PromoteTo(dd, cw));
    const auto half = hn::Set(dd, 0.5), one_d = hn::Set(dd, 1.0), unit = hn::Set(dd, double(limits::kSubpixelOne));
    const auto x_px = hn::Mul(hn::Mul(hn::Add(hn::Mul(hn::PromoteTo(dd, cx), inv_w), one_d), half), hn::Set(dd, double(vp.width)));
    const auto y_px = hn::Mul(hn::Mul(hn::Sub(one_d, hn::Mul(hn::PromoteTo(dd, cy), inv_w)), half), hn::Set(dd, double(vp.height)));
    const auto x_fx = hn::DemoteTo(di, hn::Round(hn::Mul(x_px, unit)));
    const auto y_fx = hn::DemoteTo(di, hn::Round(hn::Mul(y_px, unit)));
    const VF depth = hn::DemoteTo(df, hn::Add(hn::Mul(hn::Mul(hn::PromoteTo(dd, cz), inv_w), half), half));
    hn::StoreInterleaved4(hn::BitCast(du, x_fx), hn::BitCast(du, y_fx), hn::BitCast(du, depth),
                          hn::BitCast(du, hn::DemoteTo(df, inv_w)), du, reinterpret_cast<uint32_t*>(out.screen + i));
    if (!normals) continue;
    hn::StoreInterleaved3(view[0], view[1], view[2], df, &out.pos_view[i].x);
    VF nx, ny, nz;
    hn::LoadInterleaved3(df, &normals[i].x, nx, ny, nz);
    const glm::mat3& m = xf.normal_matrix;
    VF n[3];
    for (int r = 0; r < 3; ++r)
      n[r] = hn::Add(hn::Add(hn::Mul(hn::Set(df, m[0][r]), nx), hn::Mul(hn::Set(df, m[1][r]), ny)),
                     hn::Mul(hn::Set(df, m[2][r]), nz));
    const VF len2 = hn::Add(hn::Add(hn::Mul(n[0], n[0]), hn::Mul(n[1], n[1])), hn::Mul(n[2], n[2]));
    const VF inv_len = hn::Div(one, hn::Sqrt(len2));
    hn::StoreInterleaved3(hn::Mul(n[0], inv_len), hn::Mul(n[1], inv_len), hn::Mul(n[2], inv_len), df, &out.n_view[i].x);
  }
  if (i == count) return;
  const VertexOutputs tail{out.clip + i, out.screen + i, out.flags + i, normals ? out.n_view + i : nullptr,
                           normals ? out.pos_view + i : nullptr};
  transform_vertices_scalar(xf, positions + i, normals ? normals + i : nullptr, count - i, tail);
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace fastshade {

HWY_EXPORT(TransformVertices);

void transform_vertices(SimdTarget simd, const VertexTransform& xf, const glm::vec3* positions, const glm::vec3* normals,
                        std::size_t count, const VertexOutputs& out) {
  FASTSHADE_DISPATCH(simd, TransformVertices)(xf, positions, normals, count, out);
}

void transform_vertices_scalar(const VertexTransform& xf, const glm::vec3* positions, const glm::vec3* normals,
                               std::size_t count, const VertexOutputs& out) {
  for (std::size_t i = 0; i < count; ++i) {
    const glm::vec4 pos_view = xf.model_view * glm::vec4(positions[i], 1.0f);
    const glm::vec4 clip = xf.proj * pos_view;
    out.clip[i] = clip;
    out.flags[i] = vertex_flags(clip, xf.viewport);
    if (!(out.flags[i] & (kNeedsClip | kNonFinite))) out.screen[i] = project(clip, xf.viewport);
    if (!normals) continue;
    out.n_view[i] = glm::normalize(xf.normal_matrix * normals[i]);
    out.pos_view[i] = glm::vec3(pos_view);
  }
}

}  // namespace fastshade
#endif
