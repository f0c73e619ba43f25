// The colour model, written once for any scalar type: the yardstick (double), Gouraud's vertex
// lighting (float) and the scalar references of the SIMD kernels all call this.
//   colour = ambient + sum over lights of color * (kd * max(N.L, 0) + ks * max(N.H, 0)^n)
// clamped to [0, 1]; the specular term is not gated by N.L (the scene format's rule).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "frame/shade_constants.h"
#include "light/brdf.h"

namespace fastshade {

template <typename T>
using Vec3T = glm::vec<3, T, glm::defaultp>;

// max(c, 0)^n with c clamped to [-1, 1] first: rounding can leave N.H at 1 + 1e-7.
template <typename T>
inline T specular_power(T c, T n) {
  c = std::min(c, T(1));
  return c > T(0) ? std::pow(c, n) : T(0);
}

// n_view must be unit length; v_view is the unit direction toward the eye. kSpecular = false:
// the diffuse-only colour of `auto`'s paths without a highlight.
template <typename T, bool kSpecular = true>
inline Vec3T<T> blinn_phong(const Vec3T<T>& n_view, const Vec3T<T>& v_view, bool infinite_viewer,
                            const MaterialConstants& m, const ShadeConstants& k) {
  const Vec3T<T> kd(m.kd), ks(m.ks);
  const T n = std::is_same_v<T, double> ? T(m.shininess_d) : T(m.shininess);
  Vec3T<T> c(k.ambient);
  for (const LightView& light : k.lights) {
    const Vec3T<T> l(light.l_view);
    const T diffuse = std::max(glm::dot(n_view, l), T(0));
    T specular = 0;
    if constexpr (kSpecular) {
      const Vec3T<T> h = infinite_viewer ? Vec3T<T>(light.h_view) : glm::normalize(l + v_view);
      // The yardstick (double) is exact; float paths use the frame's approximation (--brdf).
      specular = std::is_same_v<T, double> ? specular_power(glm::dot(n_view, h), n)
                                           : T(eval_brdf_one(m.lobe, float(glm::dot(n_view, h))));
    }
    c += Vec3T<T>(light.color) * (kd * diffuse + ks * specular);
  }
  return c;
}

// A vertex's lit colour for Gouraud, clamped to [0, 1]: in float, or in double for a material
// whose highlight float cannot hold (MaterialConstants::shade_in_double).
// kSpecular = false: without the specular term (`auto`'s Gouraud path).
template <bool kSpecular = true>
inline glm::vec3 vertex_color(const glm::vec3& n_view, const glm::vec3& v_view, bool infinite_viewer,
                              const MaterialConstants& m, const ShadeConstants& k) {
  const glm::vec3 c =
      m.shade_in_double && kSpecular
          ? glm::vec3(blinn_phong<double, kSpecular>(glm::dvec3(n_view), glm::dvec3(v_view), infinite_viewer, m, k))
          : blinn_phong<float, kSpecular>(n_view, v_view, infinite_viewer, m, k);
  return glm::clamp(c, 0.0f, 1.0f);
}

// The output transfer: clamp to [0, 1], optional sRGB curve, round(255 v) (halves up).
template <typename T>
inline uint8_t quantize(T v, bool srgb) {
  v = std::clamp(v, T(0), T(1));
  if (!(v == v)) v = T(0);  // NaN never reaches the image
  if (srgb) v = v <= T(0.0031308) ? T(12.92) * v : T(1.055) * std::pow(v, T(1) / T(2.4)) - T(0.055);
  return static_cast<uint8_t>(std::floor(v * T(255) + T(0.5)));
}

}  // namespace fastshade
