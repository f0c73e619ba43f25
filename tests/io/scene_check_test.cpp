// check_scene(): a scene built in code is held to what a scene file may say, and each problem
// names its part.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include "fastshade/error.h"
#include "fastshade/primitives.h"
#include "fastshade/scene.h"

namespace fastshade {
namespace {

Scene good_scene() {
  Scene scene;
  scene.width = 64, scene.height = 48;
  scene.materials = {Material{.name = "m"}};
  scene.objects = {Object{std::make_shared<const Mesh>(make_cube(1.0f, 1)), 0, glm::mat4(1.0f)}};
  scene.lights = {Light{}};
  scene.camera = look_at_camera({0, 0, 5}, {0, 0, 0});
  return scene;
}

// The message check_scene throws for `scene`, "" (and a failure) if it throws none.
std::string problem_of(const Scene& scene) {
  try {
    check_scene(scene);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted";
  return "";
}

TEST(CheckScene, AGoodScenePasses) { EXPECT_NO_THROW(check_scene(good_scene())); }

TEST(CheckScene, EachProblemNamesItsPart) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  Scene s = good_scene();
  s.width = 0;
  EXPECT_EQ(problem_of(s).rfind("image.width:", 0), 0u);
  s = good_scene();
  s.background = {0.5f, 2.0f, 0.0f};
  EXPECT_EQ(problem_of(s).rfind("image.background:", 0), 0u);
  s = good_scene();
  s.materials[0].shininess = 0.5;
  EXPECT_EQ(problem_of(s).rfind("materials[0].shininess:", 0), 0u);
  s = good_scene();
  s.lights[0].direction = {0, 0, 0};
  EXPECT_EQ(problem_of(s).rfind("lights[0].direction:", 0), 0u);
  s = good_scene();
  s.objects[0].material = 3;
  EXPECT_EQ(problem_of(s).rfind("objects[0].material:", 0), 0u);
  s = good_scene();
  s.objects[0].model[3][0] = nan;
  EXPECT_EQ(problem_of(s).rfind("objects[0].transform:", 0), 0u);
  s = good_scene();
  Mesh bad = make_cube(1.0f, 1);
  bad.positions[5].y = nan;
  s.objects[0].mesh = std::make_shared<const Mesh>(bad);
  EXPECT_EQ(problem_of(s), "objects[0].mesh: vertex 5 is not finite");
  bad = make_cube(1.0f, 1);
  bad.triangles[2][1] = 1000;
  s.objects[0].mesh = std::make_shared<const Mesh>(bad);
  EXPECT_NE(problem_of(s).find("triangle 2 names vertex 1000"), std::string::npos);
  s = good_scene();
  s.camera.target = s.camera.eye;
  EXPECT_EQ(problem_of(s).rfind("camera.target:", 0), 0u);
}

TEST(CheckScene, CheckMeshNamesTheMesh) {
  Mesh mesh = make_cube(1.0f, 1);
  mesh.source = "arrays";
  mesh.normals.pop_back();
  try {
    check_mesh(mesh);
    ADD_FAILURE() << "a normal short was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("arrays: ", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace fastshade
