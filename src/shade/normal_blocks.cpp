#include "shade/normal_blocks.h"

#include <algorithm>
#include <cmath>

#include "light/fast_math.h"

namespace fastshade {

namespace {

// The unit normal at a pixel; returns |n/w| there (0 for a vector too short to normalise).
float unit_normal(const PhongSpanInput& in, int px, int py, float out[3]) {
  const PixelOffsets o = pixel_offsets(in.bary, px, py);
  const float x = plane_at(in.n[0], o), y = plane_at(in.n[1], o), z = plane_at(in.n[2], o);
  const float len2 = (x * x + y * y) + z * z;
  const float inv = len2 >= fast_math::kMinInvSqrtInput ? fast_math::inv_sqrt(len2) : 0.0f;
  out[0] = x * inv, out[1] = y * inv, out[2] = z * inv;
  return len2 * inv;
}

// How much the colour can move per unit of normal shortening (diffuse kd, specular ks n: c^n
// with c scaled by s moves by n (1 - s) relative) and per radian the normal turns (kd, and
// ks sqrt(n), above the lobe's steepest slope sqrt(n) ((n-1)/n)^((n-1)/2)), over lights.
struct Sensitivity {
  float shortening = 0, turning = 0;
};
Sensitivity sensitivity(const PhongSpanInput& in) {
  const MaterialConstants& m = *in.material;
  const float kd = std::max({m.kd.r, m.kd.g, m.kd.b}), ks = std::max({m.ks.r, m.ks.g, m.ks.b});
  Sensitivity s;
  for (const LightView& light : in.shade->lights) {
    const float weight = std::max({light.color.r, light.color.g, light.color.b});
    s.shortening += weight * (kd + ks * m.shininess);
    s.turning += weight * (kd + ks * std::sqrt(m.shininess));
  }
  return s;
}

// The block's weights from t = k / length (outside the run: the nearest end): plain t, or the
// exact parametrisation of n/w, affine along the row: the normal at t is the direction of
// (1 - t) la Na + t lz Nz, scaled here to sum to 1.
void linear_weights(int xb, int xa, int length, float la, float lz, bool exact, NormalBlock& out) {
  for (int i = 0; i < NormalBlock::kSize; ++i) {
    const int k = std::clamp(xb + i - xa, 0, length);
    const float t = length > 0 ? float(k) / float(length) : 0.0f;
    float a = 1.0f - t, b = t;
    if (exact) {
      const float wa = a * la, wz = b * lz, sum = wa + wz;
      a = sum > 0.0f ? wa / sum : 0.0f;
      b = sum > 0.0f ? wz / sum : 0.0f;
    }
    out.alpha[i] = a;
    out.beta[i] = b;
  }
}

// Scales each weight pair to give a unit normal (ends at cosine c).
void normalise_weights(float c, NormalBlock& out) {
  for (int i = 0; i < NormalBlock::kSize; ++i) {
    const float a = out.alpha[i], b = out.beta[i];
    const float len2 = a * a + b * b + 2.0f * a * b * c;
    const float g = len2 >= fast_math::kMinInvSqrtInput ? fast_math::inv_sqrt(len2) : 0.0f;
    out.alpha[i] = a * g;
    out.beta[i] = b * g;
  }
}

}  // namespace

void make_normal_block(const PhongSpanInput& in, PhongNormals mode, float tol, int xb, int py,
                       int xl, int xr, NormalBlock& out) {
  const int block = limits::kSeedBlockPx;
  const int xa = std::clamp(xb, xl, xr), xz = std::clamp(xb + block, xl, xr);
  const float la = unit_normal(in, xa, py, out.na), lz = unit_normal(in, xz, py, out.nz);
  const int length = xz - xa;
  const float c = std::clamp((out.na[0] * out.nz[0] + out.na[1] * out.nz[1]) + out.na[2] * out.nz[2], -1.0f, 1.0f);
  if (length == 0) return linear_weights(xb, xa, 0, la, lz, false, out);
  // Plain t turns the normal off the exact direction by at most psi |r - 1| / (4 min(1, r)),
  // r = lz / la (docs/STABILITY.md, "B2"): within half the budget it is kept, else the exact
  // parametrisation costs a division per weight. A zero end (r = 0 or inf) is always exact.
  const Sensitivity sens = sensitivity(in);
  const float psi = std::acos(c);
  const float r = lz / la;
  const float parametrisation_rad =
      (la > 0.0f && lz > 0.0f) ? psi * std::fabs(r - 1.0f) / (4.0f * std::min(1.0f, r)) : HUGE_VALF;
  const bool exact = !(sens.turning * parametrisation_rad <= 0.5f * tol);
  const float parametrisation_error = exact ? 0.0f : sens.turning * parametrisation_rad;
  linear_weights(xb, xa, length, la, lz, exact, out);
  if (mode == PhongNormals::Adaptive) {
    // The weighted unit normals are shortest, cos(psi / 2) = sqrt((1 + c) / 2), at equal weights.
    const float shortening = 1.0f - std::sqrt(0.5f * (1.0f + c));
    if (shortening * sens.shortening <= tol - parametrisation_error) return;  // lerp suffices
    return normalise_weights(c, out);
  }
  if (mode != PhongNormals::EqualAngle) return;
  // The slerp's equal angles differ from the exact parametrisation's by psi^3 / 48 at most
  // for psi <= pi / 2 (62 for small psi; STABILITY.md "B2"), plus the perspective term: past
  // the budget, or for ends more than a right angle apart (a fold), the exact weights, normalised.
  const float slerp_rad = psi <= 1.5707964f ? psi * psi * psi / 48.0f + parametrisation_rad : HUGE_VALF;
  if (!(sens.turning * slerp_rad <= tol)) {
    if (!exact) linear_weights(xb, xa, length, la, lz, true, out);
    return normalise_weights(c, out);
  }
  const float phi = psi / float(length);
  const float sin_psi = std::sin(psi);
  if (!(sin_psi > 1e-6f)) return;  // ends (nearly) equal: the lerp is the slerp
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

}  // namespace fastshade
