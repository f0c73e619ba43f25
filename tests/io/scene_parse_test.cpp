// Scene files: the shipped scenes parse, every key is checked, errors name the key path.
#include "fastshade/scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <unistd.h>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>
#include <nlohmann/json.hpp>

#include "fastshade/error.h"
#include "fastshade/primitives.h"

namespace fastshade {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kScenes = fs::path(FASTSHADE_SOURCE_DIR) / "scenes";

Scene parse(const std::string& text) { return parse_scene(text, "scene.json", "."); }

// The message of the InputError parsing `text` throws ("" and a failure if none).
std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted: " << text;
  return "";
}

// A minimal valid scene around one object; `extra` adds top-level keys.
std::string with(const std::string& extra, const std::string& object = R"({"primitive": "cube"})") {
  return R"({"objects": [)" + object + "]" + (extra.empty() ? "" : ", " + extra) + "}";
}

// The error is one line and starts with "scene.json: KEYPATH: " ("scene.json: " for the
// document itself); returns the rest.
std::string expect_error_at(const std::string& text, const std::string& key_path) {
  const std::string what = error_of(text);
  EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  const std::string prefix = key_path.empty() ? "scene.json: " : "scene.json: " + key_path + ": ";
  EXPECT_EQ(what.rfind(prefix, 0), 0u) << "expected prefix \"" << prefix << "\" in: " << what;
  return what.size() >= prefix.size() ? what.substr(prefix.size()) : what;
}

void expect_near(glm::vec3 a, glm::vec3 b, float tolerance) {
  EXPECT_LT(glm::length(a - b), tolerance) << "(" << a.x << ", " << a.y << ", " << a.z
                                           << ") vs (" << b.x << ", " << b.y << ", " << b.z << ")";
}

// A directory under the system temp dir, removed at the end of the test.
struct TempDir {
  fs::path path;
  explicit TempDir(const std::string& name)
      : path(fs::temp_directory_path() /
             ("fastshade_scene_test_" + name + "_" + std::to_string(getpid()))) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
  void write(const std::string& name, const std::string& text) const {
    std::ofstream(path / name, std::ios::binary) << text;
  }
};

// ---- shipped scenes -------------------------------------------------------------------------

TEST(Scene, DefaultSceneParsesAndLooksAsSpecified) {
  const Scene scene = parse_scene(default_scene_json(), "default", ".");
  EXPECT_EQ(scene.width, 1280);
  EXPECT_EQ(scene.height, 720);
  int world = 0, view = 0;
  for (const Light& light : scene.lights) (light.space == LightSpace::World ? world : view)++;
  EXPECT_EQ(world, 1);
  EXPECT_EQ(view, 1);
  std::set<double> shininess;
  for (const Material& m : scene.materials) shininess.insert(m.shininess);
  EXPECT_EQ(shininess, (std::set<double>{10, 100, 1000}));
  ASSERT_GE(scene.objects.size(), 3u);
  std::set<std::string> kinds;
  for (const Object& object : scene.objects) {
    ASSERT_TRUE(object.mesh);
    EXPECT_FALSE(object.mesh->triangles.empty());
    kinds.insert(object.mesh->source);
  }
  EXPECT_TRUE(kinds.count("icosphere"));
  EXPECT_TRUE(kinds.count("torus"));
}

TEST(Scene, DefaultSceneFileMatchesEmbeddedText) {
  std::ifstream in(kScenes / "default.json");
  ASSERT_TRUE(in) << kScenes / "default.json";
  EXPECT_EQ(json::parse(in), json::parse(default_scene_json()));
}

