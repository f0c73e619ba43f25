// The vertex stage's per-vertex work: position to clip space, flags and the snapped screen
// point, and the view-space normal and position. A dense mesh has hundreds of thousands of
// vertices (dragon_871k: 435k), and one by one this was a quarter of the phong frame's front
// end.
#pragma once
#include <cstddef>
#include <cstdint>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/simd_target.h"
#include "front/projection.h"

namespace fastshade {

struct VertexTransform {
  glm::mat4 model_view{1.0f}, proj{1.0f};
  glm::mat3 normal_matrix{1.0f};  // inverse transpose of model_view's 3x3
  Viewport viewport;
};

// Vertices [0, count): clip[i], flags[i] and, where the vertex needs no clipping, screen[i]
// (elsewhere screen[i] is unspecified; setup never reads it). With normals (may be null):
// n_view[i] = normalize(normal_matrix * normals[i]) and pos_view[i], the view-space position.
// SIMD lanes on the ISA `simd` (core/simd_target.h), bit for bit the scalar reference: glm's
// operation order, no FMA, the projection in double.
struct VertexOutputs {
  glm::vec4* clip;
  ScreenVertex* screen;
  uint8_t* flags;
  glm::vec3* n_view;    // written if normals is not null
  glm::vec3* pos_view;  // written if normals is not null
};
void transform_vertices(SimdTarget simd, const VertexTransform& xf, const glm::vec3* positions, const glm::vec3* normals,
                        std::size_t count, const VertexOutputs& out);

// The scalar reference: glm and project() (front/projection.h), vertex by vertex.
void transform_vertices_scalar(const VertexTransform& xf, const glm::vec3* positions, const glm::vec3* normals,
                               std::size_t count, const VertexOutputs& out);

}  // namespace fastshade
