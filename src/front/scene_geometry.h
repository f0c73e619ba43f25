// The scene's meshes flattened once per renderer: all objects' vertices and triangles in one
// index space, so the front end's chunks can cut across objects.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "fastshade/scene.h"

namespace fastshade {

struct ObjectRange {
  uint32_t first_vertex = 0, vertex_count = 0;
  uint32_t first_triangle = 0, triangle_count = 0;
  glm::mat4 model{1.0f};
  int material = 0;
  glm::vec3 box_min{0.0f}, box_max{0.0f};  // object-space bounds of its vertices
};

struct SceneGeometry {
  std::vector<glm::vec3> positions;  // object space
  std::vector<glm::vec3> normals;    // object space, unit
  std::vector<std::array<uint32_t, 3>> triangles;  // global vertex indices
  std::vector<uint16_t> triangle_material;
  std::vector<ObjectRange> objects;
};

// Meshes without normals get recomputed ones here (the loader normally supplies them).
SceneGeometry flatten_scene(const Scene& scene);

}  // namespace fastshade