TEST(Scene, DocumentedExampleIsTheDefaultScene) {
  std::ifstream in(fs::path(FASTSHADE_SOURCE_DIR) / "docs" / "scene-format.md");
  ASSERT_TRUE(in);
  const std::string doc((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t start = doc.find("```json\n");
  ASSERT_NE(start, std::string::npos);
  const size_t end = doc.find("```", start + 8);
  ASSERT_NE(end, std::string::npos);
  EXPECT_EQ(json::parse(doc.substr(start + 8, end - start - 8)), json::parse(default_scene_json()));
}

TEST(Scene, EveryShippedSceneParses) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(kScenes)) {
    if (entry.path().extension() != ".json") continue;
    ++count;
    SCOPED_TRACE(entry.path().string());
    try {
      const Scene scene = load_scene(entry.path());
      EXPECT_FALSE(scene.objects.empty());
      EXPECT_EQ(scene.source, entry.path().string());
    } catch (const InputError& e) {
      ADD_FAILURE() << e.what();
    }
  }
  EXPECT_GE(count, 3);
}

TEST(Scene, ShippedScenesCoverTheirFeatures) {
  const Scene local = load_scene(kScenes / "torus_local.json");
  EXPECT_EQ(local.viewer, Viewer::Local);
  EXPECT_EQ(local.cull, Cull::Back);
  const Scene spheres = load_scene(kScenes / "spheres.json");
  std::set<double> shininess;
  for (const Material& m : spheres.materials) shininess.insert(m.shininess);
  EXPECT_GE(shininess.size(), 8u);
  EXPECT_EQ(*shininess.rbegin(), 1e6);
}

// ---- defaults and values --------------------------------------------------------------------

TEST(Scene, Defaults) {
  const Scene scene = parse(with(""));
  EXPECT_EQ(scene.width, 640);
  EXPECT_EQ(scene.height, 480);
  EXPECT_EQ(scene.viewer, Viewer::Infinite);
  EXPECT_EQ(scene.cull, Cull::None);
  EXPECT_FALSE(scene.two_sided);
  EXPECT_TRUE(scene.lights.empty());
  EXPECT_EQ(scene.ambient, glm::vec3(0.0f));
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_EQ(scene.materials[0].name, "default");
  ASSERT_EQ(scene.objects.size(), 1u);
  EXPECT_EQ(scene.objects[0].mesh->triangles.size(), 12u);  // cube, 1 division
  // No camera key: a fit camera, distance 3, fovy 45.
  const Camera fit = fit_camera(scene.objects, 3.0f, 45.0f);
  EXPECT_EQ(scene.camera.eye, fit.eye);
  EXPECT_EQ(scene.camera.near, fit.near);
  EXPECT_EQ(scene.camera.fovy_deg, 45.0f);
}

