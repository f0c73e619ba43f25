#include "classify/classifier.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "classify/classify_limits.h"

namespace fastshade {

namespace {

double max_channel(const glm::vec3& c) { return std::max({c.r, c.g, c.b}); }

double angle_between(const dvec3& a, const dvec3& b) {  // unit vectors, stable near 0 and pi
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

// Bound of the Gouraud error of one light's max(N.L, 0) over the triangle (derivation in
// docs/CLASSIFIER.md). With m = sum lambda_i n_i, per-pixel shading gives max(L.m / |m|, 0)
// and Gouraud sum lambda_i max(L.n_i, 0):
//  - all vertices lit: Gouraud = L.m, so the error is (L.m^)(1 - |m|) <= peak (1 - min|m|);
//  - none lit: L.m <= 0 everywhere, both are 0;
//  - mixed (the terminator crosses): both lie in [0, max(max_i L.n_i, peak)].
// peak bounds max L.m^ over the triangle, min_len bounds |m| from below.
double diffuse_error(const ClassifyInput& in, const dvec3& l, double peak, double min_len) {
  double lo = 1.0, hi = -1.0;
  for (const dvec3& n : in.n) {
    const double d = glm::dot(n, l);
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  if (hi <= 0.0) return 0.0;
  peak = std::clamp(peak, 0.0, 1.0);
  if (lo >= 0.0) return peak * (1.0 - min_len);
  return std::max(hi, peak);
}

}  // namespace

double max_cos_nh(const ClassifyInput& in, const dvec3& l, const dvec3& h_infinite) {
  if (!in.local_viewer) return max_dot_over_triangle(in.n, h_infinite);
  // A local viewer's V sweeps the spherical triangle of the vertices' V (positions are
  // interpolated linearly), inside the cap of radius dv around the centre's V_c. H = (L + V)
  // / |L + V| moves by at most |dV| / |L + V|, and |L + V| = 2 cos(angle(L, V) / 2), so H
  // stays within dh = dv / (2 cos(phi_max / 2)) of H_c; N.H <= cos(max(0, beta - dh)) where
  // cos(beta) bounds N.H_c over the normals.
  const dvec3 v_c = glm::normalize(in.v[0] + in.v[1] + in.v[2]);
  double dv = 0.0;
  for (const dvec3& v : in.v) dv = std::max(dv, angle_between(v_c, v));
  const double phi_max = angle_between(l, v_c) + dv;
  const double half_cos = std::cos(phi_max / 2.0);
  if (!(half_cos > 1e-3)) return 1.0;  // light nearly behind the eye: H is unstable
  const dvec3 h_c = glm::normalize(l + v_c);
  const double dh = dv / (2.0 * half_cos);
  const double beta = std::acos(std::clamp(max_dot_over_triangle(in.n, h_c), -1.0, 1.0));
  return std::cos(std::max(0.0, beta - dh));
}

namespace {
constexpr double kNegligible = limits::kNegligibleLightShare;
}  // namespace

Classifier::Classifier(const ShadeConstants& k, const ClassifierParams& p) : shade_(k), params_(p) {
  for (const MaterialConstants& m : k.materials) {
    MaterialTerms t;
    t.shininess = m.shininess_d;
    glm::dvec3 brightest(k.ambient);
    double spec_sum = 0.0;  // the lights' ks * colour, max channel each
    for (const LightView& light : k.lights) {
      LightTerms lt;
      lt.spec_weight = max_channel(light.color * m.ks);
      lt.diffuse_weight = max_channel(light.color * m.kd);
      // weight * c^n < kNegligible * threshold  <=>  c < (kNegligible * threshold / weight)^(1/n)
      auto cos_below = [&](double term) {  // weight * c^n < term  <=>  c < (term / weight)^(1/n)
        return lt.spec_weight > 0.0 ? std::pow(term / lt.spec_weight, 1.0 / m.shininess_d) : 2.0;
      };
      lt.cos_negligible = cos_below(kNegligible * p.spec_threshold);
      lt.cos_share = cos_below(p.spec_threshold / double(k.lights.size()));
      lt.cos_alone = cos_below(p.spec_threshold);
      spec_sum += lt.spec_weight;
      if (lt.spec_weight >= p.spec_threshold)
        t.highlight_lights |= uint64_t(1) << std::min<std::size_t>(t.lights.size(), 63);
      t.lights.push_back(lt);
      brightest += glm::dvec3(light.color * m.kd);
    }
    t.may_saturate = std::max({brightest.r, brightest.g, brightest.b}) > 1.0;
    // Every light's term at its peak N.H = 1 together: below the threshold no triangle of the
    // material can show a highlight, so a dense block of them is classified, not sent to the
    // specular path (classify() still decides each triangle, safely).
    t.can_highlight = spec_sum > 0.0 && spec_sum >= p.spec_threshold;
    ConeBatchTerms batch;
    batch.spec_threshold = p.spec_threshold;
    batch.gouraud_budget = p.gouraud_budget;
    batch.negligible_share = kNegligible;
    batch.shininess = t.shininess;
    batch.paper_rule = p.paper_rule;
    for (std::size_t i = 0; i < k.lights.size(); ++i) {
      const LightTerms& lt = t.lights[i];
      const dvec3 h(k.lights[i].h_view), l(k.lights[i].l_view);
      batch.lights.push_back({{h.x, h.y, h.z}, {l.x, l.y, l.z}, lt.spec_weight, lt.cos_negligible,
                              lt.cos_share, lt.cos_alone, lt.diffuse_weight});
    }
    batch_.push_back(std::move(batch));
    materials_.push_back(std::move(t));
  }
}

const ConeBatchTerms* Classifier::cone_batch_terms(int material) const {
  if (shade_.local_viewer || shade_.two_sided || materials_[material].may_saturate) return nullptr;
  return &batch_[material];
}

Classifier::Bounds Classifier::specular(const ClassifyInput& in, const MaterialTerms& m,
                                        const NormalCone* cone) const {
  Bounds b;
  for (std::size_t i = 0; i < m.lights.size(); ++i) {
    const LightTerms& lt = m.lights[i];
    if (lt.spec_weight <= 0.0) continue;
    const LightView& light = shade_.lights[i];
    const double c_max = cone ? cone->max_dot(dvec3(light.h_view))
                              : max_cos_nh(in, dvec3(light.l_view), dvec3(light.h_view));
    // Where the term is small its exact value does not matter, only a bound: no pow. The cone
    // bound is only a first look: a term that may reach its share of the threshold is left
    // to the exact bounds (returned as infinite).
    double spec = 0.0;
    if (c_max <= 0.0) spec = 0.0;
    else if (c_max <= lt.cos_negligible) spec = kNegligible * params_.spec_threshold;
    else if (cone && c_max < lt.cos_share) spec = params_.spec_threshold / double(m.lights.size());
    else if (cone) spec = HUGE_VAL;
    else spec = lt.spec_weight * std::pow(std::min(c_max, 1.0), m.shininess);
    b.specular += spec;
    if (spec >= params_.spec_threshold) b.lights_with_highlight |= uint64_t(1) << std::min<std::size_t>(i, 63);
  }
  return b;
}

double Classifier::diffuse(const ClassifyInput& in, const MaterialTerms& m, const NormalCone* cone) const {
  double sum = 0.0, min_len = -1.0;
  for (std::size_t i = 0; i < m.lights.size(); ++i) {
    const LightTerms& lt = m.lights[i];
    if (lt.diffuse_weight <= 0.0) continue;
    const dvec3 l(shade_.lights[i].l_view);
    if (min_len < 0.0) min_len = cone ? cone->cos_half : min_length_over_triangle(in.n);
    const double peak = cone ? cone->max_dot(l) : max_dot_over_triangle(in.n, l);
    sum += lt.diffuse_weight * diffuse_error(in, l, peak, min_len);
  }
  return sum;
}

// Gouraud interpolates clamped vertex colours: a channel above 1 at some vertices but not
// all breaks the diffuse bound (the clamp is not linear there).
bool Classifier::saturates(const ClassifyInput& in, int material) const {
  if (!materials_[material].may_saturate) return false;
  const MaterialConstants& m = shade_.materials[material];
  glm::dvec3 vertex_color[3];
  for (glm::dvec3& c : vertex_color) c = glm::dvec3(shade_.ambient);
  for (const LightView& light : shade_.lights)
    for (int v = 0; v < 3; ++v)
      vertex_color[v] += glm::dvec3(light.color * m.kd) * std::max(glm::dot(in.n[v], dvec3(light.l_view)), 0.0);
  for (int c = 0; c < 3; ++c) {
    const int over = (vertex_color[0][c] > 1.0) + (vertex_color[1][c] > 1.0) + (vertex_color[2][c] > 1.0);
    if (over > 0 && over < 3) return true;
  }
  return false;
}

Classification Classifier::classify(const ClassifyInput& in, int material) const {
  // Most triangles are decided by the cheap cone bounds; the exact ones (edge maxima,
  // interior test, closest point) run only where the cheap ones are too loose to decide.
  const MaterialTerms& m = materials_[material];
  const NormalCone cone(in.n);
  const NormalCone* cheap = cone.cos_half > 0.0 && !in.local_viewer ? &cone : nullptr;
  Classification out;
  // A vertex whose own specular term reaches the threshold decides at once: the drawn
  // normals include the vertex normals.
  for (std::size_t i = 0; i < m.lights.size(); ++i) {
    const dvec3 h(shade_.lights[i].h_view);
    const double c_vertex = std::max({glm::dot(in.n[0], h), glm::dot(in.n[1], h), glm::dot(in.n[2], h)});
    if (!in.local_viewer && m.lights[i].spec_weight > 0.0 && c_vertex >= m.lights[i].cos_alone) {
      out.path = ShadePath::Specular;
      out.specular_bound = m.lights[i].spec_weight * std::pow(std::min(c_vertex, 1.0), m.shininess);
      out.lights_with_highlight = uint64_t(1) << std::min<std::size_t>(i, 63);
      return out;
    }
  }
  Bounds spec = specular(in, m, cheap);
  bool spec_exact = !cheap;
  if (spec.specular >= params_.spec_threshold && !spec_exact) {
    spec = specular(in, m, nullptr);
    spec_exact = true;
  }
  out.specular_bound = spec.specular;
  out.lights_with_highlight = spec.lights_with_highlight;
  if (spec.specular >= params_.spec_threshold) {
    out.path = ShadePath::Specular;
    return out;
  }
  if (params_.paper_rule) {
    out.path = ShadePath::GouraudDiffuse;
    return out;
  }
  out.diffuse_bound = diffuse(in, m, cheap);
  if (out.diffuse_bound + out.specular_bound > params_.gouraud_budget && cheap) {
    if (!spec_exact) out.specular_bound = specular(in, m, nullptr).specular;
    out.diffuse_bound = diffuse(in, m, nullptr);
  }
  const bool gouraud = out.diffuse_bound + out.specular_bound <= params_.gouraud_budget && !saturates(in, material);
  out.path = gouraud ? ShadePath::GouraudDiffuse : ShadePath::PixelDiffuse;
  return out;
}

}  // namespace fastshade
