// `gouraud`: Blinn-Phong at the vertices (front/vertex_stage.cpp), the colour interpolated
// perspective-correctly per pixel: (255 c/w) / (1/w) from four planes stepped by constant
// increments inside each 16-pixel block (the paper's eq. 1-2, raster/planes.h), which is the
// output level before rounding.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shade/gouraud.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep


#include <hwy/highway.h>

#include "core/dispatch.h"
#include "light/lighting.h"
#include "shade/methods.h"
#include "shade/planes_over_w-inl.h"
#include "shade/scalar_twin.h"
#include "shade/span_loop-inl.h"

HWY_BEFORE_NAMESPACE();
namespace fastshade {
namespace HWY_NAMESPACE {

// The level of channel c before rounding, clamped to the vertex levels' range (span_kernels.h
// says why), then rounded; sRGB takes the curve on the colour in [0, 1].
template <bool kSrgb, class D, class V = hn::Vec<D>>
HWY_INLINE V GouraudLevel(D d, const GouraudSpanInput& in, int c, V w, const LaneOffsets<D>& o) {
  V level = hn::Mul(EvalPlaneUnclamped(d, in.level_over_w[c], o), w);
  level = hn::Min(hn::Max(level, hn::Set(d, in.level_lo[c])), hn::Set(d, in.level_hi[c]));
  if constexpr (kSrgb) return QuantizeLevel<true>(d, hn::Mul(level, hn::Set(d, 1.0f / 255.0f)));
  return hn::Floor(hn::Add(level, hn::Set(d, 0.5f)));
}

template <bool kSrgb, class D>
HWY_INLINE auto GouraudShade(D d, const GouraudSpanInput& in, const LaneOffsets<D>& o) {
  const auto w = hn::Div(hn::Set(d, 1.0f), EvalPlane(d, in.inv_w, o));
  return PackLevels(d, GouraudLevel<kSrgb>(d, in, 0, w, o), GouraudLevel<kSrgb>(d, in, 1, w, o),
                    GouraudLevel<kSrgb>(d, in, 2, w, o));
}

// kSpecular = false: `auto`'s diffuse-only Gouraud (the vertex stage lit the vertices
// without the specular term too).
template <bool kSrgb, bool kSpecular>
void DrawGouraud(const Frame& frame, uint32_t entry, const TileTarget& tt) {
  TriangleInTile tri;
  if (!place_in_tile(frame.triangle(entry), tt.rect, tri)) return;
  const SetupTriangle& t = *tri.tri;
  const ShadeConstants& k = frame.shade;
  // Colour planes are set up on the first vector that passes the depth test (see phong.cpp).
  GouraudSpanInput in;
  bool ready = false;
  auto set_up = [&] {
    glm::vec3 color[3];
    for (int i = 0; i < 3; ++i) {
      color[i] = frame.vertex(entry, t.attr[i], &AttrArrays::color);
      if (k.two_sided && (t.flags & kBackFacing)) {  // the vertex stage lit the front side only
        const glm::vec3 v_view =
            k.local_viewer ? glm::normalize(-frame.vertex(entry, t.attr[i], &AttrArrays::pos_view))
                           : glm::vec3(0, 0, 1);
        const glm::vec3 n_view = frame.vertex(entry, t.attr[i], &AttrArrays::n_view);
        color[i] = vertex_color<kSpecular>(-n_view, v_view, !k.local_viewer, k.materials[t.material], k);
      }
    }
    PlanesOverW(tri.bary, color, 255.0, t.inv_w, in.level_over_w, in.inv_w);  // set_gouraud_colors' planes
    set_gouraud_levels(in, color);
    ready = true;
  };
  ShadeTriangle(tri, tt, [&](auto d, const auto& o) {
    if (!ready) set_up();
    return GouraudShade<kSrgb>(d, in, o);
  });
}

DrawTriangleFn SelectGouraud(bool srgb, bool specular) {
  if (specular) return srgb ? &DrawGouraud<true, true> : &DrawGouraud<false, true>;
  return srgb ? &DrawGouraud<true, false> : &DrawGouraud<false, false>;
}

void GouraudSpan(const GouraudSpanInput& in, bool srgb, int py, int x0, int x1, RowTarget row) {
  if (srgb)
    ShadeSpan(in.bary, in.depth, py, x0, x1, row, [&](auto d, const auto& o) { return GouraudShade<true>(d, in, o); });
  else
    ShadeSpan(in.bary, in.depth, py, x0, x1, row, [&](auto d, const auto& o) { return GouraudShade<false>(d, in, o); });
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace fastshade {

HWY_EXPORT(SelectGouraud);
HWY_EXPORT(GouraudSpan);

AttrNeeds gouraud_needs(const ShadeConstants& shade) {
  // Two-sided lighting relights back faces from their normals at setup.
  return {.normal = shade.two_sided, .color = true, .position = shade.two_sided && shade.local_viewer};
}

DrawTriangleFn select_gouraud(SimdTarget simd, const ShadeConstants& shade) {
  return FASTSHADE_DISPATCH(simd, SelectGouraud)(shade.srgb, true);
}

DrawTriangleFn select_gouraud_diffuse(SimdTarget simd, const ShadeConstants& shade) {
  return FASTSHADE_DISPATCH(simd, SelectGouraud)(shade.srgb, false);
}

void gouraud_span(SimdTarget simd, const GouraudSpanInput& in, bool srgb, int py, int x0, int x1, RowTarget row) {
  FASTSHADE_DISPATCH(simd, GouraudSpan)(in, srgb, py, x0, x1, row);
}


// The scalar twin of GouraudSpan.
void gouraud_span_scalar(const GouraudSpanInput& in, bool srgb, int py, int x0, int x1,
                         RowTarget row) {
  for (int px = x0; px <= x1; ++px) {
    const PixelOffsets o = pixel_offsets(in.bary, px, py);
    if (!depth_pass(in.depth, o, row.depth[px])) continue;
    const float w = 1.0f / plane_at(in.inv_w, o);
    uint8_t c[3];
    for (int i = 0; i < 3; ++i) {
      float level = plane_at_unclamped(in.level_over_w[i], o) * w;
      level = level > in.level_lo[i] ? level : in.level_lo[i];  // x86 max and min: NaN takes the bound
      level = level < in.level_hi[i] ? level : in.level_hi[i];
      c[i] = srgb ? quantize_like_simd(level * (1.0f / 255.0f), true)
                  : static_cast<uint8_t>(static_cast<int32_t>(std::floor(level + 0.5f)));
    }
    row.color[px] = pack_rgba(c[0], c[1], c[2]);
  }
}

}  // namespace fastshade
#endif
