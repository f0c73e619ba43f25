// The front end's segment lengths: decided once per triangle from the planes the hybrid
// kernel interpolates, left at per-pixel Phong where the kernel draws per pixel, and used by
// the kernel in every tile.
#include "front/segment_steps.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <glm/geometric.hpp>

#include "classify/segment_step.h"
#include "fastshade/render.h"
#include "fastshade/scene.h"
#include "frame/edge_function.h"
#include "light/brdf.h"
#include "raster/planes.h"

namespace fastshade {
namespace {

// One light along +z, so H = +z for the infinite viewer; n = 100, ks = 0.5.
struct StepFrame {
  Frame frame;
  SegmentSteps which;
  explicit StepFrame(SegmentSteps which_triangles) : which(which_triangles) {
    frame.shade.lights.push_back({glm::vec3(0, 0, 1), glm::vec3(0, 0, 1), glm::vec3(1.0f)});
    const double n = 100;
    frame.shade.materials.push_back({glm::vec3(0.6f), glm::vec3(0.5f), float(n), n, make_brdf(BrdfChoice{}, n)});
    frame.shade.hybrid_tolerance = hybrid_tolerance(1.0);
    frame.chunks.resize(1);
  }
  // A right triangle `side_px` pixels on a side at (8, 8), with these vertex normals and 1/w.
  void add(float side_px, glm::vec3 n0, glm::vec3 n1, glm::vec3 n2, ShadePath path = ShadePath::Unclassified) {
    const uint32_t first = static_cast<uint32_t>(frame.attrs.n_view.size());
    for (const glm::vec3& n : {n0, n1, n2}) frame.attrs.n_view.push_back(glm::normalize(n));
    SetupTriangle t{};
    const int32_t one = limits::kSubpixelOne, side = static_cast<int32_t>(side_px * one);
    const int32_t x[3] = {8 * one, 8 * one + side, 8 * one}, y[3] = {8 * one, 8 * one, 8 * one + side};
    for (int i = 0; i < 3; ++i) {
      t.x_fx[i] = x[i], t.y_fx[i] = y[i];
      t.depth[i] = 0.5f;
      t.inv_w[i] = 1.0f / (1.0f + 0.25f * i);
      t.attr[i] = first + i;
    }
    if (doubled_area(t) < 0) std::swap(t.y_fx[1], t.y_fx[2]), std::swap(t.attr[1], t.attr[2]), std::swap(t.x_fx[1], t.x_fx[2]);
    ASSERT_GT(doubled_area(t), 0);
    t.px_min[0] = t.px_min[1] = 8;
    t.px_max[0] = t.px_max[1] = static_cast<int16_t>(8 + side_px - 1);
    t.flags = static_cast<uint16_t>(static_cast<int>(path) << kShadePathShift);
    if (draws_segments(t, which)) frame.chunks[0].segment_pending.push_back(static_cast<uint32_t>(frame.chunks[0].triangles.size()));
    frame.chunks[0].triangles.push_back(t);
  }
  void decide() { decide_segment_steps(frame, 0, 0, static_cast<uint32_t>(frame.chunks[0].segment_pending.size())); }
  int step(uint32_t i) const { return Frame::segment_step_px(frame.chunks[0].triangles[i]); }
  int split_light(uint32_t i) const { return Frame::split_light(frame.chunks[0].triangles[i]); }
  // The plan from the kernel's own float planes of n / w (raster/planes.h make_plane).
  SegmentPlan plan_from_planes(uint32_t i) const {
    const SetupTriangle& t = frame.chunks[0].triangles[i];
    const Barycentrics b = barycentrics(t, triangle_edges(t));
    SegmentStepInput in;
    for (int v = 0; v < 3; ++v) in.n[v] = frame.attrs.n_view[t.attr[v]], in.inv_w[v] = t.inv_w[v];
    for (int c = 0; c < 3; ++c)
      in.n_over_w_dx[c] = make_plane(b, double(in.n[0][c]) * in.inv_w[0], double(in.n[1][c]) * in.inv_w[1],
                                     double(in.n[2][c]) * in.inv_w[2]).gx;
    in.material = &frame.shade.materials[0];
    in.shade = &frame.shade;
    return hybrid_triangle_step(in, frame.shade.hybrid_tolerance);
  }
};

TEST(SegmentSteps, MatchTheKernelsPlanesAndFollowCurvature) {
  StepFrame f(SegmentSteps::All);
  f.add(64, {0.3f, 0, 1}, {0.3f, 0, 1}, {0.3f, 0, 1});              // flat: longest segments
  f.add(64, {0.4f, 0, 1}, {-0.4f, 0.3f, 1}, {0, -0.4f, 1});          // curved around H: per pixel
  f.add(64, {1, 0, 0.2f}, {1, 0.003f, 0.202f}, {1, -0.003f, 0.201f});  // gentle, far from H
  f.add(8, {1, 0, 0.2f}, {1, 0.003f, 0.202f}, {1, -0.003f, 0.201f});   // too narrow for segments
  f.add(64, {1, 0, 0.1f}, {1, 0.03f, -0.1f}, {1, -0.03f, 0.05f});  // gentle, across the terminator
  EXPECT_EQ(f.frame.chunks[0].segment_pending.size(), 4u) << "the narrow one is not listed";
  f.decide();
  EXPECT_EQ(f.step(0), 16);
  EXPECT_EQ(f.step(1), 1);
  EXPECT_GT(f.step(2), 1);
  EXPECT_EQ(f.step(3), 1) << "a triangle under kHybridMinWidthPx is drawn per pixel: no step";
  EXPECT_EQ(f.split_light(4), 0) << "the light whose terminator crosses is split";
  for (uint32_t i : {0u, 1u, 2u, 4u}) {
    const SegmentPlan plan = f.plan_from_planes(i);
    EXPECT_EQ(f.step(i), plan.step_px) << "triangle " << i;
    EXPECT_EQ(f.split_light(i), plan.split_light) << "triangle " << i;
  }
  EXPECT_EQ(f.split_light(3), -1);
}

TEST(SegmentSteps, OnlyTheSpecularPathWhenAsked) {
  StepFrame f(SegmentSteps::SpecularPath);
  f.add(64, {0.3f, 0, 1}, {0.3f, 0, 1}, {0.3f, 0, 1}, ShadePath::GouraudDiffuse);
  f.add(64, {0.3f, 0, 1}, {0.3f, 0, 1}, {0.3f, 0, 1}, ShadePath::Specular);
  const uint16_t path_bits = f.frame.chunks[0].triangles[1].flags & kShadePathMask;
  f.decide();
  EXPECT_EQ(f.step(0), 1);
  EXPECT_EQ(f.step(1), 16);
  EXPECT_EQ(f.frame.chunks[0].triangles[1].flags & kShadePathMask, path_bits) << "the path bits stay";
  EXPECT_FALSE(draws_segments(f.frame.chunks[0].triangles[1], SegmentSteps::None));
}

// The kernel reads the front end's steps: with segments, hybrid interpolates between Phong
// ends, so its image differs from phong's somewhere (and stays within the budget; a triangle
// left at step 1 draws exactly as phong).
TEST(SegmentSteps, ReachTheHybridKernel) {
  // torus_local: a local viewer, whose steps also need the positions' gradient.
  for (const char* file : {"default.json", "torus_local.json"}) {
    const Scene scene = load_scene(std::filesystem::path(FASTSHADE_SOURCE_DIR) / "scenes" / file);
    RenderOptions phong, hybrid;
    phong.method = ShadingMethod::Phong;
    hybrid.method = ShadingMethod::Hybrid;
    const Image p = render(scene, phong), h = render(scene, hybrid);
    ASSERT_EQ(p.rgb.size(), h.rgb.size());
    int differ = 0, worst = 0;
    for (std::size_t i = 0; i < p.rgb.size(); ++i) {
      const int d = std::abs(int(p.rgb[i]) - int(h.rgb[i]));
      differ += d > 0;
      worst = std::max(worst, d);
    }
    EXPECT_GT(differ, 0) << file << ": hybrid drew every pixel as phong: the front end's steps did not arrive";
    EXPECT_LE(worst, 3) << file;
  }
}

// The stats count the plans: every triangle listed for segments once, by its length; none
// where the frame draws no segments.
TEST(SegmentSteps, TalliedInTheStats) {
  const Scene scene = load_scene(std::filesystem::path(FASTSHADE_SOURCE_DIR) / "scenes" / "default.json");
  auto stats_for = [&](ShadingMethod method) {
    RenderOptions o;
    o.method = method;
    Renderer r(scene, o);
    r.render_frame();
    return r.last_stats();
  };
  const RenderStats hybrid = stats_for(ShadingMethod::Hybrid), phong = stats_for(ShadingMethod::Phong);
  ASSERT_EQ(hybrid.segment_triangles.size(), 5u) << "1, 2, 4, 8 and 16 px";
  long long listed = 0, segmented = 0;
  for (std::size_t m = 0; m < hybrid.segment_triangles.size(); ++m) {
    listed += hybrid.segment_triangles[m];
    if (m > 0) segmented += hybrid.segment_triangles[m];
  }
  EXPECT_GT(segmented, 0);
  EXPECT_LE(listed, hybrid.triangles_drawn);
  EXPECT_LE(hybrid.segment_split, segmented) << "only triangles with segments split a light";
  EXPECT_GT(hybrid.segment_no_specular, 0) << "the default scene's far sides are far from every highlight";
  EXPECT_LE(hybrid.segment_no_specular, segmented) << "only triangles with segments light their ends";
  EXPECT_TRUE(std::any_of(hybrid.left_out.begin(), hybrid.left_out.end(), [&](const std::string& line) {
    return line.find(std::to_string(hybrid.segment_no_specular) + " hybrid triangles: segment ends lit without") == 0;
  })) << "--explain says what was left out";
  EXPECT_TRUE(phong.segment_triangles.empty());
  EXPECT_EQ(phong.segment_split, 0);
  EXPECT_EQ(phong.segment_no_specular, 0);
  // auto with no triangle on its specular path (the threshold above any highlight, every block
  // classified) reports no plan, rather than one of zeros.
  RenderOptions o;
  o.method = ShadingMethod::Auto;
  o.spec_threshold = 1.0;
  o.classify_min_px = 0.0;
  Renderer dull(scene, o);
  dull.render_frame();
  EXPECT_TRUE(dull.last_stats().segment_triangles.empty());
}

}  // namespace
}  // namespace fastshade