TEST(Scene, ValuesReachTheScene) {
  const Scene scene = parse(with(R"(
    "image": {"width": 33, "height": 17, "background": [0.25, 0.5, 1]},
    "camera": {"eye": [1, 2, 3], "target": [0, 1, 0], "up": [0, 0, 1], "fovy_deg": 30,
               "near": 0.25, "far": 9},
    "viewer": "local", "ambient": [0.1, 0.2, 0.3],
    "options": {"cull": "back", "two_sided": true})"));
  EXPECT_EQ(scene.width, 33);
  EXPECT_EQ(scene.height, 17);
  EXPECT_EQ(scene.background, glm::vec3(0.25f, 0.5f, 1.0f));
  EXPECT_EQ(scene.camera.eye, glm::vec3(1, 2, 3));
  EXPECT_EQ(scene.camera.target, glm::vec3(0, 1, 0));
  EXPECT_EQ(scene.camera.up, glm::vec3(0, 0, 1));
  EXPECT_EQ(scene.camera.fovy_deg, 30.0f);
  EXPECT_EQ(scene.camera.near, 0.25f);
  EXPECT_EQ(scene.camera.far, 9.0f);
  EXPECT_EQ(scene.viewer, Viewer::Local);
  EXPECT_EQ(scene.ambient, glm::vec3(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(scene.cull, Cull::Back);
  EXPECT_TRUE(scene.two_sided);
}

TEST(Scene, LightDirectionNormalised) {
  const Scene scene = parse(with(R"("lights": [
      {"type": "directional", "direction": [0, 3, 4], "color": [0.5, 1, 2], "space": "world"},
      {"direction": [1e-30, 0, 0]}])"));
  ASSERT_EQ(scene.lights.size(), 2u);
  expect_near(scene.lights[0].direction, glm::vec3(0, 0.6f, 0.8f), 1e-7f);
  EXPECT_EQ(scene.lights[0].color, glm::vec3(0.5f, 1, 2));
  EXPECT_EQ(scene.lights[0].space, LightSpace::World);
  // Tiny but not zero is a direction; defaults are white and view space.
  EXPECT_EQ(scene.lights[1].direction, glm::vec3(1, 0, 0));
  EXPECT_EQ(scene.lights[1].color, glm::vec3(1));
  EXPECT_EQ(scene.lights[1].space, LightSpace::View);
}

TEST(Scene, MaterialsByName) {
  const Scene scene = parse(R"({
    "materials": {"red": {"diffuse": [1, 0, 0], "specular": 0.25, "shininess": 12.5},
                  "blue": {"diffuse": 0.5}},
    "objects": [{"primitive": "cube", "material": "red"},
                {"primitive": "cube", "material": "blue"},
                {"primitive": "cube", "material": "red"}]})");
  ASSERT_EQ(scene.objects.size(), 3u);
  const auto& m = scene.materials;
  EXPECT_EQ(m[size_t(scene.objects[0].material)].name, "red");
  EXPECT_EQ(m[size_t(scene.objects[1].material)].name, "blue");
  EXPECT_EQ(scene.objects[2].material, scene.objects[0].material);
  const Material& red = m[size_t(scene.objects[0].material)];
  EXPECT_EQ(red.diffuse, glm::vec3(1, 0, 0));
  EXPECT_EQ(red.specular, glm::vec3(0.25f));
  EXPECT_EQ(red.shininess, 12.5);
  const Material& blue = m[size_t(scene.objects[1].material)];
  EXPECT_EQ(blue.diffuse, glm::vec3(0.5f));
  EXPECT_EQ(blue.specular, glm::vec3(0.5f));  // default
  EXPECT_EQ(blue.shininess, 32.0);            // default

  // With a single material the object may omit it.
  const Scene one = parse(R"({"materials": {"only": {}}, "objects": [{"primitive": "cube"}]})");
  EXPECT_EQ(one.materials[size_t(one.objects[0].material)].name, "only");
}

TEST(Scene, TransformOrderIsTranslateRzRyRxScale) {
  auto model_of = [](const std::string& transform) {
    return parse(with("", R"({"primitive": "cube", "transform": )" + transform + "}"))
        .objects[0]
        .model;
  };
  auto apply = [](const glm::mat4& m, glm::vec3 p) { return glm::vec3(m * glm::vec4(p, 1.0f)); };
  // Scale, then rotate, then translate.
  const glm::mat4 a = model_of(R"({"translate": [1, 0, 0], "rotate_deg": [0, 0, 90], "scale": [2, 1, 1]})");
  expect_near(apply(a, {1, 0, 0}), {1, 2, 0}, 1e-6f);
  // X before Y: (0,1,0) -Rx 90-> (0,0,1) -Ry 90-> (1,0,0). (Y first would give (0,0,1).)
  const glm::mat4 b = model_of(R"({"rotate_deg": [90, 90, 0]})");
  expect_near(apply(b, {0, 1, 0}), {1, 0, 0}, 1e-6f);
  // Y before Z: (1,0,0) -Ry 90-> (0,0,-1) -Rz 90-> (0,0,-1); Z first would give (0,1,0).
  const glm::mat4 c = model_of(R"({"rotate_deg": [0, 90, 90]})");
  expect_near(apply(c, {1, 0, 0}), {0, 0, -1}, 1e-6f);
  // A number scales uniformly.
  const glm::mat4 d = model_of(R"({"scale": 3})");
  EXPECT_EQ(apply(d, {1, 1, 1}), glm::vec3(3, 3, 3));
}

// ---- camera ---------------------------------------------------------------------------------

TEST(Scene, FitCameraFrame) {
  // The 8 corners of [-1, 1]^3, scaled by 2 and moved to (1, 2, 3): centre (1, 2, 3), r = 2√3.
  auto corners = std::make_shared<Mesh>();
  for (int i = 0; i < 8; ++i)
    corners->positions.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
  Object object;
  object.mesh = corners;
  object.model = glm::mat4(2.0f);
  object.model[3] = glm::vec4(1, 2, 3, 1);
  const float r = 2.0f * std::sqrt(3.0f), d = 2.5f;
  const Camera camera = fit_camera({object}, d, 50.0f);
  expect_near(camera.target, {1, 2, 3}, 1e-6f);
  expect_near(camera.eye, {1, 2, 3 + d * r}, 1e-5f);
  EXPECT_EQ(camera.up, glm::vec3(0, 1, 0));
  EXPECT_NEAR(camera.near, (d - 1.1f) * r, 1e-5f);
  EXPECT_NEAR(camera.far, (d + 1.1f) * r, 1e-5f);
  EXPECT_EQ(camera.fovy_deg, 50.0f);

  // The AABB centre, not the vertex mean: an extra vertex at a corner does not move it.
  auto lopsided = std::make_shared<Mesh>(*corners);
  lopsided->positions.emplace_back(1, 1, 1);
  lopsided->positions.emplace_back(0.9f, 0.9f, 0.9f);
  object.mesh = lopsided;
  expect_near(fit_camera({object}, d, 50.0f).target, {1, 2, 3}, 1e-6f);

  // Two objects: the sphere spans both.
  Object left, right;
  left.mesh = right.mesh = std::make_shared<Mesh>(make_icosphere(1.0f, 2));
  left.model[3] = glm::vec4(-3, 0, 0, 1);
  right.model[3] = glm::vec4(3, 0, 0, 1);
  const Camera both = fit_camera({left, right}, 3.0f, 45.0f);
  expect_near(both.target, {0, 0, 0}, 1e-6f);
  EXPECT_NEAR(both.eye.z, 3.0f * 4.0f, 1e-5f);
  EXPECT_NEAR(both.near, 1.9f * 4.0f, 1e-5f);

  EXPECT_THROW(fit_camera({}, 3.0f, 45.0f), InputError);
}

TEST(Scene, FitCameraFromTheSceneFile) {
  const Scene scene = parse(with(R"("camera": {"fit": true, "distance": 4, "fovy_deg": 30})",
                                 R"({"primitive": "icosphere", "radius": 2,
                                     "transform": {"translate": [0, 5, 0]}})"));
  const Camera expected = fit_camera(scene.objects, 4.0f, 30.0f);
  EXPECT_EQ(scene.camera.eye, expected.eye);
  EXPECT_EQ(scene.camera.target, expected.target);
  EXPECT_EQ(scene.camera.near, expected.near);
  EXPECT_EQ(scene.camera.far, expected.far);
  EXPECT_EQ(scene.camera.fovy_deg, 30.0f);
  expect_near(scene.camera.target, {0, 5, 0}, 1e-5f);
  EXPECT_NEAR(scene.camera.eye.z, 8.0f, 1e-5f);
}

// ---- meshes ---------------------------------------------------------------------------------

TEST(Scene, IdenticalPrimitivesShareOneMesh) {
  const Scene scene = parse(R"({"objects": [
      {"primitive": "torus", "minor": 0.25},
      {"primitive": "torus", "minor": 0.25, "transform": {"translate": [3, 0, 0]}},
      {"primitive": "torus", "minor": 0.5},
      {"primitive": "torus"}]})");
  ASSERT_EQ(scene.objects.size(), 4u);
  EXPECT_EQ(scene.objects[0].mesh, scene.objects[1].mesh);
  EXPECT_NE(scene.objects[0].mesh, scene.objects[2].mesh);
  EXPECT_NE(scene.objects[0].mesh, scene.objects[3].mesh);
  EXPECT_EQ(scene.objects[3].mesh->triangles.size(), size_t(2 * 64 * 32));  // default 64 x 32
}

