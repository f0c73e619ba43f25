// Phong's per-triangle drawing as SIMD (per-target, Highway "-inl.h"), shared by the phong and
// hybrid kernels.
#if defined(FASTSHADE_SHADE_PHONG_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FASTSHADE_SHADE_PHONG_INL_H_
#undef FASTSHADE_SHADE_PHONG_INL_H_
#else
#define FASTSHADE_SHADE_PHONG_INL_H_
#endif

#include <algorithm>

#include <hwy/highway.h>

#include "shade/diffuse_quotient-inl.h"
#include "shade/method.h"
#include "shade/methods.h"
#include "shade/phong_color-inl.h"
#include "shade/pixel_queue-inl.h"
#include "shade/planes_over_w-inl.h"
#include "shade/span_loop-inl.h"

HWY_BEFORE_NAMESPACE();
namespace fastshade {
namespace HWY_NAMESPACE {

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
  auto planes_over_w = [&](AttrField field, float scale, Plane* planes, Plane& one_over_w) {
    glm::vec3 v[3];
    for (int i = 0; i < 3; ++i) v[i] = frame.vertex(entry, t.attr[i], field);
    PlanesOverW(bary, v, scale, t.inv_w, planes, one_over_w);
  };
  Plane one_over_w;  // the same plane as the positions' below: only a local viewer reads it
  planes_over_w(&AttrArrays::n_view, flip, in.n, one_over_w);
  if constexpr (kLocal) planes_over_w(&AttrArrays::pos_view, 1.0f, in.p, in.inv_w);
}

template <bool kLocal, LobeKernel kLobe, bool kSpecular = true, class D>
HWY_INLINE auto PhongShade(D d, const PhongSpanInput& in, const LaneOffsets<D>& o) {
  const ColorVecs<D> c = PhongColor<kLocal, kLobe, kSpecular>(d, in, o);
  return PackRGBA(d, c.r, c.g, c.b, in.shade->srgb);
}

// The diffuse quotient of a binned triangle (shade/diffuse_quotient.h), from its planes in `in`;
// false where the triangle keeps the normalised planes.
HWY_INLINE bool set_up_quotient(const Frame& frame, uint32_t entry, const SetupTriangle& t,
                                const Barycentrics& bary, const PhongSpanInput& in, DiffuseQuotient& dq) {
  const float flip = (frame.shade.two_sided && (t.flags & kBackFacing)) ? -1.0f : 1.0f;
  glm::vec3 n_over_w[3];
  for (int i = 0; i < 3; ++i) n_over_w[i] = (flip * t.inv_w[i]) * frame.vertex(entry, t.attr[i], &AttrArrays::n_view);
  const PixelRect box{t.px_min[0], t.px_min[1], t.px_max[0], t.px_max[1]};
  return set_up_diffuse_quotient(in, bary, box, n_over_w, dq);
}

// A material float cannot shade within 1 LSB (docs/STABILITY.md, "Fallbacks") is drawn by the
// reference; the flag is only ever set for exact cos^n, and only its highlight needs it.
HWY_INLINE bool ShadesInDouble(const Frame& frame, uint32_t entry) {
  return frame.shade.materials[frame.triangle(entry).material].shade_in_double;
}

// `phong` for one binned triangle in a tile; kSpecular = false: `auto`'s per-pixel diffuse.
// kQueued (a viewer at infinity): the lanes of small triangles wait in the tile's pixel queue
// and are lit a full vector at a time (shade/pixel_queue.h); row spans light at once, after
// whatever waits, so colours still land in draw order.
template <bool kLocal, LobeKernel kLobe, bool kSpecular = true, bool kQueued = false>
void DrawPhong(const Frame& frame, uint32_t entry, const TileTarget& tt) {
  static_assert(!(kQueued && (kLocal || !kSpecular)), "the queue holds normals lit by a viewer at infinity");
  if constexpr (kQueued) {
    if (!tt.pending) return DrawPhong<kLocal, kLobe>(frame, entry, tt);
  }
  if (kSpecular && ShadesInDouble(frame, entry)) {
    if constexpr (kQueued) light_pending(*tt.pending, tt);
    return draw_reference(frame, entry, tt);
  }
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
  DiffuseQuotient dq;  // diffuse only: written at set-up, read only where `quotient` holds
  bool quotient = false;
  auto set_up = [&] {
    set_up_phong_planes<kLocal>(frame, entry, t, tri.bary, in);
    if constexpr (!kSpecular) quotient = set_up_quotient(frame, entry, t, tri.bary, in, dq);
    ready = true;
  };
  // Inlined into the span loop, where the planes' constants stay in registers: called per
  // vector, it reloaded them all (about 25 broadcasts a vector, perf annotate; cd62cd8).
  auto shade = [&](auto d, const auto& o) __attribute__((always_inline)) {
    if (!ready) set_up();
    if constexpr (kQueued) {
      if (tt.pending->count > 0) LightQueue<kLobe>(*tt.pending, tt, true);
    }
    if constexpr (!kSpecular) {
      // Decided once per triangle, at set-up; set-up waits for the first vector that passes
      // the depth test, so the choice is a branch here that goes the same way every vector.
      if (quotient) return DiffuseQuotientShade(d, in, dq, o);
    }
    return PhongShade<kLocal, kLobe, kSpecular>(d, in, o);
  };
  if constexpr (kQueued) {
    auto defer = [&](auto d, auto pass, auto z, const auto& o, const int32_t* lane_at) {
      if (!ready) set_up();
      EnqueuePassed<kLobe>(d, pass, z, EvalPlane(d, in.n[0], o), EvalPlane(d, in.n[1], o),
                                  EvalPlane(d, in.n[2], o), lane_at, in, tt);
    };
    ShadeTriangle(tri, tt, Deferring<decltype(shade), decltype(defer)>{shade, defer});
  } else {
    ShadeTriangle(tri, tt, shade);
  }
}

// The frame of the span-run methods (hybrid, --normals): triangles narrower than min_width_px
// (whole box: every tile decides alike) take per-pixel Phong, their lanes queued with a viewer
// at infinity, and materials shaded in double the reference (through DrawPhong); the others
// walk rows through the
// whole triangle, tile rows only, because a row's covered run [xl, xr] fixes where segment or
// block ends go, whatever tile this is. on_setup(in) runs once, when the first run is found
// (planes are ready then); run(in, xl, xr, py, x0, x1, row) shades the tile's part [x0, x1];
// finish(in) runs after the last run, while `in` still lives (for kernels that batch rows).
struct NoFinish {
  void operator()(const PhongSpanInput&) const {}
};
template <bool kLocal, LobeKernel kLobe, bool kSpecular = true, typename OnSetup, typename Run,
          typename Finish = NoFinish>
HWY_INLINE void DrawByRowRuns(const Frame& frame, uint32_t entry, const TileTarget& tt,
                              int min_width_px, OnSetup&& on_setup, Run&& run, Finish&& finish = {}) {
  const SetupTriangle& whole = frame.triangle(entry);
  if (whole.px_max[0] - whole.px_min[0] + 1 < min_width_px || (kSpecular && ShadesInDouble(frame, entry))) {
    DrawPhong<kLocal, kLobe, kSpecular, kSpecular && !kLocal>(frame, entry, tt);
    return;
  }
  // The narrow triangles' lanes may wait in the tile's queue: they land before this one stores.
  if (tt.pending) light_pending(*tt.pending, tt);
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
