// Stiff inputs for the span kernels themselves (shade/span_kernels.h, fast_math.h, brdf.h),
// where the float values are visible: spans of 65536 px with per-pixel normal angles far below
// 2.4e-4 rad, an exact 0.2 px^2 sliver 2000 px long, and the transcendental helpers on their
// whole domain. Every output is compared with the same quantity in double.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "classify/segment_step.h"
#include "core/simd_target.h"
#include "frame/edge_function.h"
#include "light/brdf.h"
#include "light/fast_math.h"
#include "light/lighting.h"
#include "raster/spans.h"
#include "shade/method.h"
#include "shade/normal_blocks.h"
#include "shade/shade_limits.h"
#include "shade/span_kernels_testing.h"
#include "stability/stability_bounds.h"
#include "stability/stability_harness.h"

namespace fastshade::stability {
namespace {

// The suite's lighting (stability_harness.h) as the kernels read it.
struct Lighting {
  ShadeConstants k;
  MaterialConstants m;
  Scene scene;  // the same, for the bounds
  explicit Lighting(double n) {
    scene = base_scene(1, 1, n, glm::vec3(0.3f, 0.2f, 1.0f));
    k = shade_constants(scene, view_transform(scene));
    m = k.materials[0];
  }
  glm::dvec3 l() const { return glm::dvec3(k.lights[0].l_view); }
  glm::dvec3 h() const { return glm::dvec3(k.lights[0].h_view); }
  // Blinn-Phong in double for a unit normal, one channel (the suite's colours are grey).
  double exact(const glm::dvec3& n) const {
    return kAmbient + kDiffuse * std::max(glm::dot(n, l()), 0.0) +
           kSpecular * cos_power(glm::dot(n, h()), m.shininess_d);
  }
};

// A row of scratch: depth cleared to 1 (every pixel passes a depth of 0.5), colour 0, with
// the kernels' slack past the end.
struct Row {
  std::vector<float> depth;
  std::vector<uint32_t> color;
  explicit Row(int width) : depth(width + limits::kScratchPadPx, 1.0f), color(width + limits::kScratchPadPx, 0) {}
  RowTarget target() { return {depth.data(), color.data()}; }
  int channel(int x, int ch) const { return (color[x] >> (8 * ch)) & 0xFF; }
};

Plane constant_plane(float v) { return Plane{v, 0, 0, v, v}; }

// ---- 65536-px spans -------------------------------------------------------------------------

constexpr int kSpanPx = 65536;
constexpr int kTilePx = limits::kMaxTilePx;  // kernels are called a tile's part at a time

// n/w along the row is H + (x - kSpanPx/2) phi e (w = 1): the normal turns by at most phi per
// pixel, through the highlight at the row's middle.
struct LongSpan {
  Lighting light;
  PhongSpanInput in;
  glm::dvec3 e;
  double phi;
  LongSpan(double n, double phi_rad) : light(n), phi(phi_rad) {
    e = glm::normalize(glm::cross(light.h(), glm::dvec3(0, 1, 0)));
    in.bary = Barycentrics{0, 0, {}, {}, {}};
    in.depth = constant_plane(0.5f);
    for (int c = 0; c < 3; ++c) {
      const double v0 = light.h()[c] - kSpanPx / 2 * phi * e[c], v1 = light.h()[c] + kSpanPx / 2 * phi * e[c];
      in.n[c] = Plane{float(v0), float(phi * e[c]), 0, float(std::min(v0, v1)), float(std::max(v0, v1))};
    }
    in.material = &light.m;
    in.shade = &light.k;
  }
  glm::dvec3 normal(int x) const { return glm::normalize(light.h() + (x + 0.0 - kSpanPx / 2) * phi * e); }
  template <typename SpanFn>
  Row shade(SpanFn&& span) const {
    Row row(kSpanPx);
    for (int x0 = 0; x0 < kSpanPx; x0 += kTilePx) span(row.target(), x0, std::min(x0 + kTilePx, kSpanPx) - 1);
    return row;
  }
  // Largest |kernel - exact| in LSB over the row.
  double worst_lsb(const Row& row) const {
    double worst = 0;
    for (int x = 0; x < kSpanPx; ++x) {
      const double want = quantize(light.exact(normal(x)), false);
      for (int ch = 0; ch < 3; ++ch) worst = std::max(worst, std::fabs(row.channel(x, ch) - want));
    }
    return worst;
  }
};

double phong_bound(const Lighting& light) { return float_kernel_lsb(light.scene); }

std::string span_case(double n, double phi) {
  std::ostringstream s;
  s << "65536-px span, n " << n << ", " << phi << " rad/px";
  return s.str();
}

// Checks a kernel's worst error against its bound and records it for the table.
void expect_within(const std::string& case_name, const std::string& kernel, double worst, double bound) {
  EXPECT_LE(worst, bound) << case_name << ", " << kernel;
  record({case_name, kernel, {bound, Status::Holds}, worst, 0});
}

class StabilityKernels : public ::testing::Test {
 protected:
};

TEST_F(StabilityKernels, PhongOver65536PxWithTinyPerPixelAngles) {
  for (double n : {37.5, 1000.0, 1e4})
    for (double phi : {2e-4, 1e-5, 1e-7}) {
      const LongSpan s(n, phi);
      // The float colour before quantisation is finite everywhere.
      for (int x = 0; x < kSpanPx; x += 97) {
        const PhongColor c = phong_color_scalar(s.in, pixel_offsets(s.in.bary, x, 0));
        ASSERT_TRUE(std::isfinite(c.c[0]) && std::isfinite(c.c[1]) && std::isfinite(c.c[2])) << x;
      }
      const double bound = phong_bound(s.light);
      const Row lanes = s.shade([&](RowTarget r, int x0, int x1) { phong_span(SimdTarget{}, s.in, 0, x0, x1, r); });
      const Row scalar = s.shade([&](RowTarget r, int x0, int x1) { phong_span_scalar(s.in, 0, x0, x1, r); });
      expect_within(span_case(n, phi), "phong_span, SIMD and scalar",
                    std::max(s.worst_lsb(lanes), s.worst_lsb(scalar)), bound);
    }
}

TEST_F(StabilityKernels, NormalsPathsOver65536PxWithTinyPerPixelAngles) {
  const float tol = hybrid_tolerance(1.0);
  for (double n : {37.5, 1000.0})
    for (double phi : {2e-4, 1e-5, 1e-7})
      for (PhongNormals mode : {PhongNormals::Adaptive, PhongNormals::EqualAngle}) {
        const LongSpan s(n, phi);
        const HybridRun run{1, 0, kSpanPx - 1};
        // With w constant along the row the block's normals are exactly a slerp (equal angle)
        // up to the turn rate's change over 16 px (below 1e-9 rad here), and the adaptive
        // weights are within tol: both hold phong's bound plus the budget's half step.
        const double bound = phong_bound(s.light);
        const Row lanes =
            s.shade([&](RowTarget r, int x0, int x1) { normals_span(SimdTarget{}, s.in, mode, tol, run, 0, x0, x1, r); });
        const Row scalar =
            s.shade([&](RowTarget r, int x0, int x1) { normals_span_scalar(s.in, mode, tol, run, 0, x0, x1, r); });
        const std::string kernel = mode == PhongNormals::Adaptive ? "adaptive" : "equal-angle";
        expect_within(span_case(n, phi), "normals_span " + kernel + ", SIMD and scalar",
                      std::max(s.worst_lsb(lanes), s.worst_lsb(scalar)), bound);
      }
}

// Each segment length against its own bound: a segment of L px turning the normal by L phi
// errs by (L phi)^2 / 8 times the colour's curvature in the angle (shade/hybrid.h), which for
// c_max = 1 is W_d + W_s n (n + 1).
TEST_F(StabilityKernels, HybridSegmentsOver65536PxWithinTheirDerivedBound) {
  for (double n : {37.5, 1000.0})
    for (double phi : {2e-4, 1e-5})
      for (int step : {1, 2, 4, 8, 16}) {
        const LongSpan s(n, phi);
        const Weights w = weights(s.light.scene, s.light.scene.materials[0]);
        const double angle = step * phi;
        const double interpolation = angle * angle / 8 * (w.diffuse + w.specular * n * (n + 1));
        const double bound = phong_bound(s.light) + std::floor(255 * interpolation);
        const HybridRun run{step, 0, kSpanPx - 1};
        const Row lanes = s.shade([&](RowTarget r, int x0, int x1) { hybrid_span(SimdTarget{}, s.in, run, 0, x0, x1, r); });
        expect_within(span_case(n, phi), "hybrid_span, step " + std::to_string(step), s.worst_lsb(lanes), bound);
      }
}

// Colour planes over 65536 px: re-seeded every 16 px, so no forward-differencing drift.
TEST_F(StabilityKernels, GouraudOver65536PxDoesNotDrift) {
  const double c0 = 0.2, c1 = 0.9;
  GouraudSpanInput in{Barycentrics{0, 0, {}, {}, {}}, constant_plane(0.5f), {}, constant_plane(1.0f), {}, {}};
  for (int c = 0; c < 3; ++c) {
    in.level_over_w[c] = Plane{float(255 * c0), float(255 * (c1 - c0) / kSpanPx), 0, 0, 0};
    in.level_lo[c] = float(255 * c0);
    in.level_hi[c] = float(255 * c1);
  }
  double worst = 0;
  for (bool lanes : {true, false}) {
    Row row(kSpanPx);
    for (int x0 = 0; x0 < kSpanPx; x0 += kTilePx) {
      const int x1 = std::min(x0 + kTilePx, kSpanPx) - 1;
      if (lanes)
        gouraud_span(SimdTarget{}, in, false, 0, x0, x1, row.target());
      else
        gouraud_span_scalar(in, false, 0, x0, x1, row.target());
    }
    for (int x = 0; x < kSpanPx; ++x)
      worst = std::max(worst, std::fabs(row.channel(x, 0) - double(quantize(c0 + (c1 - c0) * x / kSpanPx, false))));
  }
  expect_within("65536-px span, colour 0.2 to 0.9", "gouraud_span, SIMD and scalar", worst, 1.0);
}

// ---- an exact 0.2 px^2 sliver ---------------------------------------------------------------

// Long edge (512000, 7) and third vertex (69398, 1) in 1/256 px: doubled area 26214 = 0.2 px^2
// x 2 x 65536, 2000 px long. Vertex normals 0.6 rad apart: across the sliver's 2e-4 px width
// the planes change by thousands per pixel, and their float values cancel heavily.
struct Sliver {
  SetupTriangle t{};
  TriangleEdges edges;
  Barycentrics bary;
  glm::dvec3 n[3];
  Sliver(const Lighting& light, int32_t ax, int32_t ay) {
    const int32_t dx[3] = {0, 512000, 69398}, dy[3] = {0, 7, 1};
    for (int i = 0; i < 3; ++i) {
      t.x_fx[i] = ax + dx[i];
      t.y_fx[i] = ay + dy[i];
      t.depth[i] = 0.5f;
      t.inv_w[i] = 1.0f;
    }
    n[0] = light.h();
    n[1] = glm::normalize(light.h() + glm::dvec3(0.6, 0, 0));
    n[2] = glm::normalize(light.h() + glm::dvec3(0, 0.6, 0));
    if (doubled_area(t) < 0) {
      std::swap(t.x_fx[1], t.x_fx[2]);
      std::swap(t.y_fx[1], t.y_fx[2]);
      std::swap(n[1], n[2]);
    }
    edges = triangle_edges(t);
    bary = barycentrics(t, edges);
  }
  // The reference's normal at a pixel: exact barycentrics from the integer edge functions.
  glm::dvec3 normal(int px, int py) const {
    const double inv_area = 1.0 / (4.0 * double(doubled_area(t)));
    glm::dvec3 q(0.0);
    for (int i = 0; i < 3; ++i)
      q += n[i] * (double(edges.e[i].at(pixel_centre_fx(px), pixel_centre_fx(py))) * inv_area);
    return glm::normalize(q);
  }
};

TEST_F(StabilityKernels, SliverOfPointTwoPxSquaredAnd2000PxLong) {
  const Lighting light(37.5);
  constexpr int kSize = 256;
  int covered = 0;
  double worst = 0;
  // Rows of the sliver's band at several sub-pixel heights, so that pixel centres fall in it.
  for (int32_t sub = -8; sub <= 8; ++sub) {
    const Sliver s(light, -200 * 256, 100 * 256 + 128 + sub);
    ASSERT_EQ(doubled_area(s.t), 26214);
    PhongSpanInput in;
    in.bary = s.bary;
    in.depth = make_plane(s.bary, 0.5, 0.5, 0.5);
    for (int c = 0; c < 3; ++c) in.n[c] = make_plane(s.bary, s.n[0][c], s.n[1][c], s.n[2][c]);
    in.material = &light.m;
    in.shade = &light.k;
    std::vector<Row> rows(kSize, Row(kSize));
    for_each_span(s.edges, PixelRect{0, 0, kSize - 1, kSize - 1}, [&](int py, int x0, int x1) {
      phong_span(SimdTarget{}, in, py, x0, x1, rows[py].target());
      for (int x = x0; x <= x1; ++x) {
        ++covered;
        const PhongColor c = phong_color_scalar(in, pixel_offsets(in.bary, x, py));
        ASSERT_TRUE(std::isfinite(c.c[0])) << "pixel (" << x << ", " << py << ")";
        const double want = quantize(light.exact(s.normal(x, py)), false);
        worst = std::max(worst, std::fabs(rows[py].channel(x, 0) - want));
      }
    });
  }
  EXPECT_GT(covered, 10) << "the slivers must cover pixel centres to test anything";
  // The sliver's float planes (docs/STABILITY.md, "Cases").
  expect_within("0.2 px^2 sliver, 2000 px long (" + std::to_string(covered) + " px covered)", "phong_span", worst,
                phong_bound(light));
}

// ---- transcendental helpers -------------------------------------------------------------------

// exp2(n log2 c) against pow in double for c in (0, 1] and every exponent: relative error
// within |y| (2.7e-8 + 2u) + 2.6e-9 + 2u (y = n log2 c, docs/STABILITY.md "B1"), which stays
// below 4e-6 wherever c^n is above 2^-126.
TEST(StabilityFastMath, PowerThroughExp2Log2IsRelativelyAccurate) {
  for (double n : {1.0, 2.0, 37.5, 1000.0, 1e4, 1e6}) {
    double worst = 0;
    for (int i = 0; i <= 200000; ++i) {
      const float c = i < 100000 ? float(i) / 100000.0f : 1.0f - float(i - 100000) * 6e-8f;
      if (!(c > 0)) continue;
      const double y = double(float(n)) * fast_math::log2(c);
      if (y < fast_math::kExp2Min) continue;
      const double got = fast_math::exp2(float(n) * fast_math::log2(c));
      const double want = std::pow(double(c), n);
      const double allowed = std::fabs(y) * (2.7e-8 + 2 * kUnit) + 2.6e-9 + 2 * kUnit;
      ASSERT_TRUE(std::isfinite(got)) << "n " << n << " c " << c;
      worst = std::max(worst, std::fabs(got / want - 1) / allowed);
    }
    EXPECT_LE(worst, 1.0) << "n " << n << ": worst relative error over the allowed one";
  }
}

// 1/sqrt over its domain, the normal floats: within 3 units of rounding. (Below it, the
// kernels treat such vectors as zero, next test.)
TEST(StabilityFastMath, InverseSquareRootOverTheNormalFloats) {
  ASSERT_EQ(fast_math::kMinInvSqrtInput, std::numeric_limits<float>::min());
  double worst = 0;
  for (float x = fast_math::kMinInvSqrtInput; x < 1e38f; x *= 1.0137f) {
    const double got = fast_math::inv_sqrt(x), want = 1.0 / std::sqrt(double(x));
    worst = std::max(worst, std::fabs(got / want - 1));
  }
  EXPECT_LE(worst, 3 * kUnit);
}

// n/w shorter than 1.1e-19 (its squared length subnormal): near the point where antiparallel
// vertex normals cancel, or far away. It must shade as a zero normal (ambient only), not as
// the NaN or infinity 1/sqrt of a subnormal gives.
TEST_F(StabilityKernels, NormalsTooShortToNormaliseShadeAsZero) {
  const Lighting light(37.5);
  for (const Isa isa_id : available_isas()) {
    const std::string isa(option_name(isa_id));
    const SimdTarget simd = simd_target(isa_id);
    for (float tiny : {1e-20f, 3e-23f, 1e-30f, 0.0f}) {
      PhongSpanInput in;
      in.bary = Barycentrics{0, 0, {}, {}, {}};
      in.depth = constant_plane(0.5f);
      in.n[0] = constant_plane(tiny), in.n[1] = constant_plane(0.0f), in.n[2] = constant_plane(tiny);
      in.material = &light.m;
      in.shade = &light.k;
      const PhongColor c = phong_color_scalar(in, pixel_offsets(in.bary, 3, 0));
      EXPECT_EQ(c.c[0], kAmbient) << tiny;
      const int ambient = quantize(double(kAmbient), false);
      Row row(64);
      phong_span(simd, in, 0, 0, 40, row.target());
      EXPECT_EQ(row.channel(7, 0), ambient) << isa << " " << tiny;
      Row scalar(64);
      phong_span_scalar(in, 0, 0, 40, scalar.target());
      EXPECT_EQ(scalar.channel(7, 0), ambient) << "scalar " << tiny;
      for (PhongNormals mode : {PhongNormals::Adaptive, PhongNormals::EqualAngle}) {
        Row blocks(64);
        normals_span(simd, in, mode, hybrid_tolerance(1.0), HybridRun{1, 0, 40}, 0, 0, 40, blocks.target());
        EXPECT_EQ(blocks.channel(7, 0), ambient) << isa << " normals " << int(mode) << " " << tiny;
      }
    }
  }
}

// ---- hybrid's step decision on stiff normals -------------------------------------------------

TEST(StabilityHybridStep, EqualNearlyEqualAndAntiparallelNormals) {
  const Lighting light(1000);
  auto step_for = [&](glm::vec3 n0, glm::vec3 n1, glm::vec3 n2) {
    SegmentStepInput in{{n0, n1, n2}, {1, 1, 1}, {}};
    SetupTriangle t{};
    const int32_t x[3] = {0, 64 * 256, 0}, y[3] = {0, 0, 64 * 256};
    for (int i = 0; i < 3; ++i) t.x_fx[i] = x[i], t.y_fx[i] = y[i];
    if (doubled_area(t) < 0) std::swap(t.y_fx[1], t.y_fx[2]), std::swap(in.n[1], in.n[2]);
    const Barycentrics b = barycentrics(t, triangle_edges(t));
    for (int v = 0; v < 3; ++v) in.n_over_w_dx += dvec3(in.n[v]) * b.d_dx[v];
    in.material = &light.m;
    in.shade = &light.k;
    return hybrid_triangle_step(in, hybrid_tolerance(1.0)).step_px;
  };
  const glm::vec3 h(light.h());
  const glm::vec3 e = glm::normalize(glm::cross(h, glm::vec3(0, 1, 0)));
  EXPECT_EQ(step_for(h, h, h), 16) << "equal normals: nothing to interpolate wrongly";
  const glm::vec3 tilt = glm::normalize(h + 1e-6f * e);
  const int nearly = step_for(h, tilt, h);
  EXPECT_TRUE(nearly >= 1 && nearly <= 16);
  // N, -N, N: the normal flips across a line the segments would smear over 16 px.
  EXPECT_EQ(step_for(h, -h, h), 1) << "antiparallel normals: per-pixel Phong";
  EXPECT_EQ(step_for(h, -h, glm::normalize(h + glm::vec3(0, 0.7f, 0))), 1);
}

}  // namespace
}  // namespace fastshade::stability