// Needs the real mesh loader (load_mesh): a file referenced twice with the same options is
// loaded once, relative to the scene file's directory.
TEST(Scene, MeshFileLoadedOnceAndSharedRelativeToScene) {
  TempDir dir("shared_mesh");
  fs::create_directories(dir.path / "meshes");
  dir.write("meshes/tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  dir.write("scene.json", R"({"objects": [
      {"mesh": "meshes/tri.obj"},
      {"mesh": "meshes/tri.obj", "transform": {"translate": [1, 0, 0]}},
      {"mesh": "./meshes/../meshes/tri.obj"},
      {"mesh": "meshes/tri.obj", "normals": "recompute"},
      {"mesh": "meshes/tri.obj", "weld": true}],
      "camera": {"eye": [0, 0, 5], "target": [0, 0, 0]}})");
  try {
    const Scene scene = load_scene(dir.path / "scene.json");
    ASSERT_EQ(scene.objects.size(), 5u);
    EXPECT_EQ(scene.objects[0].mesh, scene.objects[1].mesh);
    EXPECT_EQ(scene.objects[0].mesh, scene.objects[2].mesh);
    EXPECT_NE(scene.objects[0].mesh, scene.objects[3].mesh);
    EXPECT_NE(scene.objects[0].mesh, scene.objects[4].mesh);
    EXPECT_EQ(scene.objects[0].mesh->triangles.size(), 1u);
  } catch (const InputError& e) {
    ADD_FAILURE() << e.what();
  }
}

TEST(Scene, MeshErrorsNameTheKeyAndTheFile) {
  const std::string rest = expect_error_at(with("", R"({"mesh": "no_such_mesh.obj"})"),
                                           "objects[0].mesh");
  EXPECT_NE(rest.find("no_such_mesh.obj"), std::string::npos) << rest;
  expect_error_at(with("", R"({"mesh": ""})"), "objects[0].mesh");
  expect_error_at(with("", R"({"mesh": 3})"), "objects[0].mesh");
  expect_error_at(with("", R"({"mesh": "a.obj", "normals": "smooth"})"), "objects[0].normals");
  expect_error_at(with("", R"({"mesh": "a.obj", "weld": 1})"), "objects[0].weld");
}

// ---- errors ---------------------------------------------------------------------------------

TEST(SceneErrors, ExactMessages) {
  EXPECT_EQ(error_of(with(R"("image": {"width": 0})")),
            "scene.json: image.width: expected an integer in [1, 16384], got 0");
  EXPECT_EQ(error_of(R"({"materials": {"silver": {}, "iron": {}}, "objects": [
                {"primitive": "cube", "material": "silver"}, {"primitive": "cube", "material": "iron"},
                {"primitive": "cube", "material": "gold"}]})")
                .rfind(R"(scene.json: objects[2].material: no material "gold")", 0),
            0u);
  EXPECT_EQ(error_of(with(R"("camera": {"eye": [0, 0, 1], "target": [0, 0, 0], "fovy": 40})"))
                .rfind("scene.json: camera.fovy: unknown key", 0),
            0u);
}

