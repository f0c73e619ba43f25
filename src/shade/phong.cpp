// `phong`: per pixel, the perspective-correct normal (its n/w planes need no division: the
// 1/w factor vanishes when normalising), normalised, Blinn-Phong in float with the frame's
// specular approximation (--brdf; exact: exp2/log2 to float precision).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shade/phong.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "shade/methods.h"
#include "shade/phong-inl.h"

HWY_BEFORE_NAMESPACE();
namespace fastshade {
namespace HWY_NAMESPACE {

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
    set_up_phong_planes<kLocal>(frame, entry, t, tri.bary, in);
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
