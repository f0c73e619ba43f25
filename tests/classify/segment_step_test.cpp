// hybrid_triangle_step() against brute force: on random triangles, every row's segments as the
// hybrid kernel lays them (ends every step px from the row's first covered pixel, the last at
// its last), interpolating exact colours at their ends (a split light's N.L apart, clamped
// after; no specular term where the plan leaves it out), stay within the tolerance of the exact
// colour at every covered pixel, and a left-out specular term is below kNegligibleSpecular there. All in double, with the
// drawn normal u = q / |q| of the perspective-correct q = sum b_i n_i / w_i: the derivation's
// claim itself, free of float rounding.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <glm/geometric.hpp>

#include "classify/segment_step.h"
#include "support/random_unit.h"

namespace fastshade {
namespace {

using test::random_unit;

struct Scene {
  ShadeConstants shade;
  MaterialConstants material{};
};

// Blinn-Phong as the kernels evaluate it (BRDF `exact`), in double: every light's diffuse and
// specular terms, each colour channel's largest weight (what the bound sums). The split light's
// diffuse term is kept apart, as the kernel interpolates it: `rest` and its unclamped N.L.
struct Colour {
  double rest = 0.0, n_dot_l = 0.0, kd_weight = 0.0;
  double value() const { return rest + kd_weight * std::max(n_dot_l, 0.0); }
};

Colour colour(const Scene& s, const dvec3& u, int split_light, bool specular = true) {
  Colour c;
  for (int index = 0; index < int(s.shade.lights.size()); ++index) {
    const LightView& light = s.shade.lights[index];
    const double weight = std::max({light.color.r, light.color.g, light.color.b});
    const double kd = s.material.kd.r, ks = s.material.ks.r;
    const double nl = glm::dot(u, dvec3(light.l_view));
    const double nh = std::max(0.0, glm::dot(u, dvec3(light.h_view)));
    const double spec = specular ? ks * std::pow(nh, s.material.shininess_d) : 0.0;
    if (index == split_light) {
      c.n_dot_l = nl;
      c.kd_weight = weight * kd;
      c.rest += weight * spec;
    } else {
      c.rest += weight * (kd * std::max(nl, 0.0) + spec);
    }
  }
  return c;
}

TEST(SegmentStep, RandomTrianglesStayWithinTheToleranceAtEveryPixel) {
  std::mt19937 rng(20);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  const double shininess[] = {1.0, 1.5, 2.0, 3.0, 10.0, 37.5, 100.0, 1000.0, 1e4};
  const float tol = hybrid_tolerance(1.0);
  int long_segments = 0, split = 0, no_specular = 0, pixels_checked = 0;
  double worst = 0.0;  // the largest error over the tolerance
  for (int trial = 0; trial < 1500; ++trial) {
    Scene s;
    const int lights = trial % 5 == 0 ? 2 : 1;
    for (int i = 0; i < lights; ++i) {
      const dvec3 l = random_unit<dvec3>(rng);
      s.shade.lights.push_back({glm::vec3(l), glm::vec3(glm::normalize(l + dvec3(0, 0, 1))), glm::vec3(float(0.3 + 0.7 * u01(rng)))});
    }
    const double n = shininess[trial % std::size(shininess)];
    const float kd = float(0.2 + 0.8 * u01(rng)), ks = float(u01(rng));
    s.material.kd = glm::vec3(kd);
    s.material.ks = glm::vec3(ks);
    s.material.shininess = float(n);
    s.material.shininess_d = n;
    // Normals around an axis: half the triangles face the first light's highlight, so that
    // segments near the lobe's peak are tried; spread from nearly flat to 60 degrees.
    const dvec3 h(s.shade.lights[0].h_view);
    const dvec3 axis = trial % 2 == 0 ? glm::normalize(h + 0.3 * u01(rng) * random_unit<dvec3>(rng)) : random_unit<dvec3>(rng);
    const double spread = std::pow(10.0, -3.0 + 3.0 * u01(rng));  // radians, 0.001 .. 1
    SegmentStepInput in;
    dvec3 n_d[3], p[3];
    double inv_w[3];
    const double size = 16.0 + 200.0 * u01(rng);
    for (int v = 0; v < 3; ++v) {
      n_d[v] = dvec3(glm::vec3(glm::normalize(axis + spread * random_unit<dvec3>(rng))));  // as a mesh holds it
      inv_w[v] = 0.5 + 1.5 * u01(rng);
      p[v] = dvec3(size * u01(rng), size * u01(rng), 0.0);
      in.n[v] = glm::vec3(n_d[v]);
      in.inv_w[v] = float(inv_w[v]);
      inv_w[v] = in.inv_w[v];
    }
    const double area = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y);
    if (std::abs(area) < 20.0) continue;
    // Screen-linear barycentrics b_i(x, y) = (e_i . (x, y, 1)) / area, e_i of the edge opposite i.
    dvec3 e[3];
    for (int v = 0; v < 3; ++v) {
      const dvec3& a = p[(v + 1) % 3];
      const dvec3& b = p[(v + 2) % 3];
      e[v] = dvec3(a.y - b.y, b.x - a.x, a.x * b.y - b.x * a.y) / area;
    }
    auto q_at = [&](double x, double y) {
      dvec3 q(0.0);
      for (int v = 0; v < 3; ++v) q += (e[v].x * x + e[v].y * y + e[v].z) * inv_w[v] * n_d[v];
      return q;
    };
    for (int v = 0; v < 3; ++v) in.n_over_w_dx += e[v].x * inv_w[v] * n_d[v];
    in.material = &s.material;
    in.shade = &s.shade;
    const SegmentPlan plan = hybrid_triangle_step(in, tol);
    const int step = plan.step_px;
    if (step == 1) continue;
    ++long_segments;
    split += plan.split_light >= 0;
    no_specular += !plan.specular;
    auto inside = [&](double x, double y) {
      for (int v = 0; v < 3; ++v)
        if (e[v].x * x + e[v].y * y + e[v].z < 0.0) return false;
      return true;
    };
    auto exact = [&](int x, int y, bool specular = true) {
      return colour(s, glm::normalize(q_at(x + 0.5, y + 0.5)), plan.split_light, specular);
    };
    for (int y = 0; y < int(size) + 1; ++y) {
      int xl = 1 << 30, xr = -1;
      for (int x = 0; x < int(size) + 1; ++x)
        if (inside(x + 0.5, y + 0.5)) xl = std::min(xl, x), xr = std::max(xr, x);
      for (int x = xl; x <= xr; ++x) {
        const int ea = xl + ((x - xl) & ~(step - 1)), eb = std::min(ea + step, xr);
        const double t = eb > ea ? double(x - ea) / double(eb - ea) : 0.0;
        const Colour ca = exact(ea, y, plan.specular), cb = exact(eb, y, plan.specular);
        if (!plan.specular)
          ASSERT_LT(exact(x, y).value() - exact(x, y, false).value(), limits::kNegligibleSpecular) << "trial " << trial;
        const Colour drawn{ca.rest + t * (cb.rest - ca.rest), ca.n_dot_l + t * (cb.n_dot_l - ca.n_dot_l), ca.kd_weight};
        const double err = std::abs(drawn.value() - exact(x, y).value());
        worst = std::max(worst, err / tol);
        ++pixels_checked;
        ASSERT_LE(err, tol * (1.0 + 1e-9)) << "trial " << trial << " n " << n << " step " << step << " pixel (" << x
                                           << ", " << y << ")";
      }
    }
  }
  // The test is only worth something if it tries long segments, often.
  EXPECT_GT(long_segments, 300);
  EXPECT_GT(split, 30);
  EXPECT_GT(no_specular, 100);
  EXPECT_GT(pixels_checked, 1000000);
  std::printf("%d triangles with segments of 2+ px (%d with a split light, %d without specular ends), %d pixels; "
              "worst error %.3f of the tolerance\n",
              long_segments, split, no_specular, pixels_checked, worst);
}

}  // namespace
}  // namespace fastshade