TEST(SceneErrors, ImageAndGlobals) {
  expect_error_at(with(R"("image": {"width": 16385})"), "image.width");
  expect_error_at(with(R"("image": {"height": -3})"), "image.height");
  expect_error_at(with(R"("image": {"width": "640"})"), "image.width");
  expect_error_at(with(R"("image": {"width": 640.5})"), "image.width");
  expect_error_at(with(R"("image": {"width": 18446744073709551615})"), "image.width");
  expect_error_at(with(R"("image": {"background": [0, 0]})"), "image.background");
  expect_error_at(with(R"("image": {"background": [0, 2, 0]})"), "image.background[1]");
  expect_error_at(with(R"("image": [640, 480])"), "image");
  expect_error_at(with(R"("viewer": "orthographic")"), "viewer");
  expect_error_at(with(R"("viewer": 3)"), "viewer");
  expect_error_at(with(R"("ambient": [0, -0.1, 0])"), "ambient[1]");
  expect_error_at(with(R"("options": {"cull": "front"})"), "options.cull");
  expect_error_at(with(R"("options": {"two_sided": "yes"})"), "options.two_sided");
}

TEST(SceneErrors, Camera) {
  const std::string eye = R"("eye": [0, 0, 5], "target": [0, 0, 0])";
  expect_error_at(with(R"("camera": {)" + eye + R"(, "fovy_deg": 180})"), "camera.fovy_deg");
  expect_error_at(with(R"("camera": {)" + eye + R"(, "fovy_deg": 0})"), "camera.fovy_deg");
  expect_error_at(with(R"("camera": {)" + eye + R"(, "near": 0})"), "camera.near");
  expect_error_at(with(R"("camera": {)" + eye + R"(, "near": 1e39})"), "camera.near");
  expect_error_at(with(R"("camera": {)" + eye + R"(, "near": 2, "far": 1})"), "camera.far");
  expect_error_at(with(R"("camera": {)" + eye + R"(, "near": 2, "far": 2})"), "camera.far");
  expect_error_at(with(R"("camera": {"eye": [1, 2, 3], "target": [1, 2, 3]})"), "camera.target");
  expect_error_at(with(R"("camera": {)" + eye + R"(, "up": [0, 0, -2]})"), "camera.up");
  expect_error_at(with(R"("camera": {)" + eye + R"(, "up": [0, 0, 0]})"), "camera.up");
  expect_error_at(with(R"("camera": {"target": [0, 0, 0]})"), "camera.eye");
  expect_error_at(with(R"("camera": {"fit": true, "distance": 1.1})"), "camera.distance");
  expect_error_at(with(R"("camera": {"fit": "yes"})"), "camera.fit");
  expect_error_at(with(R"("camera": 5)"), "camera");
  // Keys of the other mode are unknown in this one.
  EXPECT_NE(expect_error_at(with(R"("camera": {"fit": true, "eye": [0, 0, 5]})"), "camera.eye")
                .find("unknown key"),
            std::string::npos);
  EXPECT_NE(expect_error_at(with(R"("camera": {)" + eye + R"(, "distance": 3})"), "camera.distance")
                .find("unknown key"),
            std::string::npos);
}

