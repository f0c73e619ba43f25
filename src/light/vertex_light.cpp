// Gouraud's vertex lighting in lanes: blinn_phong<float>() (light/lighting.h) with the same
// float operations in the same order (glm::dot's (x + y) + z, the BRDF kernels of brdf-inl.h
// that eval_brdf_one() mirrors), so a colour differs from the scalar one only as much as the
// BRDF kernels do (tests/light/vertex_light_test.cpp).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "light/vertex_light.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "core/dispatch.h"
#include "core/dot3-inl.h"
#include "light/brdf-inl.h"
#include "light/brdf_variants.h"
#include "light/lighting.h"
#include "light/vertex_light.h"

HWY_BEFORE_NAMESPACE();
namespace fastshade {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// One vector of vertices: unit normals in, colours clamped to [0, 1] out (x86 max takes its
// second operand for NaN, so a degenerate normal's NaN becomes 0 here rather than passing).
template <BrdfKind K, bool kSpecular, class D, class V = hn::Vec<D>>
HWY_INLINE void LightLanes(D d, const MaterialConstants& m, const ShadeConstants& k, V nx, V ny, V nz, V& r,
                           V& g, V& b) {
  V c[3] = {hn::Set(d, k.ambient.r), hn::Set(d, k.ambient.g), hn::Set(d, k.ambient.b)};
  for (const LightView& light : k.lights) {
    const V diffuse = hn::Max(
        Dot3<D>(nx, ny, nz, hn::Set(d, light.l_view.x), hn::Set(d, light.l_view.y), hn::Set(d, light.l_view.z)),
        hn::Zero(d));
    V specular = hn::Zero(d);
    if constexpr (kSpecular)
      specular = Brdf<K>(
          d, Dot3<D>(nx, ny, nz, hn::Set(d, light.h_view.x), hn::Set(d, light.h_view.y), hn::Set(d, light.h_view.z)),
          m.lobe);
    for (int ch = 0; ch < 3; ++ch) {
      const V lit = hn::Add(hn::Mul(hn::Set(d, m.kd[ch]), diffuse), hn::Mul(hn::Set(d, m.ks[ch]), specular));
      c[ch] = hn::Add(c[ch], hn::Mul(hn::Set(d, light.color[ch]), lit));
    }
  }
  r = hn::Min(hn::Max(c[0], hn::Zero(d)), hn::Set(d, 1.0f));
  g = hn::Min(hn::Max(c[1], hn::Zero(d)), hn::Set(d, 1.0f));
  b = hn::Min(hn::Max(c[2], hn::Zero(d)), hn::Set(d, 1.0f));
}

template <BrdfKind K, bool kSpecular>
void LightBlock(const glm::vec3* n_view, std::size_t count, const MaterialConstants& m, const ShadeConstants& k,
                glm::vec3* color) {
  const hn::ScalableTag<float> d;
  const std::size_t lanes = hn::Lanes(d);
  hn::Vec<decltype(d)> nx, ny, nz, r, g, b;
  std::size_t i = 0;
  for (; i + lanes <= count; i += lanes) {
    hn::LoadInterleaved3(d, &n_view[i].x, nx, ny, nz);
    LightLanes<K, kSpecular>(d, m, k, nx, ny, nz, r, g, b);
    hn::StoreInterleaved3(r, g, b, d, &color[i].x);
  }
  if (i == count) return;
  // The tail through padded copies: never read or write past the arrays.
  constexpr std::size_t kMaxLanes = HWY_MAX_BYTES / sizeof(float);
  alignas(64) float n_tail[3 * kMaxLanes] = {}, c_tail[3 * kMaxLanes];
  for (std::size_t j = i; j < count; ++j)
    for (int a = 0; a < 3; ++a) n_tail[3 * (j - i) + a] = n_view[j][a];
  hn::LoadInterleaved3(d, n_tail, nx, ny, nz);
  LightLanes<K, kSpecular>(d, m, k, nx, ny, nz, r, g, b);
  hn::StoreInterleaved3(r, g, b, d, c_tail);
  for (std::size_t j = i; j < count; ++j)
    for (int a = 0; a < 3; ++a) color[j][a] = c_tail[3 * (j - i) + a];
}

void LightVertices(const glm::vec3* n_view, std::size_t count, const MaterialConstants& m, const ShadeConstants& k,
                   bool specular, glm::vec3* color) {
  if (!specular) return LightBlock<BrdfKind::Exact, false>(n_view, count, m, k, color);
  with_brdf_kind(m.lobe.kind,
                 [&](auto kind) { LightBlock<decltype(kind)::value, true>(n_view, count, m, k, color); });
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace fastshade {

HWY_EXPORT(LightVertices);

void light_vertices(SimdTarget simd, const glm::vec3* n_view, const glm::vec3* pos_view, std::size_t count,
                    const MaterialConstants& m, const ShadeConstants& k, bool specular, glm::vec3* color) {
  if (k.local_viewer || (specular && m.shade_in_double))
    return light_vertices_scalar(n_view, pos_view, count, m, k, specular, color);
  FASTSHADE_DISPATCH(simd, LightVertices)(n_view, count, m, k, specular, color);
}

void light_vertices_scalar(const glm::vec3* n_view, const glm::vec3* pos_view, std::size_t count,
                           const MaterialConstants& m, const ShadeConstants& k, bool specular,
                           glm::vec3* color) {
  for (std::size_t i = 0; i < count; ++i) {
    const glm::vec3 v_view = k.local_viewer ? glm::normalize(-pos_view[i]) : glm::vec3(0, 0, 1);
    color[i] = specular ? vertex_color<true>(n_view[i], v_view, !k.local_viewer, m, k)
                        : vertex_color<false>(n_view[i], v_view, !k.local_viewer, m, k);
  }
}

}  // namespace fastshade
#endif
