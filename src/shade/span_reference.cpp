// Scalar references of the span kernels (shade/span_kernels.h).
#include <algorithm>
#include <cmath>

#include "light/brdf.h"
#include "shade/diffuse_quotient.h"
#include "light/fast_math.h"
#include "shade/method.h"
#include "classify/segment_step.h"
#include "shade/normal_blocks.h"
#include "shade/pixel_queue.h"
#include "shade/span_kernels.h"

namespace fastshade {

uint8_t quantize_like_simd(float v, bool srgb) {
  v = std::min(std::max(v, 0.0f), 1.0f);  // NaN becomes 0, as x86 max(NaN, 0)
  if (!(v == v)) v = 0.0f;
  if (srgb && !(v <= 0.0031308f))
    v = 1.055f * fast_math::exp2(fast_math::log2(std::max(v, 1e-30f)) * (1.0f / 2.4f)) - 0.055f;
  else if (srgb)
    v = v * 12.92f;
  return static_cast<uint8_t>(static_cast<int32_t>(std::floor(v * 255.0f + 0.5f)));
}

namespace {

// Depth test and write for one pixel; true if it passes.
bool depth_pass(const Plane& depth_plane, const PixelOffsets& o, float& depth) {
  const float z = plane_at(depth_plane, o);
  if (!(z < depth)) return false;
  depth = z;
  return true;
}

}  // namespace

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

namespace {

// The interpolated normal (n/w, any length) normalised as the kernels' Normalize does, then lit.
PhongColor phong_color_from_plane_normal_scalar(const PhongSpanInput& in, float nx, float ny, float nz,
                                                const PixelOffsets& o, int split_light = -1,
                                                float* split_n_dot_l = nullptr, bool specular = true) {
  const float len2 = (nx * nx + ny * ny) + nz * nz;
  const float inv_len = len2 >= fast_math::kMinInvSqrtInput ? fast_math::inv_sqrt(len2) : 0.0f;
  return phong_color_from_normal_scalar(in, nx * inv_len, ny * inv_len, nz * inv_len, o, split_light, split_n_dot_l,
                                        specular);
}

}  // namespace

PhongColor phong_color_scalar(const PhongSpanInput& in, const PixelOffsets& o, int split_light,
                              float* split_n_dot_l, bool specular) {
  return phong_color_from_plane_normal_scalar(in, plane_at(in.n[0], o), plane_at(in.n[1], o), plane_at(in.n[2], o), o,
                                              split_light, split_n_dot_l, specular);
}

void light_pixel_queue_scalar(PixelQueue& q, const TileTarget& tt) {
  PhongSpanInput in;
  in.material = q.material;
  in.shade = q.shade;
  const PixelOffsets unused{};  // only a local viewer reads the pixel's offsets
  const bool srgb = q.shade->srgb;
  for (int i = 0; i < q.count; ++i) {
    const PhongColor c = phong_color_from_plane_normal_scalar(in, q.nx[i], q.ny[i], q.nz[i], unused);
    tt.color[q.at[i]] = pack_rgba(quantize_like_simd(c.c[0], srgb), quantize_like_simd(c.c[1], srgb),
                                  quantize_like_simd(c.c[2], srgb)) ^
                        q.alpha_xor;
  }
  q.count = 0;
}

PhongColor phong_color_from_normal_scalar(const PhongSpanInput& in, float nx, float ny, float nz,
                                          const PixelOffsets& o, int split_light, float* split_n_dot_l,
                                          bool specular) {
  const MaterialConstants& m = *in.material;
  const ShadeConstants& k = *in.shade;
  float vx = 0, vy = 0, vz = 0;  // toward the eye (local viewer)
  if (k.local_viewer) {
    const float w = 1.0f / plane_at(in.inv_w, o);
    vx = -(plane_at(in.p[0], o) * w), vy = -(plane_at(in.p[1], o) * w), vz = -(plane_at(in.p[2], o) * w);
    const float v2 = (vx * vx + vy * vy) + vz * vz;
    const float inv = v2 >= fast_math::kMinInvSqrtInput ? fast_math::inv_sqrt(v2) : 0.0f;
    vx *= inv, vy *= inv, vz *= inv;
  }
  PhongColor rgb{{k.ambient.r, k.ambient.g, k.ambient.b}};
  for (int index = 0; index < int(k.lights.size()); ++index) {
    const LightView& light = k.lights[index];
    float hx = light.h_view.x, hy = light.h_view.y, hz = light.h_view.z;
    if (k.local_viewer) {
      hx = light.l_view.x + vx, hy = light.l_view.y + vy, hz = light.l_view.z + vz;
      const float h2 = (hx * hx + hy * hy) + hz * hz;
      const float inv = h2 >= fast_math::kMinInvSqrtInput ? fast_math::inv_sqrt(h2) : 0.0f;
      hx *= inv, hy *= inv, hz *= inv;
    }
    const float ndl = (nx * light.l_view.x + ny * light.l_view.y) + nz * light.l_view.z;
    const float ndh = (nx * hx + ny * hy) + nz * hz;
    float diffuse = std::max(ndl, 0.0f);
    if (index == split_light) {
      *split_n_dot_l = ndl;
      diffuse = 0.0f;
    }
    const float spec = specular ? eval_brdf_one(m.lobe, ndh) : 0.0f;
    for (int c = 0; c < 3; ++c)
      rgb.c[c] = rgb.c[c] + light.color[c] * (m.kd[c] * diffuse + m.ks[c] * spec);
  }
  return rgb;
}

namespace {

// Depth test, colour(offsets) and quantisation of every pixel of a row span.
template <typename ColorFn>
void lit_span_scalar(const PhongSpanInput& in, int py, int x0, int x1, RowTarget row, ColorFn&& color) {
  const bool srgb = in.shade->srgb;
  for (int px = x0; px <= x1; ++px) {
    const PixelOffsets o = pixel_offsets(in.bary, px, py);
    if (!depth_pass(in.depth, o, row.depth[px])) continue;
    const PhongColor rgb = color(o);
    row.color[px] = pack_rgba(quantize_like_simd(rgb.c[0], srgb), quantize_like_simd(rgb.c[1], srgb),
                              quantize_like_simd(rgb.c[2], srgb));
  }
}

}  // namespace

void phong_span_scalar(const PhongSpanInput& in, int py, int x0, int x1, RowTarget row) {
  lit_span_scalar(in, py, x0, x1, row, [&](const PixelOffsets& o) { return phong_color_scalar(in, o); });
}

void diffuse_quotient_span_scalar(const PhongSpanInput& in, const DiffuseQuotient& dq, int py, int x0,
                                  int x1, RowTarget row) {
  lit_span_scalar(in, py, x0, x1, row,
                  [&](const PixelOffsets& o) { return diffuse_quotient_color_scalar(in, dq, o); });
}

void hybrid_span_scalar(const PhongSpanInput& in, const HybridRun& run, int py, int x0, int x1,
                        RowTarget row) {
  const bool srgb = in.shade->srgb;
  const int step = run.step;
  for (int px = x0; px <= x1; ++px) {
    const PixelOffsets o = pixel_offsets(in.bary, px, py);
    if (!depth_pass(in.depth, o, row.depth[px])) continue;
    PhongColor rgb;
    if (step == 1) {
      rgb = phong_color_scalar(in, o);
    } else {
      const int ea = run.xl + ((px - run.xl) & ~(step - 1)), eb = std::min(ea + step, run.xr);
      float da = 0.0f, db = 0.0f;  // the split light's N.L at the ends
      const PhongColor ca = phong_color_scalar(in, pixel_offsets(in.bary, ea, py), run.split_light, &da, run.specular);
      const PhongColor cb = phong_color_scalar(in, pixel_offsets(in.bary, eb, py), run.split_light, &db, run.specular);
      // The slope per pixel, then the offset from ea: the SIMD kernel's operations in order.
      const float len = static_cast<float>(eb - ea), dx = static_cast<float>(px - ea);
      auto along = [&](float a, float b) { return a + dx * (eb > ea ? (b - a) / len : 0.0f); };
      for (int ch = 0; ch < 3; ++ch) rgb.c[ch] = along(ca.c[ch], cb.c[ch]);
      if (run.split_light >= 0) {
        const float n_dot_l = std::max(along(da, db), 0.0f);
        const LightView& light = in.shade->lights[run.split_light];
        for (int ch = 0; ch < 3; ++ch) rgb.c[ch] = rgb.c[ch] + (light.color[ch] * in.material->kd[ch]) * n_dot_l;
      }
    }
    row.color[px] = pack_rgba(quantize_like_simd(rgb.c[0], srgb), quantize_like_simd(rgb.c[1], srgb),
                              quantize_like_simd(rgb.c[2], srgb));
  }
}

void normals_span_scalar(const PhongSpanInput& in, SpanNormals mode, float tol, const HybridRun& run,
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
      row.color[px] = pack_rgba(quantize_like_simd(rgb.c[0], srgb), quantize_like_simd(rgb.c[1], srgb),
                                quantize_like_simd(rgb.c[2], srgb));
    }
  }
}

}  // namespace fastshade
