#include "shade/normal_blocks.h"

#include <algorithm>
#include <cmath>

#include "fastshade/error.h"
#include "shade/fast_math.h"

namespace fastshade {

SpanNormals parse_normals(std::string_view text, const std::string& where) {
  if (text == "normalize") return SpanNormals::Normalize;
  if (text == "adaptive") return SpanNormals::Adaptive;
  if (text == "equal-angle") return SpanNormals::EqualAngle;
  throw InputError(where, "unknown normals mode '" + std::string(text) +
                              "' (expected normalize, adaptive or equal-angle)");
}

namespace {

void unit_normal(const PhongSpanInput& in, int px, int py, float out[3]) {
  const PixelOffsets o = pixel_offsets(in.bary, px, py);
  const float x = plane_at(in.n[0], o), y = plane_at(in.n[1], o), z = plane_at(in.n[2], o);
  const float len2 = (x * x + y * y) + z * z;
  const float inv = len2 > 0.0f ? fast_math::inv_sqrt(len2) : 0.0f;
  out[0] = x * inv, out[1] = y * inv, out[2] = z * inv;
}

// How much a shading result can move per unit of normal shortening: diffuse kd, specular
// ks n (c^n with c scaled by s moves by n (1 - s) relative), over lights.
float shortening_sensitivity(const PhongSpanInput& in) {
  const MaterialConstants& m = *in.material;
  const float kd = std::max({m.kd.r, m.kd.g, m.kd.b}), ks = std::max({m.ks.r, m.ks.g, m.ks.b});
  float k = 0.0f;
  for (const LightView& light : in.shade->lights)
    k += std::max({light.color.r, light.color.g, light.color.b}) * (kd + ks * m.shininess);
  return k;
}

}  // namespace

void make_normal_block(const PhongSpanInput& in, SpanNormals mode, float tol, int xb, int py,
                       int xl, int xr, NormalBlock& out) {
  const int block = limits::kSeedBlockPx;
  const int xa = std::clamp(xb, xl, xr), xz = std::clamp(xb + block, xl, xr);
  unit_normal(in, xa, py, out.na);
  unit_normal(in, xz, py, out.nz);
  const int length = xz - xa;
  const float c = std::clamp((out.na[0] * out.nz[0] + out.na[1] * out.nz[1]) + out.na[2] * out.nz[2], -1.0f, 1.0f);
  for (int i = 0; i < NormalBlock::kSize; ++i) {  // outside the run: the nearest end
    const int k = std::clamp(xb + i - xa, 0, length);
    const float t = length > 0 ? float(k) / float(length) : 0.0f;
    out.alpha[i] = 1.0f - t;
    out.beta[i] = t;
  }
  if (length == 0) return;
  if (mode == SpanNormals::Adaptive) {
    // The lerp of unit normals is shortest, cos(psi / 2) = sqrt((1 + c) / 2), at its middle.
    const float shortening = 1.0f - std::sqrt(0.5f * (1.0f + c));
    if (shortening * shortening_sensitivity(in) <= tol) return;  // linear weights suffice
    for (int i = 0; i < NormalBlock::kSize; ++i) {
      const float a = out.alpha[i], b = out.beta[i];
      const float len2 = a * a + b * b + 2.0f * a * b * c;
      const float g = len2 > 0.0f ? fast_math::inv_sqrt(len2) : 0.0f;
      out.alpha[i] = a * g;
      out.beta[i] = b * g;
    }
    return;
  }
  if (mode == SpanNormals::EqualAngle) {
    const float psi = std::acos(c);
    const float phi = psi / float(length);
    const float sin_psi = std::sin(psi);
    if (!(sin_psi > 1e-6f)) return;  // ends (nearly) equal or antiparallel: keep the lerp
    // s_k = sin(k phi) by the stable difference form of eq. (7).
    float s[limits::kSeedBlockPx + 1] = {};
    const float half = std::sin(0.5f * phi);
    const float kappa = -4.0f * half * half;
    float sk = 0.0f, d = std::sin(phi);
    for (int k = 0; k <= length; ++k) {
      s[k] = sk;
      sk += d;
      d += kappa * (sk);
    }
    // Re-anchored on the exact sin(psi): the recurrence's end is off by its rounding only.
    const float inv = 1.0f / sin_psi;
    for (int i = 0; i < NormalBlock::kSize; ++i) {
      const int k = std::clamp(xb + i - xa, 0, length);
      out.alpha[i] = (k == 0) ? 1.0f : s[length - k] * inv;
      out.beta[i] = (k == length) ? 1.0f : s[k] * inv;
    }
  }
}

}  // namespace fastshade
