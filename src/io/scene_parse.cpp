// Scene files: JSON in, a resolved Scene out (meshes loaded or built, camera framed).
// The format is documented key by key in docs/scene-format.md.
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <system_error>
#include <vector>

#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <nlohmann/json.hpp>

#include "core/limits.h"
#include "fastshade/error.h"
#include "fastshade/primitives.h"
#include "fastshade/scene.h"
#include "io/json_file.h"
#include "io/json_path.h"
#include "io/scene_camera.h"
#include "io/scene_file.h"

namespace fastshade {
namespace {

using json_path::child;
using json_path::element;
using json_path::kAnyNumber;
using json_path::kNonNegative;
using json_path::kPositive;
using json_path::Range;
using json_path::Reader;
using nlohmann::json;

glm::vec3 to_float(const glm::dvec3& v) { return glm::vec3(v); }

// ---- image, lights, materials, options ------------------------------------------------------

void parse_image(const Reader& r, const json& j, Scene& scene) {
  r.expect_object(j, "image", {"width", "height", "background"});
  if (const json* v = Reader::find(j, "width"))
    scene.width = int(r.integer(*v, "image.width", 1, kMaxImageSide));
  if (const json* v = Reader::find(j, "height"))
    scene.height = int(r.integer(*v, "image.height", 1, kMaxImageSide));
  if (const json* v = Reader::find(j, "background"))
    scene.background = to_float(r.vec3(*v, "image.background", Range{0, 1}));
}

Light parse_light(const Reader& r, const json& j, const std::string& path) {
  r.expect_object(j, path, {"type", "direction", "color", "space"});
  Light light;
  if (const json* v = Reader::find(j, "type")) r.choice(*v, child(path, "type"), {"directional"});
  const json* direction = Reader::find(j, "direction");
  if (!direction) r.fail(child(path, "direction"), "missing (the direction toward the light)");
  const glm::dvec3 d = r.vec3(*direction, child(path, "direction"), kAnyNumber);
  const glm::vec3 unit = to_float(glm::normalize(d));  // in double: tiny vectors are fine
  if (!(glm::dot(d, d) > 0.0) || !std::isfinite(unit.x + unit.y + unit.z))
    r.fail(child(path, "direction"), "must not be the zero vector");
  light.direction = unit;
  if (const json* v = Reader::find(j, "color"))
    light.color = to_float(r.vec3(*v, child(path, "color"), kNonNegative));
  if (const json* v = Reader::find(j, "space"))
    light.space = r.choice(*v, child(path, "space"), {"world", "view"}) == 0 ? LightSpace::World
                                                                              : LightSpace::View;
  return light;
}

Material parse_material(const Reader& r, const json& j, const std::string& path,
                        const std::string& name) {
  r.expect_object(j, path, {"diffuse", "specular", "shininess"});
  Material material;
  material.name = name;
  if (const json* v = Reader::find(j, "diffuse"))
    material.diffuse = to_float(r.scalar_or_vec3(*v, child(path, "diffuse"), kNonNegative));
  if (const json* v = Reader::find(j, "specular"))
    material.specular = to_float(r.scalar_or_vec3(*v, child(path, "specular"), kNonNegative));
  if (const json* v = Reader::find(j, "shininess"))
    material.shininess = r.number(*v, child(path, "shininess"), Range{1, limits::kMaxShininess});
  return material;
}

std::vector<Material> parse_materials(const Reader& r, const json* j) {
  if (!j) return {Material{.name = "default"}};
  if (!j->is_object())  // keys are material names, free
    r.fail("materials", "expected an object of named materials, got " + json_path::describe(*j));
  std::vector<Material> materials;
  for (const auto& [name, value] : j->items()) {
    const std::string path = child("materials", name);
    if (name.empty()) r.fail(path, "a material name must not be empty");
    materials.push_back(parse_material(r, value, path, name));
  }
  if (materials.empty())
    r.fail("materials", "expected at least one material (leave the key out for a default one)");
  return materials;
}

void parse_options(const Reader& r, const json& j, Scene& scene) {
  r.expect_object(j, "options", {"cull", "two_sided"});
  if (const json* v = Reader::find(j, "cull"))
    scene.cull = r.choice(*v, "options.cull", {"none", "back"}) == 0 ? Cull::None : Cull::Back;
  if (const json* v = Reader::find(j, "two_sided"))
    scene.two_sided = r.boolean(*v, "options.two_sided");
}

// ---- objects --------------------------------------------------------------------------------

// model = T · Rz · Ry · Rx · S: scale first, then rotate about X, Y, Z (degrees,
// counter-clockwise looking down the axis), then translate.
glm::mat4 parse_transform(const Reader& r, const json& j, const std::string& path) {
  r.expect_object(j, path, {"translate", "rotate_deg", "scale"});
  glm::dvec3 translate(0.0), rotate_deg(0.0), scale(1.0);
  if (const json* v = Reader::find(j, "translate"))
    translate = r.vec3(*v, child(path, "translate"), kAnyNumber);
  if (const json* v = Reader::find(j, "rotate_deg"))
    rotate_deg = r.vec3(*v, child(path, "rotate_deg"), kAnyNumber);
  if (const json* v = Reader::find(j, "scale"))
    scale = r.scalar_or_vec3(*v, child(path, "scale"), kPositive);
  glm::dmat4 model = glm::translate(glm::dmat4(1.0), translate);
  model = glm::rotate(model, glm::radians(rotate_deg.z), glm::dvec3(0, 0, 1));
  model = glm::rotate(model, glm::radians(rotate_deg.y), glm::dvec3(0, 1, 0));
  model = glm::rotate(model, glm::radians(rotate_deg.x), glm::dvec3(1, 0, 0));
  model = glm::scale(model, scale);
  return glm::mat4(model);
}

// A primitive's parameters: key, integer or not, default, accepted range.
struct ParamSpec {
  std::string_view key;
  bool integer;
  double fallback;
  Range range;
};

struct PrimitiveSpec {
  std::string_view name;
  std::vector<ParamSpec> params;
  std::function<Mesh(const std::vector<double>&)> build;  // values in `params` order
};

const std::vector<PrimitiveSpec>& primitive_specs() {
  const Range size{0, kMaxPrimitiveSize, true};
  const double segs = kMaxPrimitiveSegments;
  static const std::vector<PrimitiveSpec> specs = {
      {"icosphere",
       {{"radius", false, 1, size}, {"subdivisions", true, 3, {0, kMaxIcosphereSubdivisions}}},
       [](const std::vector<double>& v) { return make_icosphere(float(v[0]), int(v[1])); }},
      {"uvsphere",
       {{"radius", false, 1, size}, {"segments", true, 64, {3, segs}}, {"rings", true, 32, {2, segs}}},
       [](const std::vector<double>& v) {
         return make_uvsphere(float(v[0]), int(v[1]), int(v[2]));
       }},
      {"torus",
       {{"major", false, 1, size},
        {"minor", false, 0.3, size},
        {"segments", true, 64, {3, segs}},
        {"sides", true, 32, {3, segs}}},
       [](const std::vector<double>& v) {
         return make_torus(float(v[0]), float(v[1]), int(v[2]), int(v[3]));
       }},
      {"plane",
       {{"size", false, 2, size}, {"divisions", true, 1, {1, segs}}},
       [](const std::vector<double>& v) { return make_plane(float(v[0]), int(v[1])); }},
      {"cube",
       {{"size", false, 1, size}, {"divisions", true, 1, {1, segs}}},
       [](const std::vector<double>& v) { return make_cube(float(v[0]), int(v[1])); }},
  };
  return specs;
}

class ObjectParser {
 public:
  ObjectParser(const Reader& r, const std::filesystem::path& base_dir,
               const std::vector<Material>& materials)
      : r_(r), base_dir_(base_dir), materials_(materials) {}

