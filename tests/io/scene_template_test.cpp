// Batch templates: a mesh put in the template gives the scene the parser makes of the
// equivalent scene file; what a template may not hold is refused; turned cameras.
#include "io/scene_template.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "fastshade/error.h"
#include "fastshade/primitives.h"
#include "io/io_test_util.h"

namespace fastshade {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr const char* kTemplate = R"({
  "image": {"width": 33, "height": 17},
  "camera": {"fit": true, "distance": 4, "fovy_deg": 30},
  "lights": [{"direction": [0, 1, 1], "space": "world"}],
  "materials": {"a": {"diffuse": 0.1}, "b": {"shininess": 7}},
  "objects": [{"mesh": "not/read.ply", "material": "b", "normals": "recompute", "weld": true,
               "transform": {"rotate_deg": [0, 30, 0], "scale": 2}},
              {"primitive": "cube", "material": "a"}]
})";

std::string error_of(const std::string& text) {
  try {
    SceneTemplate(text, "t.json");
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted: " << text;
  return "";
}

TEST(SceneTemplate, MeshSceneEqualsTheParsedEquivalentScene) {
  const testing::ScratchDir scratch;
  const Mesh torus = make_torus(1.0f, 0.25f, 12, 8);
  std::string obj;
  for (const glm::vec3& p : torus.positions)
    obj += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
  for (const auto& t : torus.triangles)
    obj += "f " + std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " + std::to_string(t[2] + 1) + "\n";
  const fs::path mesh_path = scratch.write("torus.obj", obj);

  SceneTemplate tmpl(kTemplate, "t.json");
  EXPECT_EQ(tmpl.mesh_options().normals, NormalsMode::Recompute);
  EXPECT_TRUE(tmpl.mesh_options().weld);
  const Scene got = tmpl.scene_for(std::make_shared<const Mesh>(load_mesh(mesh_path, tmpl.mesh_options())));

  json equivalent = json::parse(kTemplate);
  equivalent["objects"] = json::array({equivalent["objects"][0]});
  equivalent["objects"][0]["mesh"] = mesh_path.string();
  const Scene want = parse_scene(equivalent.dump(), "e.json", ".");

  EXPECT_EQ(got.width, 33);
  EXPECT_EQ(got.height, 17);
  ASSERT_EQ(got.objects.size(), 1u);
  EXPECT_EQ(got.objects[0].material, 1);  // "b"
  EXPECT_EQ(got.objects[0].model, want.objects[0].model);
  EXPECT_EQ(got.objects[0].mesh->positions, want.objects[0].mesh->positions);
  EXPECT_EQ(got.objects[0].mesh->normals, want.objects[0].mesh->normals);
  for (auto [a, b] : {std::pair{got.camera.eye, want.camera.eye}, {got.camera.target, want.camera.target},
                      {got.camera.up, want.camera.up}})
    EXPECT_EQ(a, b);
  EXPECT_EQ(got.camera.fovy_deg, 30.0f);
  EXPECT_EQ(got.camera.near, want.camera.near);
  EXPECT_EQ(got.camera.far, want.camera.far);
  ASSERT_EQ(got.lights.size(), 1u);
  EXPECT_EQ(got.lights[0].space, LightSpace::World);
  EXPECT_EQ(got.materials.size(), 2u);

  // --size reaches the scene and the canonical text (so resume fingerprints change).
  const std::string before = tmpl.canonical();
  tmpl.set_image_size(8, 9);
  EXPECT_EQ(tmpl.scene_for(got.objects[0].mesh).width, 8);
  EXPECT_NE(tmpl.canonical(), before);
}

TEST(SceneTemplate, RefusesWhatCannotFrameEveryMesh) {
  EXPECT_NE(error_of(R"({"camera": {"eye": [0, 0, 5], "target": [0, 0, 0]}})").find("t.json: camera:"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"camera": {"fit": false, "eye": [0, 0, 5], "target": [0, 0, 0]}})").find("fit camera"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"objects": [{"mesh": "a.ply", "material": "gold"}]})").find("objects[0].material"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"objects": [{"mesh": "a.ply", "normals": "magic"}]})").find("objects[0].normals"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"image": {"width": 0}})").find("image.width"), std::string::npos);
  EXPECT_NE(error_of(R"([1, 2])").find("top level"), std::string::npos);
  EXPECT_NO_THROW(SceneTemplate(R"({})", "t.json"));  // objects may be left out
}

TEST(SceneTemplate, FlatMeshCannotBeFramed) {
  Mesh point;
  point.positions = {glm::vec3(1, 2, 3), glm::vec3(1, 2, 3), glm::vec3(1, 2, 3)};
  point.triangles = {{0, 1, 2}};
  point.source = "point.obj";
  try {
    SceneTemplate("{}", "t.json").scene_for(std::make_shared<const Mesh>(point));
    ADD_FAILURE() << "framed a point";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("point.obj: ", 0), 0u) << e.what();
  }
}

TEST(SceneTemplate, OrbitTurnsTheEyeAboutTheVerticalThroughTheTarget) {
  Camera fit;
  fit.target = glm::vec3(1, 2, 3);
  fit.eye = glm::vec3(1, 2, 8);
  const Camera same = orbit_camera(fit, 0.0);
  EXPECT_EQ(same.eye, fit.eye);
  const Camera quarter = orbit_camera(fit, 90.0);  // from +X
  EXPECT_NEAR(quarter.eye.x, 6.0f, 1e-5f);
  EXPECT_EQ(quarter.eye.y, 2.0f);
  EXPECT_NEAR(quarter.eye.z, 3.0f, 1e-5f);
  EXPECT_EQ(quarter.target, fit.target);
  EXPECT_EQ(quarter.near, fit.near);
  for (double deg = 0; deg < 360; deg += 7.5)
    EXPECT_NEAR(glm::distance(orbit_camera(fit, deg).eye, fit.target), 5.0f, 1e-5f) << deg;
}

TEST(SceneTemplate, DefaultTemplateIsTheShippedFile) {
  std::ifstream in(fs::path(FASTSHADE_SOURCE_DIR) / "scenes" / "batch.json");
  ASSERT_TRUE(in);
  const std::string file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(file, default_batch_template_json());
  EXPECT_NO_THROW(SceneTemplate(default_batch_template_json(), "batch.json"));
}

}  // namespace
}  // namespace fastshade