TEST(SceneErrors, Lights) {
  expect_error_at(with(R"("lights": [{"direction": [0, 0, 1]}, {"direction": [0, 0, 0]}])"),
                  "lights[1].direction");
  expect_error_at(with(R"("lights": [{}])"), "lights[0].direction");
  expect_error_at(with(R"("lights": [{"direction": [0, 0, 1], "type": "point"}])"), "lights[0].type");
  expect_error_at(with(R"("lights": [{"direction": [0, 0, 1], "space": "screen"}])"), "lights[0].space");
  expect_error_at(with(R"("lights": [{"direction": [0, 0, 1], "color": [-1, 0, 0]}])"),
                  "lights[0].color[0]");
  expect_error_at(with(R"("lights": [{"direction": [0, "up", 1]}])"), "lights[0].direction[1]");
  expect_error_at(with(R"("lights": {"direction": [0, 0, 1]})"), "lights");
}

TEST(SceneErrors, Materials) {
  auto material = [](const std::string& body) {
    return R"({"materials": {"m": )" + body + R"(}, "objects": [{"primitive": "cube"}]})";
  };
  expect_error_at(material(R"({"shininess": 0.5})"), "materials.m.shininess");
  expect_error_at(material(R"({"shininess": 2e6})"), "materials.m.shininess");
  expect_error_at(material(R"({"shininess": "high"})"), "materials.m.shininess");
  expect_error_at(material(R"({"diffuse": -0.1})"), "materials.m.diffuse");
  expect_error_at(material(R"({"diffuse": "red"})"), "materials.m.diffuse");
  expect_error_at(material(R"({"specular": [1, 2]})"), "materials.m.specular");
  expect_error_at(material(R"({"specular": [1, 2, -3]})"), "materials.m.specular[2]");
  expect_error_at(material(R"(7)"), "materials.m");
  // Names that are not identifiers are quoted in the path.
  expect_error_at(R"({"materials": {"old gold": {"shininess": 0}}, "objects": [{"primitive": "cube"}]})",
                  R"(materials["old gold"].shininess)");
  expect_error_at(R"({"materials": {}, "objects": [{"primitive": "cube"}]})", "materials");
  expect_error_at(R"({"materials": [], "objects": [{"primitive": "cube"}]})", "materials");
  // Two materials: an object must name one.
  const std::string rest = expect_error_at(
      R"({"materials": {"a": {}, "b": {}}, "objects": [{"primitive": "cube", "material": "a"},
          {"primitive": "cube"}]})",
      "objects[1].material");
  EXPECT_NE(rest.find("missing"), std::string::npos) << rest;
  expect_error_at(with("", R"({"primitive": "cube", "material": 1})"), "objects[0].material");
}

