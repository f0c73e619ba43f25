// `auto`'s cost model (exec/auto_cost.h): the triangle-size estimate on a grid of known size,
// the per-ISA thresholds, and what a renderer draws on either side of them.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include <glm/gtc/matrix_transform.hpp>

#include "core/simd_target.h"
#include "exec/auto_cost.h"
#include "exec/exec_limits.h"
#include "fastshade/primitives.h"
#include "fastshade/render.h"
#include "front/scene_geometry.h"

namespace fastshade {
namespace {

// A sphere of `triangles` = 20 * 4^subdivisions faces, lit, filling about half of a side x side frame.
Scene sphere_scene(int subdivisions, int side) {
  Scene s;
  s.width = s.height = side;
  s.camera = look_at_camera({0, 0, 3}, {0, 0, 0});
  s.lights.push_back(Light{glm::normalize(glm::vec3(1, 1, 1)), glm::vec3(1), LightSpace::View});
  s.materials.push_back(Material{});
  s.objects.push_back(Object{std::make_shared<Mesh>(make_icosphere(1.0f, subdivisions)), 0, glm::mat4(1.0f)});
  return s;
}

// The XZ plane of side 2 in `divisions`^2 quads, seen straight on from 5 units: every
// triangle at one depth, so the projection scales every area alike.
Scene plane_scene(int divisions, int side, glm::vec3 offset = {0, 0, 0}) {
  Scene s = sphere_scene(0, side);
  s.camera = look_at_camera({0, 5, 0}, {0, 0, 0}, {0, 0, -1});
  s.objects[0].mesh = std::make_shared<Mesh>(make_plane(2.0f, divisions));
  s.objects[0].model = glm::translate(glm::mat4(1.0f), offset);
  return s;
}

double estimate(const Scene& s) {
  return sampled_triangle_px(flatten_scene(s), view_transform(s), make_viewport(s.width, s.height));
}

TEST(SampledTrianglePx, FlatGridHasItsExactArea) {
  for (const int divisions : {8, 200}) {  // 128 triangles, all sampled; 80,000, a sample of them
    const Scene s = plane_scene(divisions, 400);
    // 2 units at distance 5 with a 45-degree field: 2 / (2 * 5 * tan(22.5 deg)) of 400 px.
    const double side_px = 2.0 / (2.0 * 5.0 * std::tan(glm::radians(22.5))) * 400.0;
    const double triangle_px = 0.5 * (side_px / divisions) * (side_px / divisions);
    EXPECT_NEAR(estimate(s), triangle_px, 1e-4 * triangle_px) << divisions;
  }
}

TEST(SampledTrianglePx, NothingOnScreenOrBehindIsZero) {
  EXPECT_EQ(estimate(plane_scene(8, 400, {100, 0, 0})), 0.0);  // far to the side
  EXPECT_EQ(estimate(plane_scene(8, 400, {0, 10, 0})), 0.0);   // behind the eye
}

TEST(AutoCost, ThresholdsGrowWithTheVector) {
  // The wider the vector, the cheaper per-pixel Phong, the larger a triangle must be for
  // classifying to pay.
  double previous = 0;
  for (const auto& [isa, min_px] : limits::kAutoClassifyMinPx) {
    EXPECT_GE(min_px, previous) << option_name(isa);
    EXPECT_TRUE(auto_classifies(isa, min_px)) << option_name(isa);
    if (min_px > 0) EXPECT_FALSE(auto_classifies(isa, std::nextafter(min_px, 0.0))) << option_name(isa);
    previous = min_px;
  }
}

// What `auto` draws and whether it is phong's image, bit for bit.
void expect_drawn_as(const Scene& scene, RenderOptions options, const std::string& expected) {
  Renderer renderer(scene, options);
  const Image image = renderer.render_frame();
  EXPECT_EQ(renderer.last_stats().method, "auto");
  EXPECT_EQ(renderer.last_stats().drawn_as, expected) << option_name(options.isa);
  options.method = ShadingMethod::Phong;
  if (expected == "phong") EXPECT_EQ(image.rgb, render(scene, options).rgb) << option_name(options.isa);
}

TEST(AutoCost, EachIsaDrawsBySizeAndTheClassifiersOptionsKeepIt) {
  const Scene dense = sphere_scene(6, 256), coarse = sphere_scene(1, 1024);  // about 0.2 and 1,500 px a triangle
  const double dense_px = estimate(dense), coarse_px = estimate(coarse);
  for (const Isa isa : available_isas()) {
    RenderOptions o;
    o.isa = isa;
    expect_drawn_as(dense, o, auto_classifies(isa, dense_px) ? "auto" : "phong");
    expect_drawn_as(coarse, o, auto_classifies(isa, coarse_px) ? "auto" : "phong");
    EXPECT_TRUE(auto_classifies(isa, coarse_px)) << option_name(isa);  // large triangles always pay
    RenderOptions asked = o;  // --classifier bound: classified whatever the cost
    asked.classifier = ClassifierRule::Bound;
    expect_drawn_as(dense, asked, "auto");
  }
  // On a SIMD CPU the dense frame is below the best ISA's threshold.
  const Isa best = available_isas().back();
  if (best != Isa::Scalar) EXPECT_FALSE(auto_classifies(best, dense_px));
}

}  // namespace
}  // namespace fastshade
