// The classifier is conservative: its bounds of N.H, of the specular term and of Gouraud's
// diffuse error are never below what dense sampling of the drawn normals (linear, then
// normalised) finds, on 10^5 random triangles with the hard cases mixed in.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include <glm/geometric.hpp>

#include "classify/classifier.h"
#include "support/random_unit.h"

namespace fastshade {
namespace {

using test::random_unit;

dvec3 rotate_towards(const dvec3& a, const dvec3& dir, double angle) {  // a turned by angle
  const dvec3 side = glm::normalize(dir - glm::dot(dir, a) * a);
  return glm::normalize(std::cos(angle) * a + std::sin(angle) * side);
}

// Where antiparallel normals nearly cancel, the interpolated normal is shorter than its own
// rounding error and its direction is noise, in double as in the kernels' float; such points
// (|m| < 1e-6, a set of measure ~1e-12 of the triangle) are left out, as zero normals.
constexpr double kNoiseLength = 1e-6;

dvec3 interpolate(const dvec3 n[3], double l0, double l1) {
  const dvec3 m = l0 * n[0] + l1 * n[1] + (1.0 - l0 - l1) * n[2];
  const double len = glm::length(m);
  return len > kNoiseLength ? m / len : dvec3(0.0);  // the kernels' zero-stays-zero normalisation
}

// max over the triangle of f(normal) by a grid of barycentrics, then a local search around
// the best sample (the peak may be narrower than the grid).
template <typename F>
double sampled_max(const dvec3 n[3], F&& f) {
  constexpr int kGrid = 24;
  double best = -1e300, b0 = 1, b1 = 0;
  for (int i = 0; i <= kGrid; ++i)
    for (int j = 0; i + j <= kGrid; ++j) {
      const double l0 = double(i) / kGrid, l1 = double(j) / kGrid;
      const double v = f(interpolate(n, l0, l1), l0, l1);
      if (v > best) best = v, b0 = l0, b1 = l1;
    }
  for (double step = 1.0 / kGrid; step > 1e-9; step *= 0.5)
    for (int k = 0; k < 8; ++k)
      for (const auto& [d0, d1] : {std::pair{step, 0.0}, {-step, 0.0}, {0.0, step}, {0.0, -step},
                                   {step, -step}, {-step, step}}) {
        const double l0 = std::clamp(b0 + d0, 0.0, 1.0), l1 = std::clamp(b1 + d1, 0.0, 1.0 - l0);
        const double v = f(interpolate(n, l0, l1), l0, l1);
        if (v > best) best = v, b0 = l0, b1 = l1;
      }
  return best;
}

// A random case: normals of one of several hard kinds, H anywhere or perpendicular to all.
struct Case {
  dvec3 n[3];
  dvec3 h;
};

Case random_case(std::mt19937_64& rng, int kind) {
  std::uniform_real_distribution<double> u(0, 1);
  Case c;
  const dvec3 a = random_unit<dvec3>(rng);
  const double spread = std::pow(10.0, -4.0 * u(rng));  // 1e-4 .. 1 rad
  switch (kind % 6) {
    case 0:  // general
      for (dvec3& n : c.n) n = random_unit<dvec3>(rng);
      break;
    case 1:  // a small cone: a dense mesh's triangle
      for (dvec3& n : c.n) n = rotate_towards(a, random_unit<dvec3>(rng), spread * u(rng));
      break;
    case 2:  // equal
      c.n[0] = c.n[1] = c.n[2] = a;
      break;
    case 3:  // nearly equal: 1e-6 apart
      c.n[0] = a, c.n[1] = rotate_towards(a, random_unit<dvec3>(rng), 1e-6), c.n[2] = rotate_towards(a, random_unit<dvec3>(rng), 1e-6);
      break;
    case 4:  // antiparallel pair
      c.n[0] = a, c.n[1] = -a, c.n[2] = random_unit<dvec3>(rng);
      break;
    case 5:  // two equal, one apart
      c.n[0] = c.n[1] = a, c.n[2] = rotate_towards(a, random_unit<dvec3>(rng), spread);
      break;
  }
  // H: near the normals (the hard part: highlights), anywhere, or perpendicular to all.
  const int h_kind = int(u(rng) * 3);
  if (h_kind == 0) c.h = rotate_towards(c.n[0], random_unit<dvec3>(rng), 2.0 * spread * u(rng));
  else if (h_kind == 1) c.h = random_unit<dvec3>(rng);
  else {
    const dvec3 perp = glm::cross(c.n[0], c.n[2]);  // perpendicular to n0 and n2 (and n1 if coplanar)
    c.h = glm::length(perp) > 1e-9 ? glm::normalize(perp) : glm::normalize(glm::cross(c.n[0], dvec3(0.3, 0.5, 0.8)));
  }
  return c;
}

TEST(Classifier, NeverBelowSampledMaximumOfNH) {
  std::mt19937_64 rng(20261122);
  constexpr int kCases = 30000;
  int worst_case = -1;
  double worst_gap = 0;
  for (int i = 0; i < kCases; ++i) {
    const Case c = random_case(rng, i);
    const double bound = max_dot_over_triangle(c.n, c.h);
    const double sampled = sampled_max(c.n, [&](const dvec3& n, double, double) { return glm::dot(n, c.h); });
    if (sampled - bound > worst_gap) worst_gap = sampled - bound, worst_case = i;
  }
  // Sampled values near the noise length carry rounding of eps / |m| ~ 1e-10.
  EXPECT_LE(worst_gap, 1e-9) << "case " << worst_case;
}

// The specular decision, the one the image depends on: a triangle sent to a diffuse path has
// no sampled specular term at or above the threshold, for n from 1 to 1e6.
TEST(Classifier, NeverSendsAHighlightToADiffusePath) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  ShadeConstants k;
  MaterialConstants m{};
  m.kd = glm::vec3(0.7f);
  m.ks = glm::vec3(0.5f);
  const ClassifierParams params{1.0 / 510.0, 1.0 / 255.0, false};
  constexpr int kCases = 100000;
  long long missed = 0, cautious = 0, specular = 0;
  for (int i = 0; i < kCases; ++i) {
    const Case c = random_case(rng, i);
    m.shininess_d = std::pow(10.0, 6.0 * u(rng));  // 1 .. 1e6
    m.shininess = float(m.shininess_d);
    k.lights = {{glm::vec3(c.h), glm::vec3(c.h), glm::vec3(1.0f)}};  // L = H: infinite viewer
    ClassifyInput in;
    for (int v = 0; v < 3; ++v) in.n[v] = dvec3(glm::vec3(c.n[v]));  // what the pipeline stores
    const dvec3 h(k.lights[0].h_view);
    k.materials = {m};
    const Classification cls = Classifier(k, params).classify(in, 0);
    const double peak = sampled_max(in.n, [&](const dvec3& n, double, double) { return glm::dot(n, h); });
    const double spec = peak > 0 ? 0.5 * std::pow(std::min(peak, 1.0), m.shininess_d) : 0.0;
    if (cls.path == ShadePath::Specular) {
      ++specular;
      cautious += spec < params.spec_threshold;
    } else {
      missed += spec >= params.spec_threshold;
    }
  }
  EXPECT_EQ(missed, 0);
  std::printf("classifier: %lld of %d triangles sent to the specular path, %lld of them (%.1f %%) "
              "needlessly (sampled peak below the threshold)\n",
              specular, kCases, cautious, 100.0 * cautious / std::max(specular, 1LL));
  RecordProperty("needlessly_cautious", std::to_string(cautious));
}

// A local viewer: H varies over the triangle; the widened bound still covers it.
TEST(Classifier, LocalViewerBoundCoversSampledH) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  for (int i = 0; i < 10000; ++i) {
    Case c = random_case(rng, i);
    ClassifyInput in;
    in.local_viewer = true;
    const dvec3 centre = random_unit<dvec3>(rng) * (1.0 + 10.0 * u(rng));
    const double size = std::pow(10.0, -3.0 * u(rng));
    dvec3 pos[3];
    for (int v = 0; v < 3; ++v) {
      in.n[v] = c.n[v];
      pos[v] = centre + size * random_unit<dvec3>(rng);
      in.v[v] = glm::normalize(-pos[v]);
    }
    const dvec3 l = random_unit<dvec3>(rng);
    const double bound = max_cos_nh(in, l, dvec3(0));
    const double sampled = sampled_max(in.n, [&](const dvec3& n, double l0, double l1) {
      const dvec3 p = l0 * pos[0] + l1 * pos[1] + (1 - l0 - l1) * pos[2];
      const dvec3 lv = l + glm::normalize(-p);
      if (glm::length(lv) < 1e-12) return 1.0;
      return glm::dot(n, glm::normalize(lv));
    });
    ASSERT_LE(sampled, bound + 1e-9) << "case " << i;
  }
}

