// Phong's per-pixel colour as SIMD (per-target, Highway "-inl.h"), shared by the phong and
// hybrid kernels.
#if defined(FASTSHADE_SHADE_PHONG_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FASTSHADE_SHADE_PHONG_INL_H_
#undef FASTSHADE_SHADE_PHONG_INL_H_
#else
#define FASTSHADE_SHADE_PHONG_INL_H_
#endif

#include <algorithm>

#include <hwy/highway.h>

#include "core/dot3-inl.h"
#include "shade/brdf-inl.h"
#include "shade/method.h"
#include "shade/methods.h"
#include "shade/planes_over_w-inl.h"
#include "shade/span_loop-inl.h"

HWY_BEFORE_NAMESPACE();
namespace fastshade {
namespace HWY_NAMESPACE {

// Scales (x, y, z) to unit length; a zero vector (or one too short for InvSqrt) becomes zero.
template <class D, class V = hn::Vec<D>>
HWY_INLINE void Normalize(D d, V& x, V& y, V& z) {
  const V len2 = Dot3<D>(x, y, z, x, y, z);
  const V inv = hn::IfThenElseZero(hn::Ge(len2, hn::Set(d, fast_math::kMinInvSqrtInput)), InvSqrt(d, len2));
  x = hn::Mul(x, inv);
  y = hn::Mul(y, inv);
  z = hn::Mul(z, inv);
}

template <class D>
struct ColorVecs {
  hn::Vec<D> r, g, b;
};

// Blinn-Phong at the lanes' pixels before quantisation; phong_color_scalar() is its twin.
// kSpecular = false: the diffuse-only colour (`auto`'s per-pixel diffuse path).
template <bool kLocal, BrdfKind kBrdf, bool kSpecular = true, class D, class V = hn::Vec<D>>
HWY_INLINE ColorVecs<D> PhongColorFromNormal(D d, const PhongSpanInput& in, V nx, V ny, V nz,
                                             const LaneOffsets<D>& o);

template <bool kLocal, BrdfKind kBrdf, bool kSpecular = true, class D>
HWY_INLINE ColorVecs<D> PhongColor(D d, const PhongSpanInput& in, const LaneOffsets<D>& o) {
  using V = hn::Vec<D>;
  V nx = EvalPlane(d, in.n[0], o), ny = EvalPlane(d, in.n[1], o), nz = EvalPlane(d, in.n[2], o);
  Normalize(d, nx, ny, nz);
  return PhongColorFromNormal<kLocal, kBrdf, kSpecular>(d, in, nx, ny, nz, o);
}

// Blinn-Phong for unit normals in lanes; phong_color_from_normal_scalar() is its twin.
template <bool kLocal, BrdfKind kBrdf, bool kSpecular, class D, class V>
HWY_INLINE ColorVecs<D> PhongColorFromNormal(D d, const PhongSpanInput& in, V nx, V ny, V nz,
                                             const LaneOffsets<D>& o) {
  const MaterialConstants& m = *in.material;
  const ShadeConstants& k = *in.shade;
  V vx, vy, vz;  // toward the eye (local viewer only)
  if constexpr (kLocal && kSpecular) {
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
    const V diffuse = hn::Max(Dot3<D>(nx, ny, nz, lx, ly, lz), hn::Zero(d));
    V specular = hn::Zero(d);
    if constexpr (kSpecular) {
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
      specular = Brdf<kBrdf>(d, Dot3<D>(nx, ny, nz, hx, hy, hz), m.lobe);
    }
    auto channel = [&](V acc, int c) {
      const V kd_diffuse = hn::Mul(hn::Set(d, m.kd[c]), diffuse);
      // Diffuse only: no ks * 0 term, so no cost (the sum is the same: x + 0 = x).
      const V lit = kSpecular ? hn::Add(kd_diffuse, hn::Mul(hn::Set(d, m.ks[c]), specular)) : kd_diffuse;
      return hn::Add(acc, hn::Mul(hn::Set(d, light.color[c]), lit));
    };
    r = channel(r, 0);
    g = channel(g, 1);
    b = channel(b, 2);
  }
  return {r, g, b};
}

// The normal planes (and, for a local viewer, position and 1/w planes) of a binned triangle:
// attributes over w, linear in screen space. Back faces of two-sided scenes flip the normal.
template <bool kLocal>
HWY_INLINE void set_up_phong_planes(const Frame& frame, uint32_t entry, const SetupTriangle& t,
                                    const Barycentrics& bary, PhongSpanInput& in) {
  const ShadeConstants& k = frame.shade;
  const float flip = (k.two_sided && (t.flags & kBackFacing)) ? -1.0f : 1.0f;
  // Each vertex's attribute is fetched once (a fetch decodes the clipped-vertex tag), then
  // split into one plane per component (PlanesOverW: make_plane of (scale v) / w, scale +-1,
  // which keeps float(scale v) exact, and of 1/w).
  auto planes_over_w = [&](AttrField field, float scale, Plane* planes) {
    glm::vec3 v[3];
    for (int i = 0; i < 3; ++i) v[i] = frame.vertex(entry, t.attr[i], field);
    Plane all[4];
    PlanesOverW(bary, v, scale, t.inv_w, all);
    std::copy(all, all + 3, planes);
    return all[3];
  };
  planes_over_w(&AttrArrays::n_view, flip, in.n);
  if constexpr (kLocal) in.inv_w = planes_over_w(&AttrArrays::pos_view, 1.0f, in.p);
}

template <bool kLocal, bool kSrgb, BrdfKind kBrdf, bool kSpecular = true, class D>
HWY_INLINE auto PhongShade(D d, const PhongSpanInput& in, const LaneOffsets<D>& o) {
  const ColorVecs<D> c = PhongColor<kLocal, kBrdf, kSpecular>(d, in, o);
  return PackRGBA<kSrgb>(d, c.r, c.g, c.b);
}

// A material float cannot shade within 1 LSB (docs/STABILITY.md, "Fallbacks") is drawn by the
// reference; the flag is only ever set for exact cos^n, and only its highlight needs it.
HWY_INLINE bool ShadesInDouble(const Frame& frame, uint32_t entry) {
  return frame.shade.materials[frame.triangle(entry).material].shade_in_double;
}

// `phong` for one binned triangle in a tile; kSpecular = false: `auto`'s per-pixel diffuse.
template <bool kLocal, bool kSrgb, BrdfKind kBrdf, bool kSpecular = true>
void DrawPhong(const Frame& frame, uint32_t entry, const TileTarget& tt) {
  if (kSpecular && ShadesInDouble(frame, entry)) return draw_reference(frame, entry, tt);
  TriangleInTile tri;
  if (!place_in_tile(frame.triangle(entry), tt.rect, tri)) return;
  const SetupTriangle& t = *tri.tri;
  const ShadeConstants& k = frame.shade;
  // Shading planes are set up on the first vector that passes the depth test: in a dense
  // mesh many triangles are entirely hidden, and they cost only coverage and depth.
  PhongSpanInput in;
  in.material = &k.materials[t.material];
  in.shade = &k;
  bool ready = false;
  auto set_up = [&] {
    set_up_phong_planes<kLocal>(frame, entry, t, tri.bary, in);
    ready = true;
  };
  ShadeTriangle(tri, tt, [&](auto d, const auto& o) {
    if (!ready) set_up();
    return PhongShade<kLocal, kSrgb, kBrdf, kSpecular>(d, in, o);
  });
}

// The frame of the span-run methods (hybrid, --normals): triangles narrower than min_width_px
// (whole box: every tile decides alike) take per-pixel Phong, and materials shaded in double
// the reference (through DrawPhong); the others walk rows through the
// whole triangle, tile rows only, because a row's covered run [xl, xr] fixes where segment or
// block ends go, whatever tile this is. on_setup(in) runs once, when the first run is found
// (planes are ready then); run(in, xl, xr, py, x0, x1, row) shades the tile's part [x0, x1];
// finish(in) runs after the last run, while `in` still lives (for kernels that batch rows).
struct NoFinish {
  void operator()(const PhongSpanInput&) const {}
};
template <bool kLocal, bool kSrgb, BrdfKind kBrdf, bool kSpecular = true, typename OnSetup, typename Run,
          typename Finish = NoFinish>
HWY_INLINE void DrawByRowRuns(const Frame& frame, uint32_t entry, const TileTarget& tt,
                              int min_width_px, OnSetup&& on_setup, Run&& run, Finish&& finish = {}) {
  const SetupTriangle& whole = frame.triangle(entry);
  if (whole.px_max[0] - whole.px_min[0] + 1 < min_width_px || (kSpecular && ShadesInDouble(frame, entry))) {
    DrawPhong<kLocal, kSrgb, kBrdf, kSpecular>(frame, entry, tt);
    return;
  }
  TriangleInTile tri;
  if (!prepare_triangle(whole, tt.rect, tri)) return;
  const ShadeConstants& k = frame.shade;
  PhongSpanInput in;
  in.material = &k.materials[whole.material];
  in.shade = &k;
  bool ready = false;
  const PixelRect rows{whole.px_min[0], tri.rect.y0, whole.px_max[0], tri.rect.y1};
  for_each_span(tri.edges, rows, [&](int py, int xl, int xr) {
    const int x0 = std::max(xl, tri.rect.x0), x1 = std::min(xr, tri.rect.x1);
    if (x0 > x1) return;
    tri.set_up_planes();
    if (!ready) {
      in.bary = tri.bary;
      in.depth = tri.depth;
      set_up_phong_planes<kLocal>(frame, entry, whole, tri.bary, in);
      on_setup(in);
      ready = true;
    }
    run(in, xl, xr, py, x0, x1, tile_row(tt, py));
  });
  if (ready) finish(in);
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#endif  // include guard toggle
