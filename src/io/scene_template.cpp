// Scene templates for fastshade batch: the template is parsed once by the scene parser with a
// stand-in object (so every key is checked exactly as `fastshade render` checks it), and each
// mesh then takes the stand-in's place and is framed by the same camera code.
#include "io/scene_template.h"

#include <cmath>

#include <glm/trigonometric.hpp>

#include "fastshade/error.h"
#include "io/json_path.h"
#include "io/scene_camera.h"

namespace fastshade {
namespace {

using json_path::Reader;
using nlohmann::json;

// The first object's keys that apply to any mesh; the rest of it (its file or primitive and
// their parameters) is what each mesh replaces.
constexpr const char* kKeptObjectKeys[] = {"material", "transform", "normals", "weld"};

// Parsed in place of the mesh: tiny, and valid with any material and transform.
json stand_in(const json& kept) {
  json object = {{"primitive", "icosphere"}, {"subdivisions", 0}};
  for (const char* key : {"material", "transform"}) {
    if (const json* v = Reader::find(kept, key)) object[key] = *v;
  }
  return object;
}

}  // namespace

SceneTemplate::SceneTemplate(const std::string& json_text, const std::string& source) {
  const Reader r(source);
  root_ = json_path::parse(json_text, source);
  if (!root_.is_object())
    r.fail("", "expected a JSON object at the top level, got " + json_path::describe(root_));

  if (const json* camera = Reader::find(root_, "camera")) {
    const json* fit = camera->is_object() ? Reader::find(*camera, "fit") : nullptr;
    if (!fit || *fit != true)
      r.fail("camera", "batch frames every mesh with the fit camera: give {\"fit\": true, ...} "
                       "or leave the camera out");
    camera_ = *camera;
  }

  json kept = json::object();
  if (const json* objects = Reader::find(root_, "objects")) {
    r.expect_array(*objects, "objects");
    if (!objects->empty()) {
      const json& first = (*objects)[0];
      if (!first.is_object())
        r.fail("objects[0]", "expected an object, got " + json_path::describe(first));
      for (const char* key : kKeptObjectKeys) {
        if (const json* v = Reader::find(first, key)) kept[key] = *v;
      }
    }
  }
  if (const json* v = Reader::find(kept, "normals"))
    mesh_options_.normals = r.choice(*v, "objects[0].normals", {"file", "recompute"}) == 0
                                ? NormalsMode::File
                                : NormalsMode::Recompute;
  if (const json* v = Reader::find(kept, "weld")) mesh_options_.weld = r.boolean(*v, "objects[0].weld");

  json parsed = root_;
  parsed["objects"] = json::array({stand_in(kept)});
  base_ = parse_scene(parsed.dump(), source, ".");
  material_ = base_.objects[0].material;
  model_ = base_.objects[0].model;
  base_.objects.clear();
  root_["objects"] = json::array({kept});
}

void SceneTemplate::set_image_size(int width, int height) {
  base_.width = width;
  base_.height = height;
  root_["image"]["width"] = width;
  root_["image"]["height"] = height;
}

Scene SceneTemplate::scene_for(std::shared_ptr<const Mesh> mesh) const {
  Scene scene = base_;
  scene.source = mesh->source;
  Object object;
  object.mesh = std::move(mesh);
  object.material = material_;
  object.model = model_;
  scene.objects.push_back(std::move(object));
  scene.camera = parse_camera(Reader(scene.source), camera_.is_null() ? nullptr : &camera_,
                              scene.objects);
  return scene;
}

std::string SceneTemplate::canonical() const { return root_.dump(); }

Camera orbit_camera(const Camera& camera, double angle_deg) {
  if (angle_deg == 0.0) return camera;
  // A calibrated camera has a pose but no target to turn about.
  if (camera.intrinsics) throw InputError("camera", "a calibrated camera (intrinsics) has one view only: use --views 1");
  const glm::dvec3 target(camera.target);
  const glm::dvec3 offset = glm::dvec3(camera.eye) - target;
  const double c = std::cos(glm::radians(angle_deg)), s = std::sin(glm::radians(angle_deg));
  // Right-handed rotation about +Y: +Z turns toward +X.
  const glm::dvec3 turned(c * offset.x + s * offset.z, offset.y, -s * offset.x + c * offset.z);
  Camera orbit = camera;
  orbit.eye = glm::vec3(target + turned);
  return orbit;
}

const char* default_batch_template_json() {
  return R"json({
  "image": {"width": 512, "height": 512, "background": [0.10, 0.11, 0.13]},
  "camera": {"fit": true, "distance": 3, "fovy_deg": 45},
  "ambient": [0.04, 0.04, 0.05],
  "lights": [
    {"direction": [-0.5, 0.8, 1.0], "color": [0.85, 0.82, 0.76], "space": "view"},
    {"direction": [0.6, 0.1, 0.6], "color": [0.25, 0.28, 0.35], "space": "view"}
  ],
  "materials": {"clay": {"diffuse": 0.75, "specular": 0.25, "shininess": 40}},
  "objects": [{"primitive": "icosphere", "subdivisions": 3}],
  "options": {"two_sided": true}
}
)json";
}

}  // namespace fastshade
