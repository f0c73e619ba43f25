// Every span kernel's SIMD version against its scalar reference (shade/span_kernels.h), on
// every compiled ISA, for span lengths 0..2W+1 (W up to 16) at unaligned starts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include <glm/geometric.hpp>

#include "classify/segment_step.h"
#include "core/simd_target.h"
#include "frame/edge_function.h"
#include "light/brdf.h"
#include "shade/diffuse_quotient.h"
#include "shade/normal_blocks.h"
#include "shade/shade_limits.h"
#include "shade/span_kernels_testing.h"

namespace fastshade {
namespace {

struct Fixture {
  SetupTriangle tri{};
  Barycentrics bary;
};

// A random triangle around pixel (200, 100), wound for positive area, with random depth and w.
Fixture random_triangle(std::mt19937& rng) {
  std::uniform_int_distribution<int32_t> coord(-40 * 256, 60 * 256);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  Fixture f;
  SetupTriangle& t = f.tri;
  do {
    for (int i = 0; i < 3; ++i) {
      t.x_fx[i] = 200 * 256 + coord(rng);
      t.y_fx[i] = 100 * 256 + coord(rng);
      t.depth[i] = unit(rng);
      t.inv_w[i] = 0.2f + unit(rng);
    }
    if (doubled_area(t) < 0) {
      std::swap(t.x_fx[1], t.x_fx[2]);
      std::swap(t.y_fx[1], t.y_fx[2]);
    }
  } while (doubled_area(t) == 0);
  t.px_min[0] = static_cast<int16_t>(std::min({t.x_fx[0], t.x_fx[1], t.x_fx[2]}) / 256);
  t.px_min[1] = static_cast<int16_t>(std::min({t.y_fx[0], t.y_fx[1], t.y_fx[2]}) / 256);
  f.bary = barycentrics(t, triangle_edges(t));
  return f;
}

Plane random_plane(const Fixture& f, std::mt19937& rng, float lo, float hi) {
  std::uniform_real_distribution<float> u(lo, hi);
  return make_plane(f.bary, double(u(rng)) * f.tri.inv_w[0], double(u(rng)) * f.tri.inv_w[1],
                    double(u(rng)) * f.tri.inv_w[2]);
}

struct Row {
  std::vector<float> depth;
  std::vector<uint32_t> color;
  explicit Row(std::mt19937& rng) : depth(512), color(512, 0xFF000000u) {
    std::uniform_real_distribution<float> u(0.0f, 1.2f);  // some pixels fail the depth test
    for (float& z : depth) z = u(rng);
  }
  RowTarget target() { return {depth.data(), color.data()}; }
};

// Runs both versions on the same row; colour channels may differ by `lsb`, depth never.
template <typename Simd, typename Scalar>
void expect_same(const std::string& what, std::mt19937& rng, int lsb, Simd simd, Scalar scalar) {
  for (int start = 150; start < 154; ++start)
    for (int len = 0; len <= 2 * 16 + 1; ++len) {
      Row a(rng);
      Row b = a;
      simd(a.target(), start, start + len - 1);
      scalar(b.target(), start, start + len - 1);
      for (std::size_t x = 0; x < a.depth.size(); ++x) {
        ASSERT_EQ(a.depth[x], b.depth[x]) << what << " depth at x=" << x << " start " << start << " len " << len;
        for (int c = 0; c < 3; ++c) {
          const int va = (a.color[x] >> (8 * c)) & 0xFF, vb = (b.color[x] >> (8 * c)) & 0xFF;
          ASSERT_LE(std::abs(va - vb), lsb) << what << " colour at x=" << x << " len " << len;
        }
        if (x < std::size_t(start) || x >= std::size_t(start + len)) {
          ASSERT_EQ(a.color[x], 0xFF000000u) << what << " wrote outside the span at x=" << x;
        }
      }
    }
}

class SpanKernels : public ::testing::Test {
 protected:
};

TEST_F(SpanKernels, GouraudMatchesScalarReferenceOnEveryIsa) {
  std::mt19937 rng(11);
  for (const Isa isa_id : available_isas()) {
    const std::string isa(option_name(isa_id));
    const SimdTarget simd = simd_target(isa_id);
    for (int trial = 0; trial < 6; ++trial) {
      const Fixture f = random_triangle(rng);
      std::uniform_real_distribution<float> u(0.0f, 1.3f);  // lit vertices may pass 1
      glm::vec3 colors[3];
      for (glm::vec3& c : colors) c = {u(rng), u(rng), u(rng)};
      GouraudSpanInput in;
      in.bary = f.bary;
      in.depth = make_plane(f.bary, f.tri.depth[0], f.tri.depth[1], f.tri.depth[2]);
      set_gouraud_colors(in, f.bary, colors, f.tri.inv_w);
      const int py = 100 + trial;
      for (bool srgb : {false, true})
        // Linear output is the same IEEE arithmetic in both: bit-exact. The sRGB curve's
        // exp2/log2 use FMA where the target has it and std::fma in the reference: 1 LSB.
        expect_same("gouraud " + isa + (srgb ? " srgb" : ""), rng, srgb ? 1 : 0,
                    [&](RowTarget r, int x0, int x1) { gouraud_span(simd, in, srgb, py, x0, x1, r); },
                    [&](RowTarget r, int x0, int x1) { gouraud_span_scalar(in, srgb, py, x0, x1, r); });
    }
  }
}

TEST_F(SpanKernels, PhongMatchesScalarReferenceOnEveryIsaBrdfAndViewer) {
  std::mt19937 rng(12);
  ShadeConstants k;
  k.ambient = glm::vec3(0.05f);
  k.lights.push_back({glm::normalize(glm::vec3(1, 1, 1)), glm::normalize(glm::vec3(1, 1, 2.732f)), glm::vec3(0.9f)});
  k.lights.push_back({glm::normalize(glm::vec3(-1, 0.2f, 0.5f)), glm::vec3(0), glm::vec3(0.4f, 0.5f, 0.6f)});
  k.lights[1].h_view = glm::normalize(k.lights[1].l_view + glm::vec3(0, 0, 1));
  for (const Isa isa_id : available_isas()) {
    const std::string isa(option_name(isa_id));
    const SimdTarget simd = simd_target(isa_id);
    for (const BrdfChoice& brdf : brdf_choices())
      for (bool local : {false, true}) {
        k.local_viewer = local;
        MaterialConstants m{glm::vec3(0.6f, 0.5f, 0.4f), glm::vec3(0.5f), 40.0f, 40.0,
                            make_brdf(brdf, 40.0)};
        const Fixture f = random_triangle(rng);
        PhongSpanInput in;
        in.bary = f.bary;
        in.depth = make_plane(f.bary, f.tri.depth[0], f.tri.depth[1], f.tri.depth[2]);
        for (int c = 0; c < 3; ++c) {
          in.n[c] = random_plane(f, rng, c == 2 ? 0.2f : -1.0f, 1.0f);
          in.p[c] = random_plane(f, rng, c == 2 ? -9.0f : -2.0f, c == 2 ? -3.0f : 2.0f);
        }
        in.inv_w = make_plane(f.bary, f.tri.inv_w[0], f.tri.inv_w[1], f.tri.inv_w[2]);
        in.material = &m;
        in.shade = &k;
        // The IEEE parts are identical; exp2/log2 and the BRDFs' acos/cos differ by float
        // rounding (FMA or not, Highway's vs the C library's), never by a whole step but for
        // values that sit on a rounding boundary: at most 1 LSB.
        expect_same("phong " + isa + " " + option_name(brdf) + (local ? " local" : ""), rng, 1,
                    [&](RowTarget r, int x0, int x1) { phong_span(simd, in, 100, x0, x1, r); },
                    [&](RowTarget r, int x0, int x1) { phong_span_scalar(in, 100, x0, x1, r); });
      }
  }
}

// One white light near the view axis and a mid-shininess material; random triangles with
// normal components in [min_xy, 1] (x, y) and [min_z, 1] (z).
struct OneLight {
  ShadeConstants k;
  MaterialConstants m{glm::vec3(0.6f), glm::vec3(0.5f), 40.0f, 40.0, make_brdf(BrdfChoice{}, 40.0)};
  OneLight() {
    k.ambient = glm::vec3(0.05f);
    k.lights.push_back({glm::normalize(glm::vec3(0.2f, 0.3f, 1)), glm::vec3(0), glm::vec3(1.0f)});
    k.lights[0].h_view = glm::normalize(k.lights[0].l_view + glm::vec3(0, 0, 1));
  }
  PhongSpanInput random_input(std::mt19937& rng, float min_xy, float min_z) const {
    const Fixture f = random_triangle(rng);
    PhongSpanInput in;
    in.bary = f.bary;
    in.depth = make_plane(f.bary, f.tri.depth[0], f.tri.depth[1], f.tri.depth[2]);
    for (int c = 0; c < 3; ++c) in.n[c] = random_plane(f, rng, c == 2 ? min_z : min_xy, 1.0f);
    in.material = &m;
    in.shade = &k;
    return in;
  }
};

TEST_F(SpanKernels, HybridMatchesScalarReferenceOnEveryIsaAndStep) {
  std::mt19937 rng(13);
  const OneLight scene;
  int terminator_rows = 0;  // split rows whose N.L changes sign: the per-pixel clamp is exercised
  for (const Isa isa_id : available_isas()) {
    const std::string isa(option_name(isa_id));
    const SimdTarget simd = simd_target(isa_id);
    for (int split_light : {-1, 0})
      for (bool specular : {true, false})
      for (int step : {1, 2, 4, 8, 16}) {
        // A split light's rows reach past its terminator (normals' z down to -0.6).
        const PhongSpanInput in = scene.random_input(rng, -0.5f, split_light < 0 ? 0.5f : -0.6f);
        const HybridRun run{step, 145, 190, split_light, specular};  // the row's run starts and ends off the blocks
        if (split_light >= 0) {
          float nl_a = 0, nl_b = 0;
          phong_color_scalar(in, pixel_offsets(in.bary, run.xl, 100), split_light, &nl_a);
          phong_color_scalar(in, pixel_offsets(in.bary, run.xr, 100), split_light, &nl_b);
          terminator_rows += (nl_a < 0) != (nl_b < 0);
        }
        expect_same("hybrid " + isa + " step " + std::to_string(step) + " split " + std::to_string(split_light) +
                        (specular ? "" : " no specular"), rng, 1,
                    [&](RowTarget r, int x0, int x1) { hybrid_span(simd, in, run, 100, std::max(x0, run.xl), std::min(x1, run.xr), r); },
                    [&](RowTarget r, int x0, int x1) { hybrid_span_scalar(in, run, 100, std::max(x0, run.xl), std::min(x1, run.xr), r); });
      }
  }
  EXPECT_GT(terminator_rows, 0);
}

TEST_F(SpanKernels, NormalsPathsMatchScalarReferenceOnEveryIsa) {
  std::mt19937 rng(14);
  const OneLight scene;
  for (const Isa isa_id : available_isas()) {
    const std::string isa(option_name(isa_id));
    const SimdTarget simd = simd_target(isa_id);
    for (PhongNormals mode : {PhongNormals::Adaptive, PhongNormals::EqualAngle})
      for (float tol : {0.0f, hybrid_tolerance(2.0)}) {
        const PhongSpanInput in = scene.random_input(rng, -0.8f, 0.3f);
        const HybridRun run{1, 145, 190};
        expect_same("normals " + isa, rng, 1,
                    [&](RowTarget r, int x0, int x1) { normals_span(simd, in, mode, tol, run, 100, std::max(x0, run.xl), std::min(x1, run.xr), r); },
                    [&](RowTarget r, int x0, int x1) { normals_span_scalar(in, mode, tol, run, 100, std::max(x0, run.xl), std::min(x1, run.xr), r); });
      }
  }
}

// A triangle whose vertex normals lie within `spread` (radians, roughly) of a random axis:
// its normal planes, its normals over w as set-up reads them, and its box.
struct QuotientCase {
  Fixture f;
  PhongSpanInput in;
  glm::vec3 n_over_w[3];
  PixelRect box;
};
QuotientCase quotient_case(std::mt19937& rng, float spread, const MaterialConstants& m, const ShadeConstants& k) {
  std::normal_distribution<float> g(0.0f, 1.0f);
  QuotientCase qc;
  qc.f = random_triangle(rng);
  const SetupTriangle& t = qc.f.tri;
  const glm::vec3 axis = glm::normalize(glm::vec3(g(rng), g(rng), g(rng)));
  glm::vec3 n[3];
  for (int i = 0; i < 3; ++i) {
    n[i] = glm::normalize(axis + spread * glm::vec3(g(rng), g(rng), g(rng)));
    qc.n_over_w[i] = t.inv_w[i] * n[i];
  }
  qc.in.bary = qc.f.bary;
  qc.in.depth = make_plane(qc.f.bary, t.depth[0], t.depth[1], t.depth[2]);
  for (int c = 0; c < 3; ++c)
    qc.in.n[c] = make_plane(qc.f.bary, double(n[0][c]) * t.inv_w[0], double(n[1][c]) * t.inv_w[1],
                            double(n[2][c]) * t.inv_w[2]);
  qc.in.material = &m;
  qc.in.shade = &k;
  qc.box = {std::min({t.x_fx[0], t.x_fx[1], t.x_fx[2]}) / 256, std::min({t.y_fx[0], t.y_fx[1], t.y_fx[2]}) / 256,
            std::max({t.x_fx[0], t.x_fx[1], t.x_fx[2]}) / 256, std::max({t.y_fx[0], t.y_fx[1], t.y_fx[2]}) / 256};
  return qc;
}

struct TwoLights {
  ShadeConstants k;
  MaterialConstants m{glm::vec3(0.6f, 0.5f, 0.4f), glm::vec3(0.0f), 40.0f, 40.0, make_brdf(BrdfChoice{}, 40.0)};
  TwoLights() {
    k.ambient = glm::vec3(0.05f);
    k.lights.push_back({glm::normalize(glm::vec3(1, 1, 1)), glm::vec3(0, 0, 1), glm::vec3(0.9f)});
    k.lights.push_back({glm::normalize(glm::vec3(-1, 0.2f, 0.5f)), glm::vec3(0, 0, 1), glm::vec3(0.4f, 0.5f, 0.6f)});
  }
};

TEST_F(SpanKernels, DiffuseQuotientMatchesScalarReferenceOnEveryIsa) {
  std::mt19937 rng(15);
  TwoLights scene;
  for (const Isa isa_id : available_isas()) {
    const std::string isa(option_name(isa_id));
    const SimdTarget simd = simd_target(isa_id);
    for (bool srgb : {false, true}) {
      scene.k.srgb = srgb;
      QuotientCase qc = quotient_case(rng, 0.3f, scene.m, scene.k);
      DiffuseQuotient dq;
      while (!set_up_diffuse_quotient(qc.in, qc.f.bary, qc.box, qc.n_over_w, dq))
        qc = quotient_case(rng, 0.3f, scene.m, scene.k);
      // Linear output: the same IEEE operations, bit-exact; sRGB as gouraud's, 1 LSB.
      expect_same("diffuse quotient " + isa + (srgb ? " srgb" : ""), rng, srgb ? 1 : 0,
                  [&](RowTarget r, int x0, int x1) { diffuse_quotient_span(simd, qc.in, dq, 100, x0, x1, r); },
                  [&](RowTarget r, int x0, int x1) { diffuse_quotient_span_scalar(qc.in, dq, 100, x0, x1, r); });
    }
  }
}

// The quotient's colour against the normalised normal of the same planes in double, at every
// covered pixel of triangles set-up accepts, within the bound limits::kDiffuseQuotientMaxTermRatio
// promises: (3.5 R + 5 sqrt(R) + 3)u of each light's kd, and the sums' own rounding.
TEST(DiffuseQuotient, WithinItsRoundingBoundOfTheNormalisedPlanes) {
  std::mt19937 rng(16);
  const TwoLights scene;
  const double r = limits::kDiffuseQuotientMaxTermRatio, u = 0x1p-24;
  const double bound = ((3.5 * r + 5.0 * std::sqrt(r) + 3.0) + 8.0) * u;
  int accepted = 0, pixels = 0;
  double worst = 0.0;
  for (float spread : {0.001f, 0.05f, 0.3f, 0.8f, 2.0f})
    for (int trial = 0; trial < 200; ++trial) {
      const QuotientCase qc = quotient_case(rng, spread, scene.m, scene.k);
      DiffuseQuotient dq;
      if (!set_up_diffuse_quotient(qc.in, qc.f.bary, qc.box, qc.n_over_w, dq)) continue;
      ++accepted;
      const Barycentrics& b = qc.f.bary;
      for (int py = qc.box.y0; py <= qc.box.y1; py += 3)
        for (int px = qc.box.x0; px <= qc.box.x1; px += 3) {
          const double x = px - b.ax, y = py - b.ay;
          bool inside = true;
          for (int i = 0; i < 3; ++i) inside = inside && b.at_anchor[i] + b.d_dx[i] * x + b.d_dy[i] * y >= 0.0;
          if (!inside) continue;
          glm::dvec3 m_w;
          for (int c = 0; c < 3; ++c) m_w[c] = double(qc.in.n[c].v0) + double(qc.in.n[c].gx) * x + double(qc.in.n[c].gy) * y;
          const PhongColor got = diffuse_quotient_color_scalar(qc.in, dq, pixel_offsets(b, px, py));
          for (int c = 0; c < 3; ++c) {
            double want = scene.k.ambient[c], scale = want;
            for (const LightView& light : scene.k.lights) {
              const double lit = double(light.color[c]) * scene.m.kd[c];
              want += lit * std::max(glm::dot(glm::dvec3(light.l_view), m_w) / glm::length(m_w), 0.0);
              scale += lit;
            }
            const double err = std::abs(got.c[c] - want) / scale;
            worst = std::max(worst, err);
            ASSERT_LE(err, bound) << "spread " << spread << " trial " << trial << " pixel " << px << "," << py;
          }
          ++pixels;
        }
    }
  // Set-up must take most triangles whose normals spread up to a fifth of a radian or so.
  EXPECT_GT(accepted, 400);
  EXPECT_GT(pixels, 10000);
  std::printf("diffuse quotient: %d of 1000 triangles taken, %d pixels, worst %.1f u (bound %.0f u)\n", accepted,
              pixels, worst / u, bound / u);
}

TEST(DiffuseQuotient, RefusesWhatItCannotBound) {
  std::mt19937 rng(17);
  TwoLights scene;
  QuotientCase qc = quotient_case(rng, 0.01f, scene.m, scene.k);
  DiffuseQuotient dq;
  ASSERT_TRUE(set_up_diffuse_quotient(qc.in, qc.f.bary, qc.box, qc.n_over_w, dq));
  // Antiparallel vertex normals: |m| reaches 0 inside.
  QuotientCase opposed = qc;
  opposed.n_over_w[1] = -qc.n_over_w[0];
  EXPECT_FALSE(set_up_diffuse_quotient(opposed.in, opposed.f.bary, opposed.box, opposed.n_over_w, dq));
  // A vertex normal over w 100 times shorter than the planes' (a vertex 100 times farther): the
  // terms outgrow the least |m|^2 set-up can promise.
  QuotientCase far = qc;
  far.n_over_w[2] *= 0.01f;
  EXPECT_FALSE(set_up_diffuse_quotient(far.in, far.f.bary, far.box, far.n_over_w, dq));
  // More lights than a quotient holds planes for.
  while (scene.k.lights.size() <= static_cast<std::size_t>(limits::kDiffuseQuotientMaxLights)) scene.k.lights.push_back(scene.k.lights[0]);
  EXPECT_FALSE(set_up_diffuse_quotient(qc.in, qc.f.bary, qc.box, qc.n_over_w, dq));
}

// The block weights give the normals they promise: equal-angle = slerp of the ends, adaptive
// with no budget = the normalised lerp, even for per-pixel angles far below 2.4e-4, equal and
// antiparallel end normals.
TEST(NormalBlocks, WeightsReproduceSlerpAndNormalisedLerp) {
  std::mt19937 rng(21);
  const Fixture f = random_triangle(rng);
  ShadeConstants k;
  k.lights.push_back({glm::vec3(0, 0, 1), glm::vec3(0, 0, 1), glm::vec3(1.0f)});
  MaterialConstants m{glm::vec3(0.6f), glm::vec3(0.5f), 40.0f, 40.0, make_brdf(BrdfChoice{}, 40.0)};
  for (double angle : {1.0, 0.1, 1e-3, 1e-5, 1e-7, 0.0, 3.14159}) {
    const glm::dvec3 a(0, 0, 1), b(std::sin(angle), 0, std::cos(angle));
    PhongSpanInput in;
    in.bary = f.bary;
    in.material = &m;
    in.shade = &k;
    // Plane n(x) along row 100: a at x = 160, b at x = 176 (one block), w = 1.
    for (int c = 0; c < 3; ++c) {
      in.n[c] = Plane{float(a[c] + (b[c] - a[c]) * (160 - f.bary.ax) / -16.0 * -1.0), float((b[c] - a[c]) / 16.0), 0.0f, -2.0f, 2.0f};
      const float at160 = plane_at(in.n[c], pixel_offsets(f.bary, 160, f.bary.ay));
      in.n[c].v0 += float(a[c]) - at160;
    }
    for (PhongNormals mode : {PhongNormals::EqualAngle, PhongNormals::Adaptive}) {
      NormalBlock nb;
      // Equal angles are an approximation kept within the budget: any budget, to see them.
      const float tol = mode == PhongNormals::EqualAngle ? 1e30f : 0.0f;
      make_normal_block(in, mode, tol, 160, f.bary.ay, 150, 200, nb);
      const glm::dvec3 na(nb.na[0], nb.na[1], nb.na[2]), nz(nb.nz[0], nb.nz[1], nb.nz[2]);
      for (int i = 0; i < 16; ++i) {
        const glm::dvec3 got = double(nb.alpha[i]) * na + double(nb.beta[i]) * nz;
        ASSERT_TRUE(std::isfinite(got.x) && std::isfinite(got.z)) << angle;
        const double psi = std::acos(std::clamp(glm::dot(na, nz), -1.0, 1.0));
        if (psi > 3.0) continue;  // antiparallel: only finiteness is promised
        glm::dvec3 want;
        if (mode == PhongNormals::EqualAngle && std::sin(psi) > 1e-6)
          want = (std::sin((16 - i) * psi / 16) * na + std::sin(i * psi / 16) * nz) / std::sin(psi);
        else
          want = glm::normalize((1 - i / 16.0) * na + (i / 16.0) * nz);
        EXPECT_LT(glm::length(got - want), 2e-6) << "angle " << angle << " pixel " << i;
      }
    }
  }
}

// One light along +z (so H = +z for the infinite viewer), n = 100, on a random triangle: the
// segment plan for given vertex normals.
struct StepCase {
  ShadeConstants k;
  MaterialConstants m{glm::vec3(0.6f), glm::vec3(0.5f), 100.0f, 100.0, make_brdf(BrdfChoice{}, 100.0)};
  Fixture f;
  explicit StepCase(unsigned seed) {
    k.lights.push_back({glm::vec3(0, 0, 1), glm::vec3(0, 0, 1), glm::vec3(1.0f)});
    std::mt19937 rng(seed);
    f = random_triangle(rng);
  }
  SegmentPlan plan(glm::vec3 n0, glm::vec3 n1, glm::vec3 n2) const {
    SegmentStepInput in{{glm::normalize(n0), glm::normalize(n1), glm::normalize(n2)},
                        {f.tri.inv_w[0], f.tri.inv_w[1], f.tri.inv_w[2]}, {}};
    for (int v = 0; v < 3; ++v) in.n_over_w_dx += (dvec3(in.n[v]) * double(in.inv_w[v])) * f.bary.d_dx[v];
    in.material = &m;
    in.shade = &k;
    return hybrid_triangle_step(in, hybrid_tolerance(1.0));
  }
};

TEST(HybridStep, FollowsCurvatureAndHighlights) {
  const StepCase c(3);
  auto step_for = [&](glm::vec3 n0, glm::vec3 n1, glm::vec3 n2) { return c.plan(n0, n1, n2).step_px; };
  // Equal normals: nothing to interpolate wrongly, the longest segments.
  EXPECT_EQ(step_for({0.3f, 0, 1}, {0.3f, 0, 1}, {0.3f, 0, 1}), 16);
  // Curved and facing the highlight (H = +z inside the normals' cone): per-pixel Phong.
  EXPECT_EQ(step_for({0.4f, 0, 1}, {-0.4f, 0.3f, 1}, {0, -0.4f, 1}), 1);
  // Far from the highlight the same curvature takes segments at least as long, and a gentle
  // curvature there takes long ones.
  EXPECT_GE(step_for({1, 0, 0.2f}, {1, 0.3f, 0.35f}, {1, -0.3f, 0.3f}),
            step_for({0.4f, 0, 1}, {-0.4f, 0.3f, 1}, {0, -0.4f, 1}));
  EXPECT_GT(step_for({1, 0, 0.2f}, {1, 0.003f, 0.202f}, {1, -0.003f, 0.201f}), 1);
  // The specular term stays only where it can reach 2^-24 (n = 100, ks = 0.5: N.H above 0.85).
  EXPECT_TRUE(c.plan({0.4f, 0, 1}, {-0.4f, 0.3f, 1}, {0, -0.4f, 1}).specular);
  EXPECT_TRUE(c.plan({0.5f, 0, 1}, {0.5f, 0, 1}, {0.5f, 0, 1}).specular);     // N.H = 0.894
  EXPECT_FALSE(c.plan({0.7f, 0, 1}, {0.7f, 0, 1}, {0.7f, 0, 1}).specular);    // N.H = 0.819
  EXPECT_FALSE(c.plan({1, 0, 0.2f}, {1, 0.3f, 0.35f}, {1, -0.3f, 0.3f}).specular);
  // No budget: always per pixel.
  SegmentStepInput in;
  in.material = &c.m;
  in.shade = &c.k;
  EXPECT_EQ(hybrid_triangle_step(in, 0.0f).step_px, 1);
}

TEST(HybridStep, SplitsTheTerminatorsLightOnlyWhereItLengthensSegments) {
  const StepCase c(4);
  auto plan_for = [&](glm::vec3 n0, glm::vec3 n1, glm::vec3 n2) { return c.plan(n0, n1, n2); };
  // Gently curved across the terminator (N.L = z changes sign), far from H = +z: the kink
  // alone shortens the segments, and splitting the light lengthens them.
  const SegmentPlan across = plan_for({1, 0, 0.02f}, {1, 0.01f, -0.02f}, {1, -0.01f, 0.01f});
  EXPECT_EQ(across.split_light, 0);
  EXPECT_GT(across.step_px, 1);
  // The same curvature wholly on the lit side: no kink, nothing to split.
  const SegmentPlan lit = plan_for({1, 0, 0.52f}, {1, 0.01f, 0.48f}, {1, -0.01f, 0.51f});
  EXPECT_EQ(lit.split_light, -1);
  // Equal normals: no kink, nothing to split.
  EXPECT_EQ(plan_for({1, 0, 0.3f}, {1, 0, 0.3f}, {1, 0, 0.3f}).split_light, -1);
}

}  // namespace
}  // namespace fastshade
