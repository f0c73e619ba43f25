// `phong`: per pixel, the perspective-correct normal (its n/w planes need no division: the
// 1/w factor vanishes when normalising), normalised, Blinn-Phong in float with the frame's
// specular approximation (--brdf; exact: exp2/log2 to float precision).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shade/phong.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "core/dispatch.h"
#include "light/brdf_variants.h"
#include "shade/diffuse_quotient.h"
#include "shade/methods.h"
#include "shade/phong-inl.h"
#include "shade/pixel_queue.h"
#include "shade/scalar_twin.h"

HWY_BEFORE_NAMESPACE();
namespace fastshade {
namespace HWY_NAMESPACE {

template <bool kLocal, LobeKernel kLobe>
void PhongSpanVariant(const PhongSpanInput& in, int py, int x0, int x1, RowTarget row) {
  ShadeSpan(in.bary, in.depth, py, x0, x1, row,
            [&](auto d, const auto& o) { return PhongShade<kLocal, kLobe>(d, in, o); });
}

// The `phong` method's draw: with a viewer at infinity, small triangles' pixels wait in the
// tile's queue to be lit a full vector at a time (shade/pixel_queue.h).
template <bool kLocal, LobeKernel kLobe>
void DrawPhongMethod(const Frame& frame, uint32_t entry, const TileTarget& tt) {
  DrawPhong<kLocal, kLobe, true, !kLocal>(frame, entry, tt);
}

using PhongSpanFn = void (*)(const PhongSpanInput&, int, int, int, RowTarget);
FASTSHADE_DEFINE_VARIANT_PICKER(SelectPhong, DrawPhongMethod, DrawTriangleFn)
FASTSHADE_DEFINE_VARIANT_PICKER(PickPhongSpan, PhongSpanVariant, PhongSpanFn)

// Diffuse only: no half vector, so neither the viewer nor the lobe matters.
DrawTriangleFn SelectPhongDiffuse() { return &DrawPhong<false, LobeKernel::Exact, false>; }

void PhongSpan(const PhongSpanInput& in, int py, int x0, int x1, RowTarget row) {
  PickPhongSpan(in.shade->local_viewer, in.material->lobe.kind)(in, py, x0, x1, row);
}

void DiffuseQuotientSpan(const PhongSpanInput& in, const DiffuseQuotient& dq, int py, int x0, int x1,
                         RowTarget row) {
  ShadeSpan(in.bary, in.depth, py, x0, x1, row,
            [&](auto d, const auto& o) { return DiffuseQuotientShade(d, in, dq, o); });
}

void LightPixelQueue(PixelQueue& queue, const TileTarget& target, bool all) {
  if (lobe_kernel(queue.material->lobe.kind) == LobeKernel::Exact) LightQueue<LobeKernel::Exact>(queue, target, all);
  else LightQueue<LobeKernel::ByKind>(queue, target, all);
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace fastshade {

HWY_EXPORT(SelectPhong);
HWY_EXPORT(PhongSpan);
HWY_EXPORT(SelectPhongDiffuse);
HWY_EXPORT(LightPixelQueue);
HWY_EXPORT(DiffuseQuotientSpan);

AttrNeeds phong_needs(const ShadeConstants& shade) {
  return {.normal = true, .color = false, .position = shade.local_viewer};
}

DrawTriangleFn select_phong(SimdTarget simd, const ShadeConstants& shade) {
  if (shade.normals != PhongNormals::Normalize) return select_phong_normals(simd, shade);
  return FASTSHADE_DISPATCH(simd, SelectPhong)(shade.local_viewer, shade.brdf.kind);
}

DrawTriangleFn select_phong_diffuse(SimdTarget simd, const ShadeConstants&) {  // the output curve is read per frame
  return FASTSHADE_DISPATCH(simd, SelectPhongDiffuse)();
}

void phong_span(SimdTarget simd, const PhongSpanInput& in, int py, int x0, int x1, RowTarget row) {
  FASTSHADE_DISPATCH(simd, PhongSpan)(in, py, x0, x1, row);
}

void diffuse_quotient_span(SimdTarget simd, const PhongSpanInput& in, const DiffuseQuotient& dq, int py, int x0, int x1,
                           RowTarget row) {
  FASTSHADE_DISPATCH(simd, DiffuseQuotientSpan)(in, dq, py, x0, x1, row);
}

void light_pixel_queue(SimdTarget simd, PixelQueue& queue, const TileTarget& target, bool all) {
  FASTSHADE_DISPATCH(simd, LightPixelQueue)(queue, target, all);
}


// The scalar twins of PhongSpan, DiffuseQuotientSpan and LightPixelQueue.
void phong_span_scalar(const PhongSpanInput& in, int py, int x0, int x1, RowTarget row) {
  lit_span_scalar(in, py, x0, x1, row, [&](const PixelOffsets& o) { return phong_color_scalar(in, o); });
}

void diffuse_quotient_span_scalar(const PhongSpanInput& in, const DiffuseQuotient& dq, int py, int x0,
                                  int x1, RowTarget row) {
  lit_span_scalar(in, py, x0, x1, row,
                  [&](const PixelOffsets& o) { return diffuse_quotient_color_scalar(in, dq, o); });
}

void light_pixel_queue_scalar(PixelQueue& q, const TileTarget& tt) {
  PhongSpanInput in;
  in.material = q.material;
  in.shade = q.shade;
  const PixelOffsets unused{};  // only a local viewer reads the pixel's offsets
  const bool srgb = q.shade->srgb;
  for (int i = 0; i < q.count; ++i) {
    const PhongColor c = phong_color_from_plane_normal_scalar(in, q.nx[i], q.ny[i], q.nz[i], unused);
    tt.color[q.at[i]] = pack_quantized(c, srgb) ^ q.alpha_xor;
  }
  q.count = 0;
}

}  // namespace fastshade
#endif
