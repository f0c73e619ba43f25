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
  glm::vec3 color[3];
  for (int i = 0; i < 3; ++i) {
    const VertexAttrs& v = frame.vertex(entry, t.attr[i]);
    color[i] = v.color;
    if (k.two_sided && (t.flags & kBackFacing)) {  // the vertex stage lit the front side only
      const glm::vec3 v_view = k.local_viewer ? glm::normalize(-v.pos_view) : glm::vec3(0, 0, 1);
      color[i] = glm::clamp(
          blinn_phong<float>(-v.n_view, v_view, !k.local_viewer, k.materials[t.material], k), 0.0f,
          1.0f);
    }
  }
  Plane c_over_w[3];
  for (int c = 0; c < 3; ++c)
    c_over_w[c] = make_plane(tri.bary, double(color[0][c]) * t.inv_w[0],
                             double(color[1][c]) * t.inv_w[1], double(color[2][c]) * t.inv_w[2]);
  const Plane inv_w = make_plane(tri.bary, t.inv_w[0], t.inv_w[1], t.inv_w[2]);

  const DF d;
  for_each_span(tri.edges, tri.rect, [&](int py, int x0, int x1) {
    float row[3];
    for (int c = 0; c < 3; ++c) row[c] = row_value(c_over_w[c], tri.bary, py);
    const float w_row = row_value(inv_w, tri.bary, py);
    ShadeSpan(tri, py, x0, x1, tt, [&](VF dx, MF) {
      const VF w = hn::Div(hn::Set(d, 1.0f), EvalPlane(d, inv_w, w_row, dx));
      return PackRGBA<kSrgb>(d, hn::Mul(EvalPlane(d, c_over_w[0], row[0], dx), w),
                             hn::Mul(EvalPlane(d, c_over_w[1], row[1], dx), w),
                             hn::Mul(EvalPlane(d, c_over_w[2], row[2], dx), w));
    });
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
