// The scalar twin of shade/phong_color-inl.h: Blinn-Phong at one pixel with the same float
// operations in the same order, and quantisation as the lanes do it.
#include <algorithm>
#include <cmath>

#include "light/brdf.h"
#include "light/fast_math.h"
#include "shade/scalar_twin.h"

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

PhongColor phong_color_from_plane_normal_scalar(const PhongSpanInput& in, float nx, float ny, float nz,
                                                const PixelOffsets& o, int split_light,
                                                float* split_n_dot_l, bool specular) {
  const float len2 = (nx * nx + ny * ny) + nz * nz;
  const float inv_len = len2 >= fast_math::kMinInvSqrtInput ? fast_math::inv_sqrt(len2) : 0.0f;
  return phong_color_from_normal_scalar(in, nx * inv_len, ny * inv_len, nz * inv_len, o, split_light, split_n_dot_l,
                                        specular);
}

PhongColor phong_color_scalar(const PhongSpanInput& in, const PixelOffsets& o, int split_light,
                              float* split_n_dot_l, bool specular) {
  return phong_color_from_plane_normal_scalar(in, plane_at(in.n[0], o), plane_at(in.n[1], o), plane_at(in.n[2], o), o,
                                              split_light, split_n_dot_l, specular);
}

}  // namespace fastshade
