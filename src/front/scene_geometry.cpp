#include "front/scene_geometry.h"

#include <cmath>
#include <limits>
#include <string>

#include <glm/geometric.hpp>

#include "fastshade/error.h"

namespace fastshade {

namespace {

// Appends the mesh's normals scaled to unit length (in double). A mesh built in memory reaches
// the renderer without load_mesh's checks: a zero or non-finite normal would normalise to NaN
// in the vertex stage, and one shorter than 1e-19 or longer than 1e19 to zero or infinity in
// float, all shading as garbage. The first is an error, the others are scaled here; a normal
// already unit to float rounding (within 1e-6: a float-normalised vector is within 3e-7) is
// kept bit for bit.
void append_unit_normals(const Mesh& mesh, std::vector<glm::vec3>& out) {
  constexpr double kUnitSlack = 1e-6;
  for (std::size_t i = 0; i < mesh.normals.size(); ++i) {
    const glm::dvec3 n(mesh.normals[i]);
    const double len = glm::length(n);
    if (!(std::isfinite(len) && len > 0.0))
      throw InputError(mesh.source, "vertex " + std::to_string(i) + ": normal is zero or not finite");
    out.push_back(std::fabs(len - 1.0) <= kUnitSlack ? mesh.normals[i] : glm::vec3(n / len));
  }
}

}  // namespace

SceneGeometry flatten_scene(const Scene& scene) {
  SceneGeometry g;
  std::size_t vertices = 0, triangles = 0;
  for (const Object& o : scene.objects) {
    vertices += o.mesh->positions.size();
    triangles += o.mesh->triangles.size();
  }
  // Bin entries and attribute indices reserve the top bit; 2^31 vertices is far beyond memory.
  if (vertices >= (std::size_t{1} << 31) || triangles >= std::numeric_limits<uint32_t>::max())
    throw InputError(scene.source, "too many vertices or triangles");
  if (scene.materials.size() > std::numeric_limits<uint16_t>::max())
    throw InputError(scene.source, "too many materials");
  g.positions.reserve(vertices);
  g.normals.reserve(vertices);
  g.triangles.reserve(triangles);
  g.triangle_material.reserve(triangles);
  for (const Object& o : scene.objects) {
    const Mesh* mesh = o.mesh.get();
    Mesh with_normals;
    if (mesh->normals.size() != mesh->positions.size()) {
      with_normals = *mesh;
      recompute_normals(with_normals);
      mesh = &with_normals;
    }
    ObjectRange range;
    range.first_vertex = static_cast<uint32_t>(g.positions.size());
    range.vertex_count = static_cast<uint32_t>(mesh->positions.size());
    range.first_triangle = static_cast<uint32_t>(g.triangles.size());
    range.triangle_count = static_cast<uint32_t>(mesh->triangles.size());
    range.model = o.model;
    range.material = o.material;
    if (!mesh->positions.empty()) {
      range.box_min = range.box_max = mesh->positions.front();
      for (const glm::vec3& p : mesh->positions) {
        range.box_min = glm::min(range.box_min, p);
        range.box_max = glm::max(range.box_max, p);
      }
    }
    g.objects.push_back(range);
    g.positions.insert(g.positions.end(), mesh->positions.begin(), mesh->positions.end());
    append_unit_normals(*mesh, g.normals);
    for (const auto& t : mesh->triangles) {
      g.triangles.push_back({t[0] + range.first_vertex, t[1] + range.first_vertex,
                             t[2] + range.first_vertex});
      g.triangle_material.push_back(static_cast<uint16_t>(o.material));
    }
  }
  return g;
}

}  // namespace fastshade
