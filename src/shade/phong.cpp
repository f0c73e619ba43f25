// `phong`: per pixel, the perspective-correct normal (its n/w planes need no division: the
// 1/w factor vanishes when normalising), normalised, Blinn-Phong in float with exp/log pow.
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

struct PhongPlanes {
  Plane n[3];    // n_view / w
  Plane p[3];    // pos_view / w (local viewer)
  Plane inv_w;   // (local viewer)
};

template <bool kLocal, bool kSrgb, BrdfKind kBrdf>
void DrawPhong(const Frame& frame, uint32_t entry, const TileTarget& tt) {
  TriangleInTile tri;
  if (!prepare_triangle(frame.triangle(entry), tt.rect, tri)) return;
  const SetupTriangle& t = *tri.tri;
  const ShadeConstants& k = frame.shade;
  const MaterialConstants& m = k.materials[t.material];
  const float flip = (k.two_sided && (t.flags & kBackFacing)) ? -1.0f : 1.0f;
  // Shading planes are set up on the first vector that passes the depth test: in a dense
  // mesh many triangles are entirely hidden, and they cost only coverage and depth.
  PhongPlanes planes;
  bool planes_ready = false;
  auto set_up_planes = [&] {
    // Attributes over w: what varies linearly across the screen.
    auto plane_over_w = [&](AttrField field, int c, float scale) {
      double q[3];
      for (int i = 0; i < 3; ++i)
        q[i] = double(scale * frame.vertex(entry, t.attr[i], field)[c]) * t.inv_w[i];
      return make_plane(tri.bary, q[0], q[1], q[2]);
    };
    for (int c = 0; c < 3; ++c) {
      planes.n[c] = plane_over_w(&AttrArrays::n_view, c, flip);
      if constexpr (kLocal) planes.p[c] = plane_over_w(&AttrArrays::pos_view, c, 1.0f);
    }
    if constexpr (kLocal) planes.inv_w = make_plane(tri.bary, t.inv_w[0], t.inv_w[1], t.inv_w[2]);
    planes_ready = true;
  };

  ShadeTriangle(tri, tt, [&](auto d, const auto& o) {
      using V = decltype(o.k);
      if (!planes_ready) set_up_planes();
      V nx = EvalPlane(d, planes.n[0], o);
      V ny = EvalPlane(d, planes.n[1], o);
      V nz = EvalPlane(d, planes.n[2], o);
      const V len2 = hn::Add(hn::Add(hn::Mul(nx, nx), hn::Mul(ny, ny)), hn::Mul(nz, nz));
      const V inv_len = hn::IfThenElseZero(hn::Gt(len2, hn::Zero(d)), InvSqrt(d, len2));
      nx = hn::Mul(nx, inv_len);
      ny = hn::Mul(ny, inv_len);
      nz = hn::Mul(nz, inv_len);
      V vx, vy, vz;  // toward the eye (local viewer only)
      if constexpr (kLocal) {
        const V w = hn::Div(hn::Set(d, 1.0f),
                            EvalPlane(d, planes.inv_w, o));
        vx = hn::Neg(hn::Mul(EvalPlane(d, planes.p[0], o), w));
        vy = hn::Neg(hn::Mul(EvalPlane(d, planes.p[1], o), w));
        vz = hn::Neg(hn::Mul(EvalPlane(d, planes.p[2], o), w));
        const V inv =
            InvSqrt(d, hn::Add(hn::Add(hn::Mul(vx, vx), hn::Mul(vy, vy)), hn::Mul(vz, vz)));
        vx = hn::Mul(vx, inv);
        vy = hn::Mul(vy, inv);
        vz = hn::Mul(vz, inv);
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
          const V h2 = hn::Add(hn::Add(hn::Mul(hx, hx), hn::Mul(hy, hy)), hn::Mul(hz, hz));
          const V inv = hn::IfThenElseZero(hn::Gt(h2, hn::Zero(d)),
                                            InvSqrt(d, h2));
          hx = hn::Mul(hx, inv);
          hy = hn::Mul(hy, inv);
          hz = hn::Mul(hz, inv);
        } else {
          hx = hn::Set(d, light.h_view.x);
          hy = hn::Set(d, light.h_view.y);
          hz = hn::Set(d, light.h_view.z);
        }
        const V ndl = hn::Add(hn::Add(hn::Mul(nx, lx), hn::Mul(ny, ly)), hn::Mul(nz, lz));
        const V ndh = hn::Add(hn::Add(hn::Mul(nx, hx), hn::Mul(ny, hy)), hn::Mul(nz, hz));
        const V diffuse = hn::Max(ndl, hn::Zero(d));
        const V specular = Brdf<kBrdf>(d, ndh, m.lobe);
        r = hn::Add(r, hn::Mul(hn::Set(d, light.color.r),
                               hn::Add(hn::Mul(hn::Set(d, m.kd.r), diffuse),
                                       hn::Mul(hn::Set(d, m.ks.r), specular))));
        g = hn::Add(g, hn::Mul(hn::Set(d, light.color.g),
                               hn::Add(hn::Mul(hn::Set(d, m.kd.g), diffuse),
                                       hn::Mul(hn::Set(d, m.ks.g), specular))));
        b = hn::Add(b, hn::Mul(hn::Set(d, light.color.b),
                               hn::Add(hn::Mul(hn::Set(d, m.kd.b), diffuse),
                                       hn::Mul(hn::Set(d, m.ks.b), specular))));
      }
      return PackRGBA<kSrgb>(d, r, g, b);
  });
}

template <bool kLocal, bool kSrgb>
DrawTriangleFn PickBrdf(BrdfKind kind) {
  switch (kind) {
    case BrdfKind::Exact: return &DrawPhong<kLocal, kSrgb, BrdfKind::Exact>;
    case BrdfKind::CosK: return &DrawPhong<kLocal, kSrgb, BrdfKind::CosK>;
    case BrdfKind::Schlick: return &DrawPhong<kLocal, kSrgb, BrdfKind::Schlick>;
    case BrdfKind::SchlickPow2: return &DrawPhong<kLocal, kSrgb, BrdfKind::SchlickPow2>;
    case BrdfKind::Quadratic: return &DrawPhong<kLocal, kSrgb, BrdfKind::Quadratic>;
    case BrdfKind::QuadraticFit: return &DrawPhong<kLocal, kSrgb, BrdfKind::QuadraticFit>;
    case BrdfKind::Poly2: return &DrawPhong<kLocal, kSrgb, BrdfKind::Poly2>;
    case BrdfKind::Poly3: return &DrawPhong<kLocal, kSrgb, BrdfKind::Poly3>;
  }
  return nullptr;
}

// This target's variant for the frame: viewer, output curve and BRDF are template flags.
DrawTriangleFn SelectPhong(bool local, bool srgb, BrdfKind kind) {
  if (local) return srgb ? PickBrdf<true, true>(kind) : PickBrdf<true, false>(kind);
  return srgb ? PickBrdf<false, true>(kind) : PickBrdf<false, false>(kind);
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace fastshade {

HWY_EXPORT(SelectPhong);

AttrNeeds phong_needs(const ShadeConstants& shade) {
  return {.normal = true, .color = false, .position = shade.local_viewer};
}

DrawTriangleFn select_phong(const ShadeConstants& shade) {
  return HWY_DYNAMIC_DISPATCH(SelectPhong)(shade.local_viewer, shade.srgb, shade.brdf.kind);
}

}  // namespace fastshade
#endif