TEST(SceneErrors, Objects) {
  expect_error_at(R"({})", "objects");
  expect_error_at(R"({"objects": []})", "objects");
  expect_error_at(R"({"objects": {"primitive": "cube"}})", "objects");
  expect_error_at(R"({"objects": ["cube"]})", "objects[0]");
  expect_error_at(with("", R"({"material": "default"})"), "objects[0]");
  expect_error_at(with("", R"({"primitive": "cube", "mesh": "a.obj"})"), "objects[0]");
  expect_error_at(with("", R"({"primitive": "cone"})"), "objects[0].primitive");
  expect_error_at(with("", R"({"primitive": "icosphere", "subdivisions": 9})"), "objects[0].subdivisions");
  expect_error_at(with("", R"({"primitive": "icosphere", "subdivisions": 2.5})"), "objects[0].subdivisions");
  expect_error_at(with("", R"({"primitive": "icosphere", "radius": 0})"), "objects[0].radius");
  expect_error_at(with("", R"({"primitive": "icosphere", "radius": -1})"), "objects[0].radius");
  expect_error_at(with("", R"({"primitive": "uvsphere", "segments": 5000})"), "objects[0].segments");
  expect_error_at(with("", R"({"primitive": "uvsphere", "rings": 1})"), "objects[0].rings");
  expect_error_at(with("", R"({"primitive": "torus", "minor": 1})"), "objects[0].minor");
  expect_error_at(with("", R"({"primitive": "torus", "sides": 2})"), "objects[0].sides");
  expect_error_at(with("", R"({"primitive": "plane", "divisions": 0})"), "objects[0].divisions");
  expect_error_at(with("", R"({"primitive": "cube", "size": 1e7})"), "objects[0].size");
  // Each parameter in range, the product too large: the primitive's own check, keyed by object.
  const std::string rest = expect_error_at(
      with("", R"({"primitive": "torus", "segments": 4096, "sides": 4096})"), "objects[0]");
  EXPECT_NE(rest.find("triangles"), std::string::npos) << rest;
  expect_error_at(with("", R"({"primitive": "cube", "transform": {"scale": 0}})"),
                  "objects[0].transform.scale");
  expect_error_at(with("", R"({"primitive": "cube", "transform": {"scale": [1, -1, 1]}})"),
                  "objects[0].transform.scale[1]");
  expect_error_at(with("", R"({"primitive": "cube", "transform": {"scale": "big"}})"),
                  "objects[0].transform.scale");
  expect_error_at(with("", R"({"primitive": "cube", "transform": {"translate": [0, 0]}})"),
                  "objects[0].transform.translate");
  expect_error_at(with("", R"({"primitive": "cube", "transform": [1, 0, 0]})"), "objects[0].transform");
}