// Gouraud's diffuse error: |sum lambda_i max(N_i.L, 0) - max(N(lambda).L, 0)| never exceeds
// the classifier's diffuse bound, lit, unlit or across the terminator.
TEST(Classifier, DiffuseBoundCoversSampledGouraudError) {
  std::mt19937_64 rng(13);
  ShadeConstants k;
  MaterialConstants m{};
  m.kd = glm::vec3(1.0f);
  m.ks = glm::vec3(0.0f);
  m.shininess = 10, m.shininess_d = 10;
  for (int i = 0; i < 20000; ++i) {
    const Case c = random_case(rng, i);
    const dvec3 l = c.h;  // the hard directions of H serve as L here
    k.lights = {{glm::vec3(l), glm::vec3(l), glm::vec3(1.0f)}};
    ClassifyInput in;
    for (int v = 0; v < 3; ++v) in.n[v] = c.n[v];
    const dvec3 lf(k.lights[0].l_view);
    k.materials = {m};
    const Classification cls = Classifier(k, {1.0 / 510.0, 1.0, false}).classify(in, 0);
    const double err = sampled_max(in.n, [&](const dvec3& n, double l0, double l1) {
      const double gouraud = l0 * std::max(glm::dot(in.n[0], lf), 0.0) + l1 * std::max(glm::dot(in.n[1], lf), 0.0) +
                             (1 - l0 - l1) * std::max(glm::dot(in.n[2], lf), 0.0);
      return std::abs(gouraud - std::max(glm::dot(n, lf), 0.0));
    });
    ASSERT_LE(err, cls.diffuse_bound + 1e-9) << "case " << i;
  }
}

