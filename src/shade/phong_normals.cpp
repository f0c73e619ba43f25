// `phong --normals adaptive|equal-angle`: normals from per-block weights of the block's two
// end normals (shade/normal_blocks.h), Blinn-Phong per pixel as `phong`.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shade/phong_normals.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <algorithm>

#include <hwy/highway.h>

#include "core/dispatch.h"
#include "light/brdf_variants.h"
#include "shade/methods.h"
#include "shade/normal_blocks.h"
#include "shade/phong-inl.h"
#include "shade/scalar_twin.h"
#include "shade/shade_limits.h"

HWY_BEFORE_NAMESPACE();
namespace fastshade {
namespace HWY_NAMESPACE {

template <bool kLocal, LobeKernel kLobe, bool kSpecular = true>
void NormalsSpanImpl(const PhongSpanInput& in, PhongNormals mode, float tol, const HybridRun& run,
                     int py, int x0, int x1, RowTarget row) {
  const hn::ScalableTag<float> d;
  constexpr int kBlock = limits::kSeedBlockPx;
  NormalBlock nb;
  for (int xb = x0 & ~(kBlock - 1); xb <= x1; xb += kBlock) {
    make_normal_block(in, mode, tol, xb, py, run.xl, run.xr, nb);
    const int lo = std::max(xb, x0), hi = std::min(xb + kBlock - 1, x1);
    ShadeSpanAt(d, in.bary, in.depth, py, lo, hi, row, [&](auto, const auto& o, int x) {
      const auto alpha = hn::LoadU(d, nb.alpha + (x - xb)), beta = hn::LoadU(d, nb.beta + (x - xb));
      auto mix = [&](int c) {
        return hn::Add(hn::Mul(alpha, hn::Set(d, nb.na[c])), hn::Mul(beta, hn::Set(d, nb.nz[c])));
      };
      const auto c = PhongColorFromNormal<kLocal, kLobe, kSpecular>(d, in, mix(0), mix(1), mix(2), o);
      return PackRGBA(d, c.r, c.g, c.b, in.shade->srgb);
    });
  }
}

// kSpecular = false: `auto`'s per-pixel diffuse path under --normals adaptive|equal-angle.
template <bool kLocal, LobeKernel kLobe, bool kSpecular = true>
void DrawPhongNormals(const Frame& frame, uint32_t entry, const TileTarget& tt) {
  const ShadeConstants& k = frame.shade;
  DrawByRowRuns<kLocal, kLobe, kSpecular>(
      frame, entry, tt, limits::kBlockNormalsMinWidthPx, [](const PhongSpanInput&) {},
      [&](const PhongSpanInput& in, int xl, int xr, int py, int x0, int x1, RowTarget row) {
        NormalsSpanImpl<kLocal, kLobe, kSpecular>(in, k.normals, k.hybrid_tolerance, {1, xl, xr}, py, x0,
                                              x1, row);
      });
}

using NormalsSpanFn = void (*)(const PhongSpanInput&, PhongNormals, float, const HybridRun&, int, int,
                               int, RowTarget);
FASTSHADE_DEFINE_VARIANT_PICKER(SelectPhongNormals, DrawPhongNormals, DrawTriangleFn)
FASTSHADE_DEFINE_VARIANT_PICKER(PickNormalsSpan, NormalsSpanImpl, NormalsSpanFn)

DrawTriangleFn SelectPhongNormalsDiffuse() { return &DrawPhongNormals<false, LobeKernel::Exact, false>; }

void NormalsSpan(const PhongSpanInput& in, PhongNormals mode, float tol, const HybridRun& run, int py,
                 int x0, int x1, RowTarget row) {
  PickNormalsSpan(in.shade->local_viewer, in.material->lobe.kind)(in, mode, tol, run, py,
                                                                                  x0, x1, row);
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace fastshade {

HWY_EXPORT(SelectPhongNormals);
HWY_EXPORT(NormalsSpan);
HWY_EXPORT(SelectPhongNormalsDiffuse);

DrawTriangleFn select_phong_normals(SimdTarget simd, const ShadeConstants& shade) {
  return FASTSHADE_DISPATCH(simd, SelectPhongNormals)(shade.local_viewer, shade.brdf.kind);
}

DrawTriangleFn select_phong_normals_diffuse(SimdTarget simd, const ShadeConstants&) {  // as select_phong_diffuse
  return FASTSHADE_DISPATCH(simd, SelectPhongNormalsDiffuse)();
}

void normals_span(SimdTarget simd, const PhongSpanInput& in, PhongNormals mode, float tol, const HybridRun& run, int py,
                  int x0, int x1, RowTarget row) {
  FASTSHADE_DISPATCH(simd, NormalsSpan)(in, mode, tol, run, py, x0, x1, row);
}


// The scalar twin of NormalsSpan.
void normals_span_scalar(const PhongSpanInput& in, PhongNormals mode, float tol, const HybridRun& run,
                         int py, int x0, int x1, RowTarget row) {
  const bool srgb = in.shade->srgb;
  const int block = limits::kSeedBlockPx;
  NormalBlock nb;
  for (int xb = x0 & ~(block - 1); xb <= x1; xb += block) {
    make_normal_block(in, mode, tol, xb, py, run.xl, run.xr, nb);
    for (int px = std::max(xb, x0); px <= std::min(xb + block - 1, x1); ++px) {
      const PixelOffsets o = pixel_offsets(in.bary, px, py);
      if (!depth_pass(in.depth, o, row.depth[px])) continue;
      const float a = nb.alpha[px - xb], b = nb.beta[px - xb];
      const PhongColor rgb = phong_color_from_normal_scalar(
          in, a * nb.na[0] + b * nb.nz[0], a * nb.na[1] + b * nb.nz[1], a * nb.na[2] + b * nb.nz[2], o);
      row.color[px] = pack_quantized(rgb, srgb);
    }
  }
}

}  // namespace fastshade
#endif