TEST(SceneErrors, UnknownKeysAtEveryDepth) {
  auto unknown = [](const std::string& text, const std::string& path) {
    EXPECT_NE(expect_error_at(text, path).find("unknown key"), std::string::npos) << text;
  };
  unknown(with(R"("lightz": [])"), "lightz");
  unknown(with(R"("image": {"width": 10, "depth": 8})"), "image.depth");
  unknown(with(R"("lights": [{"direction": [0, 0, 1], "intensity": 2}])"), "lights[0].intensity");
  unknown(R"({"materials": {"m": {"roughness": 0.2}}, "objects": [{"primitive": "cube"}]})",
          "materials.m.roughness");
  unknown(with("", R"({"primitive": "cube", "transform": {"skew": 1}})"), "objects[0].transform.skew");
  unknown(with("", R"({"primitive": "icosphere", "segments": 8})"), "objects[0].segments");
  unknown(with("", R"({"primitive": "cube", "normals": "recompute"})"), "objects[0].normals");
  unknown(with("", R"({"mesh": "a.obj", "radius": 1})"), "objects[0].radius");
  unknown(with(R"("options": {"wireframe": true})"), "options.wireframe");
  unknown(with(R"("image": {"width ": 10})"), R"(image["width "])");
}

TEST(SceneErrors, JsonSyntaxAndDuplicates) {
  const std::string one_line = error_of(R"({"objects": [{"primitive": "cube"},]})");
  EXPECT_EQ(one_line.rfind("scene.json: line 1, column ", 0), 0u) << one_line;
  const std::string third = error_of("{\n  \"objects\": [\n    {\"primitive\" \"cube\"}]}");
  EXPECT_EQ(third.rfind("scene.json: line 3, column ", 0), 0u) << third;
  EXPECT_EQ(third.find('\n'), std::string::npos) << third;
  const std::string empty = error_of("");
  EXPECT_EQ(empty.rfind("scene.json: line 1, column ", 0), 0u) << empty;
  // A number beyond double range is an error, not infinity.
  const std::string huge = error_of(with(R"("ambient": [1e400, 0, 0])"));
  EXPECT_EQ(huge.rfind("scene.json: ", 0), 0u) << huge;
  EXPECT_EQ(huge.find('\n'), std::string::npos) << huge;
  // Duplicate keys would silently take the last value: named by their path instead.
  EXPECT_EQ(error_of(with(R"("image": {"width": 10, "width": 20})")),
            "scene.json: image.width: duplicate key");
  EXPECT_EQ(error_of(R"({"objects": [{"primitive": "cube"}, {"primitive": "cube", "primitive": "torus"}]})"),
            "scene.json: objects[1].primitive: duplicate key");
  EXPECT_EQ(error_of(R"({"lights": [[1], {"a": 1, "a": 2}]})"), "scene.json: lights[1].a: duplicate key");
  expect_error_at("[1, 2]", "");  // the top level must be an object
}

TEST(SceneErrors, FilesThatAreNotScenes) {
  TempDir dir("not_scenes");
  for (const fs::path& path : {dir.path / "missing.json", dir.path}) {
    try {
      load_scene(path);
      ADD_FAILURE() << "accepted " << path;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(path.string() + ": ", 0), 0u) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }
  // Errors inside a file carry the path as given.
  dir.write("bad.json", R"({"objects": [{"primitive": "cube"}], "viewer": "near"})");
  try {
    load_scene(dir.path / "bad.json");
    ADD_FAILURE() << "accepted bad.json";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind((dir.path / "bad.json").string() + ": viewer: ", 0), 0u)
        << e.what();
  }
}

}  // namespace
}  // namespace fastshade
