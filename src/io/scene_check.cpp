// check_scene(): a scene built in code held to what a scene file may say (scene-format.md).
#include <cmath>
#include <string>

#include "core/limits.h"
#include "fastshade/error.h"
#include "fastshade/scene.h"
#include "io/json_path.h"
#include "io/scene_camera.h"

namespace fastshade {

namespace {

using json_path::format_number;

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Each channel finite and in [lo, hi].
void check_color(const glm::vec3& c, const std::string& key, float lo, float hi) {
  for (int i = 0; i < 3; ++i)
    if (!(c[i] >= lo && c[i] <= hi))
      throw InputError(key, "expected each channel in [" + format_number(lo) + ", " + format_number(hi) + "], got " +
                                format_number(c[i]));
}

void check_mesh(const Mesh& mesh, const std::string& key) {
  if (mesh.triangles.empty()) throw InputError(key, "has no triangles");
  for (std::size_t i = 0; i < mesh.positions.size(); ++i)
    if (!finite(mesh.positions[i])) throw InputError(key, "vertex " + std::to_string(i) + " is not finite");
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (uint32_t v : mesh.triangles[t])
      if (v >= mesh.positions.size())
        throw InputError(key, "triangle " + std::to_string(t) + " names vertex " + std::to_string(v) + " of " +
                                  std::to_string(mesh.positions.size()));
  if (!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size())
    throw InputError(key, std::to_string(mesh.normals.size()) + " normals for " + std::to_string(mesh.positions.size()) +
                              " vertices (one each, or none)");
  for (std::size_t i = 0; i < mesh.normals.size(); ++i)
    if (!finite(mesh.normals[i]) || mesh.normals[i] == glm::vec3(0.0f))
      throw InputError(key, "normal " + std::to_string(i) + " is zero or not finite");
}

}  // namespace

void check_material(const Material& m, const std::string& key) {
  check_color(m.diffuse, key + ".diffuse", 0.0f, HUGE_VALF);
  check_color(m.specular, key + ".specular", 0.0f, HUGE_VALF);
  if (!(m.shininess >= 1.0 && m.shininess <= limits::kMaxShininess))
    throw InputError(key + ".shininess", "expected [1, " + format_number(limits::kMaxShininess) + "], got " +
                                             format_number(m.shininess));
}

void check_mesh(const Mesh& mesh) { check_mesh(mesh, mesh.source.empty() ? std::string("mesh") : mesh.source); }

void check_scene(const Scene& s) {
  for (auto [key, side] : {std::pair{"image.width", s.width}, std::pair{"image.height", s.height}})
    if (side < 1 || side > kMaxImageSide)
      throw InputError(key, "expected 1 to " + std::to_string(kMaxImageSide) + ", got " + std::to_string(side));
  check_color(s.background, "image.background", 0.0f, 1.0f);
  check_color(s.ambient, "ambient", 0.0f, 1.0f);
  for (std::size_t i = 0; i < s.lights.size(); ++i) {
    const std::string key = json_path::element("lights", i);
    const glm::vec3& d = s.lights[i].direction;
    if (!finite(d) || !(std::fabs(std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z) - 1.0f) <= 1e-4f))
      throw InputError(key + ".direction", "expected a finite unit vector toward the light");
    check_color(s.lights[i].color, key + ".color", 0.0f, HUGE_VALF);
  }
  if (s.materials.empty()) throw InputError("materials", "expected at least one material");
  for (std::size_t i = 0; i < s.materials.size(); ++i) check_material(s.materials[i], json_path::element("materials", i));
  if (s.objects.empty()) throw InputError("objects", "expected at least one object");
  for (std::size_t i = 0; i < s.objects.size(); ++i) {
    const Object& o = s.objects[i];
    const std::string key = json_path::element("objects", i);
    if (!o.mesh) throw InputError(key + ".mesh", "missing");
    check_mesh(*o.mesh, key + ".mesh");
    if (o.material < 0 || o.material >= static_cast<int>(s.materials.size()))
      throw InputError(key + ".material", "index " + std::to_string(o.material) + " of " +
                                              std::to_string(s.materials.size()) + " materials");
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r)
        if (!std::isfinite(o.model[c][r])) throw InputError(key + ".transform", "has a non-finite entry");
  }
  check_camera(s.camera);
}

}  // namespace fastshade
