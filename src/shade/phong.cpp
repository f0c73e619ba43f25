// `phong`: per pixel, the perspective-correct normal (its n/w planes need no division: the
// 1/w factor vanishes when normalising), normalised, Blinn-Phong in float with the frame's
// specular approximation (--brdf; exact: exp2/log2 to float precision).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shade/phong.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "shade/brdf-inl.h"
#include "shade/methods.h"
#include "shade/span_loop-inl.h"

HWY_BEFORE_NAMESPACE();
namespace fastshade {
namespace HWY_NAMESPACE {

template <class D, class V = hn::Vec<D>>
HWY_INLINE V Dot(V ax, V ay, V az, V bx, V by, V bz) {
  return hn::Add(hn::Add(hn::Mul(ax, bx), hn::Mul(ay, by)), hn::Mul(az, bz));
}

// Scales (x, y, z) to unit length; a zero vector stays zero.
template <class D, class V = hn::Vec<D>>
HWY_INLINE void Normalize(D d, V& x, V& y, V& z) {
  const V len2 = Dot<D>(x, y, z, x, y, z);
  const V inv = hn::IfThenElseZero(hn::Gt(len2, hn::Zero(d)), InvSqrt(d, len2));
  x = hn::Mul(x, inv);
  y = hn::Mul(y, inv);
  z = hn::Mul(z, inv);
}

template <bool kLocal, bool kSrgb, BrdfKind kBrdf, class D>
HWY_INLINE auto PhongShade(D d, const PhongSpanInput& in, const LaneOffsets<D>& o) {
  using V = hn::Vec<D>;
  const MaterialConstants& m = *in.material;
  const ShadeConstants& k = *in.shade;
  V nx = EvalPlane(d, in.n[0], o), ny = EvalPlane(d, in.n[1], o), nz = EvalPlane(d, in.n[2], o);
  Normalize(d, nx, ny, nz);
  V vx, vy, vz;  // toward the eye (local viewer only)
  if constexpr (kLocal) {
    const V w = hn::Div(hn::Set(d, 1.0f), EvalPlane(d, in.inv_w, o));
    vx = hn::Neg(hn::Mul(EvalPlane(d, in.p[0], o), w));
    vy = hn::Neg(hn::Mul(EvalPlane(d, in.p[1], o), w));
    vz = hn::Neg(hn::Mul(EvalPlane(d, in.p[2], o), w));
    Normalize(d, vx, vy, vz);
  }
  V r = hn::Set(d, k.ambient.r), g = hn::Set(d, k.ambient.g), b = hn::Set(d, k.ambient.b);
  for (const LightView& light : k.lights) {
    const V lx = hn::Set(d, light.l_view.x), ly = hn::Set(d, light.l_view.y),
            lz = hn::Set(d, light.l_view.z);
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
    const V diffuse = hn::Max(Dot<D>(nx, ny, nz, lx, ly, lz), hn::Zero(d));
    const V specular = Brdf<kBrdf>(d, Dot<D>(nx, ny, nz, hx, hy, hz), m.lobe);
    auto channel = [&](V acc, int c) {
      return hn::Add(acc, hn::Mul(hn::Set(d, light.color[c]),
                                  hn::Add(hn::Mul(hn::Set(d, m.kd[c]), diffuse),
                                          hn::Mul(hn::Set(d, m.ks[c]), specular))));
    };
    r = channel(r, 0);
    g = channel(g, 1);
    b = channel(b, 2);
  }
  return PackRGBA<kSrgb>(d, r, g, b);
}

template <bool kLocal, bool kSrgb, BrdfKind kBrdf>
void DrawPhong(const Frame& frame, uint32_t entry, const TileTarget& tt) {
  TriangleInTile tri;
  if (!prepare_triangle(frame.triangle(entry), tt.rect, tri)) return;
  const SetupTriangle& t = *tri.tri;
  const ShadeConstants& k = frame.shade;
  // Shading planes are set up on the first vector that passes the depth test: in a dense
  // mesh many triangles are entirely hidden, and they cost only coverage and depth.
  PhongSpanInput in;
  in.material = &k.materials[t.material];
  in.shade = &k;
  bool ready = false;
  auto set_up = [&] {
    const float flip = (k.two_sided && (t.flags & kBackFacing)) ? -1.0f : 1.0f;
    auto plane_over_w = [&](AttrField field, int c, float scale) {  // linear in screen space
      double q[3];
      for (int i = 0; i < 3; ++i)
        q[i] = double(scale * frame.vertex(entry, t.attr[i], field)[c]) * t.inv_w[i];
      return make_plane(tri.bary, q[0], q[1], q[2]);
    };
    for (int c = 0; c < 3; ++c) {
      in.n[c] = plane_over_w(&AttrArrays::n_view, c, flip);
      if constexpr (kLocal) in.p[c] = plane_over_w(&AttrArrays::pos_view, c, 1.0f);
    }
    if constexpr (kLocal) in.inv_w = make_plane(tri.bary, t.inv_w[0], t.inv_w[1], t.inv_w[2]);
    ready = true;
  };
  ShadeTriangle(tri, tt, [&](auto d, const auto& o) {
    if (!ready) set_up();
    return PhongShade<kLocal, kSrgb, kBrdf>(d, in, o);
  });
}

// One function pointer per variant: viewer, output curve and BRDF are template flags.
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
DrawTriangleFn PickDraw(BrdfKind kind) { FASTSHADE_BRDF_CASES(&DrawPhong, kLocal, kSrgb) }

DrawTriangleFn SelectPhong(bool local, bool srgb, BrdfKind kind) {
  if (local) return srgb ? PickDraw<true, true>(kind) : PickDraw<true, false>(kind);
  return srgb ? PickDraw<false, true>(kind) : PickDraw<false, false>(kind);
}

template <bool kLocal, bool kSrgb, BrdfKind kBrdf>
void PhongSpanVariant(const PhongSpanInput& in, int py, int x0, int x1, RowTarget row) {
  ShadeSpan(in.bary, in.depth, py, x0, x1, row,
            [&](auto d, const auto& o) { return PhongShade<kLocal, kSrgb, kBrdf>(d, in, o); });
}

using PhongSpanFn = void (*)(const PhongSpanInput&, int, int, int, RowTarget);

template <bool kLocal, bool kSrgb>
PhongSpanFn PickSpan(BrdfKind kind) { FASTSHADE_BRDF_CASES(&PhongSpanVariant, kLocal, kSrgb) }
#undef FASTSHADE_BRDF_CASES

void PhongSpan(const PhongSpanInput& in, int py, int x0, int x1, RowTarget row) {
  const bool local = in.shade->local_viewer, srgb = in.shade->srgb;
  const BrdfKind kind = in.material->lobe.kind;
  const PhongSpanFn fn = local ? (srgb ? PickSpan<true, true>(kind) : PickSpan<true, false>(kind))
                               : (srgb ? PickSpan<false, true>(kind) : PickSpan<false, false>(kind));
  fn(in, py, x0, x1, row);
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace fastshade {

HWY_EXPORT(SelectPhong);
HWY_EXPORT(PhongSpan);

AttrNeeds phong_needs(const ShadeConstants& shade) {
  return {.normal = true, .color = false, .position = shade.local_viewer};
}

DrawTriangleFn select_phong(const ShadeConstants& shade) {
  return HWY_DYNAMIC_DISPATCH(SelectPhong)(shade.local_viewer, shade.srgb, shade.brdf.kind);
}

void phong_span(const PhongSpanInput& in, int py, int x0, int x1, RowTarget row) {
  HWY_DYNAMIC_DISPATCH(PhongSpan)(in, py, x0, x1, row);
}

}  // namespace fastshade
#endif