TEST(Classifier, PaperRuleSendsEverythingWithoutHighlightToGouraud) {
  ShadeConstants k;
  k.lights = {{glm::vec3(1, 0, 0), glm::vec3(0, 0, -1), glm::vec3(1.0f)}};
  MaterialConstants m{};
  m.kd = glm::vec3(0.8f), m.ks = glm::vec3(0.5f), m.shininess = 1000, m.shininess_d = 1000;
  k.materials = {m};
  ClassifyInput in;  // the terminator crosses it; N.H <= 0 everywhere: no highlight
  in.n[0] = glm::normalize(dvec3(1, 0, 0.1)), in.n[1] = glm::normalize(dvec3(-1, 0, 0.1)), in.n[2] = dvec3(0, 1, 0);
  EXPECT_EQ(Classifier(k, {1.0 / 510.0, 1.0 / 255.0, false}).classify(in, 0).path, ShadePath::PixelDiffuse);
  EXPECT_EQ(Classifier(k, {1.0 / 510.0, 1.0 / 255.0, true}).classify(in, 0).path, ShadePath::GouraudDiffuse);
  in.n[2] = dvec3(0, 0, -1);  // now H is a vertex normal: a highlight
  EXPECT_EQ(Classifier(k, {1.0 / 510.0, 1.0 / 255.0, true}).classify(in, 0).path, ShadePath::Specular);
}

TEST(Classifier, ZeroThresholdSendsEveryTriangleToTheSpecularPath) {
  ShadeConstants k;
  k.lights = {{glm::vec3(0, 0, 1), glm::vec3(0, 0, 1), glm::vec3(1.0f)}};
  MaterialConstants m{};
  m.kd = glm::vec3(0.8f), m.ks = glm::vec3(0.5f), m.shininess = 10, m.shininess_d = 10;
  k.materials = {m};
  ClassifyInput in;  // facing away: N.H < 0 everywhere
  in.n[0] = in.n[1] = in.n[2] = dvec3(0, 0, -1);
  EXPECT_EQ(Classifier(k, {0.0, 1.0 / 255.0, false}).classify(in, 0).path, ShadePath::Specular);
  EXPECT_EQ(Classifier(k, {1.0 / 510.0, 1.0 / 255.0, false}).classify(in, 0).path, ShadePath::GouraudDiffuse);
}

}  // namespace
}  // namespace fastshade
