#include "front/scene_geometry.h"

#include <glm/common.hpp>

#include <limits>

#include "fastshade/error.h"

namespace fastshade {

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
    g.normals.insert(g.normals.end(), mesh->normals.begin(), mesh->normals.end());
    for (const auto& t : mesh->triangles) {
      g.triangles.push_back({t[0] + range.first_vertex, t[1] + range.first_vertex,
                             t[2] + range.first_vertex});
      g.triangle_material.push_back(static_cast<uint16_t>(o.material));
    }
  }
  return g;
}

}  // namespace fastshade