  Object parse(const json& j, const std::string& path) {
    if (!j.is_object()) r_.fail(path, "expected an object, got " + json_path::describe(j));
    const json* mesh = Reader::find(j, "mesh");
    const json* primitive = Reader::find(j, "primitive");
    if (mesh && primitive) r_.fail(path, "give either \"mesh\" or \"primitive\", not both");
    if (!mesh && !primitive) r_.fail(path, "missing \"mesh\" (a file) or \"primitive\"");

    Object object;
    object.mesh = mesh ? mesh_object(j, path) : primitive_object(j, path);
    object.material = material_index(j, path);
    if (const json* v = Reader::find(j, "transform"))
      object.model = parse_transform(r_, *v, child(path, "transform"));
    return object;
  }

 private:
  std::shared_ptr<const Mesh> mesh_object(const json& j, const std::string& path) {
    r_.expect_object(j, path, {"mesh", "material", "transform", "normals", "weld"});
    const std::string key_path = child(path, "mesh");
    const std::string file = r_.string(j.at("mesh"), key_path);
    if (file.empty()) r_.fail(key_path, "expected a file path, got \"\"");
    MeshLoadOptions options;
    if (const json* v = Reader::find(j, "normals"))
      options.normals = r_.choice(*v, child(path, "normals"), {"file", "recompute"}) == 0
                            ? NormalsMode::File
                            : NormalsMode::Recompute;
    if (const json* v = Reader::find(j, "weld")) options.weld = r_.boolean(*v, child(path, "weld"));

    // Relative paths are relative to the scene file; the cache key is the resolved file, so
    // "a.obj" and "./a.obj" load once.
    const std::filesystem::path full = base_dir_ / std::filesystem::path(file);
    std::error_code ec;
    std::filesystem::path canonical = std::filesystem::weakly_canonical(full, ec);
    if (ec) canonical = full.lexically_normal();
    const std::string key = "mesh:" + canonical.string() + "|normals=" +
                            std::to_string(int(options.normals)) + "|weld=" +
                            std::to_string(int(options.weld));
    if (auto it = cache_.find(key); it != cache_.end()) return it->second;
    try {
      auto loaded = std::make_shared<const Mesh>(load_mesh(full, options));
      return cache_[key] = loaded;
    } catch (const InputError& e) {  // "PATH: problem" from the loader
      r_.fail(key_path, e.what());
    }
  }

