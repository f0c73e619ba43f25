// `gouraud`: Blinn-Phong at the vertices (front/vertex_stage.cpp), the colour interpolated
// perspective-correctly per pixel: (c/w) / (1/w) from four planes.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shade/gouraud.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "shade/lighting.h"
#include "shade/methods.h"
#include "shade/span_loop-inl.h"

HWY_BEFORE_NAMESPACE();
namespace fastshade {
namespace HWY_NAMESPACE {

template <bool kSrgb>
HWY_INLINE void DrawGouraud(const Frame& frame, uint32_t entry, const TileTarget& tt) {
  TriangleInTile tri;
  if (!prepare_triangle(frame.triangle(entry), tt.rect, tri)) return;
  const SetupTriangle& t = *tri.tri;
  const ShadeConstants& k = frame.shade;
  double vertex_color[3][3];  // colour / w
  // Planes are set up on the first vector that passes the depth test (see phong.cpp).
  Plane c_over_w[3], inv_w;
  bool planes_ready = false;
  auto set_up_planes = [&] {
    for (int i = 0; i < 3; ++i) {
      glm::vec3 color = frame.vertex(entry, t.attr[i], &AttrArrays::color);
      if (k.two_sided && (t.flags & kBackFacing)) {  // the vertex stage lit the front side only
        const glm::vec3 v_view =
            k.local_viewer ? glm::normalize(-frame.vertex(entry, t.attr[i], &AttrArrays::pos_view))
                           : glm::vec3(0, 0, 1);
        const glm::vec3 n_view = frame.vertex(entry, t.attr[i], &AttrArrays::n_view);
        color = glm::clamp(
            blinn_phong<float>(-n_view, v_view, !k.local_viewer, k.materials[t.material], k), 0.0f,
            1.0f);
      }
      for (int c = 0; c < 3; ++c) vertex_color[i][c] = double(color[c]) * t.inv_w[i];
    }
    for (int c = 0; c < 3; ++c)
      c_over_w[c] = make_plane(tri.bary, vertex_color[0][c], vertex_color[1][c], vertex_color[2][c]);
    inv_w = make_plane(tri.bary, t.inv_w[0], t.inv_w[1], t.inv_w[2]);
    planes_ready = true;
  };

  ShadeTriangle(tri, tt, [&](auto d, const auto& o) {
    if (!planes_ready) set_up_planes();
    const auto w = hn::Div(hn::Set(d, 1.0f), EvalPlane(d, inv_w, o));
    auto channel = [&](int c) { return hn::Mul(EvalPlane(d, c_over_w[c], o), w); };
    return PackRGBA<kSrgb>(d, channel(0), channel(1), channel(2));
  });
}

void DrawGouraudLinear(const Frame& f, uint32_t e, const TileTarget& t) { DrawGouraud<false>(f, e, t); }
void DrawGouraudSrgb(const Frame& f, uint32_t e, const TileTarget& t) { DrawGouraud<true>(f, e, t); }

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace fastshade {

HWY_EXPORT(DrawGouraudLinear);
HWY_EXPORT(DrawGouraudSrgb);

AttrNeeds gouraud_needs(const ShadeConstants& shade) {
  // Two-sided lighting relights back faces from their normals at setup.
  return {.normal = shade.two_sided, .color = true, .position = shade.two_sided && shade.local_viewer};
}

DrawTriangleFn select_gouraud(const ShadeConstants& shade) {
  return shade.srgb ? &HWY_DYNAMIC_DISPATCH(DrawGouraudSrgb) : &HWY_DYNAMIC_DISPATCH(DrawGouraudLinear);
}

}  // namespace fastshade
#endif