  std::shared_ptr<const Mesh> primitive_object(const json& j, const std::string& path) {
    const std::string key_path = child(path, "primitive");
    std::vector<std::string_view> names;
    for (const PrimitiveSpec& spec : primitive_specs()) names.push_back(spec.name);
    const PrimitiveSpec& spec = primitive_specs()[r_.choice(j.at("primitive"), key_path, names)];

    std::vector<std::string_view> allowed = {"primitive", "material", "transform"};
    for (const ParamSpec& p : spec.params) allowed.push_back(p.key);
    r_.expect_object(j, path, allowed);

    std::vector<double> values;
    std::string key = "primitive:" + std::string(spec.name);
    for (const ParamSpec& p : spec.params) {
      double value = p.fallback;
      if (const json* v = Reader::find(j, p.key)) {
        value = p.integer ? double(r_.integer(*v, child(path, p.key), int64_t(p.range.lo),
                                                 int64_t(p.range.hi)))
                          : r_.number(*v, child(path, p.key), p.range);
      }
      values.push_back(value);
      key.append("|").append(json_path::format_number(value));
    }
    if (spec.name == "torus" && !(float(values[1]) < float(values[0])))
      r_.fail(child(path, "minor"), "must be less than major (" +
                                        json_path::format_number(values[0]) + "), got " +
                                        json_path::format_number(values[1]));

    if (auto it = cache_.find(key); it != cache_.end()) return it->second;
    try {
      return cache_[key] = std::make_shared<const Mesh>(spec.build(values));
    } catch (const InputError& e) {  // e.g. more triangles than kMaxPrimitiveTriangles
      r_.fail(path, e.what());
    }
  }

  int material_index(const json& j, const std::string& path) const {
    const std::string key_path = child(path, "material");
    std::string names;
    for (const Material& m : materials_) names += (names.empty() ? "" : ", ") + m.name;
    const json* v = Reader::find(j, "material");
    if (!v) {
      if (materials_.size() == 1) return 0;
      r_.fail(key_path, "missing: the scene defines " + std::to_string(materials_.size()) +
                            " materials (" + names + "), name one");
    }
    const std::string name = r_.string(*v, key_path);
    for (size_t i = 0; i < materials_.size(); ++i) {
      if (materials_[i].name == name) return int(i);
    }
    r_.fail(key_path, "no material " + json_path::describe(*v) + " (defined: " + names + ")");
  }

  const Reader& r_;
  std::filesystem::path base_dir_;
  const std::vector<Material>& materials_;
  std::map<std::string, std::shared_ptr<const Mesh>> cache_;  // one Mesh per file/options
};

}  // namespace

Scene parse_scene(const std::string& json_text, const std::string& source,
                  const std::filesystem::path& base_dir) {
  const Reader r(source);
  const json root = json_path::parse(json_text, source);
  if (!root.is_object())
    r.fail("", "expected a JSON object at the top level, got " + json_path::describe(root));
  r.expect_object(root, "", {"image", "camera", "lights", "viewer", "ambient", "materials",
                             "objects", "options"});

  Scene scene;
  scene.source = source;
  if (const json* v = Reader::find(root, "image")) parse_image(r, *v, scene);
  if (const json* v = Reader::find(root, "lights")) {
    r.expect_array(*v, "lights");
    for (size_t i = 0; i < v->size(); ++i)
      scene.lights.push_back(parse_light(r, (*v)[i], element("lights", i)));
  }
  if (const json* v = Reader::find(root, "viewer"))
    scene.viewer = r.choice(*v, "viewer", {"infinite", "local"}) == 0 ? Viewer::Infinite
                                                                      : Viewer::Local;
  if (const json* v = Reader::find(root, "ambient"))
    scene.ambient = to_float(r.vec3(*v, "ambient", kNonNegative));
  scene.materials = parse_materials(r, Reader::find(root, "materials"));
  if (const json* v = Reader::find(root, "options")) parse_options(r, *v, scene);

  const json* objects = Reader::find(root, "objects");
  if (!objects) r.fail("objects", "missing (a scene needs at least one object)");
  r.expect_array(*objects, "objects");
  if (objects->empty()) r.fail("objects", "expected at least one object, got an empty array");
  ObjectParser object_parser(r, base_dir, scene.materials);
  for (size_t i = 0; i < objects->size(); ++i)
    scene.objects.push_back(object_parser.parse((*objects)[i], element("objects", i)));

  scene.camera = parse_camera(r, Reader::find(root, "camera"), scene.objects);
  return scene;
}

std::string read_scene_file(const std::filesystem::path& path) {
  return read_json_file_text(path, "scene file");
}

Scene load_scene(const std::filesystem::path& path) {
  const std::string text = read_scene_file(path);
  std::filesystem::path base_dir = path.parent_path();
  if (base_dir.empty()) base_dir = ".";
  return parse_scene(text, path.string(), base_dir);
}

}  // namespace fastshade
