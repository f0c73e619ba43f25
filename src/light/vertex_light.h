// Gouraud's vertex lighting over a block of vertices: vertex_color() (light/lighting.h) for
// each, in SIMD lanes where that computes the same colour. On a dense mesh the vertex stage
// lights hundreds of thousands of vertices a frame (dragon_871k: 435k), and one by one that
// was about a third of the gouraud frame's front end.
#pragma once
#include <cstddef>

#include <glm/vec3.hpp>

#include "core/simd_target.h"
#include "frame/shade_constants.h"

namespace fastshade {

// color[i] = vertex_color<specular>(n_view[i], V, ...) with V toward the eye: (0, 0, 1) for an
// infinite viewer, normalize(-pos_view[i]) for a local one (pos_view may be null otherwise).
// Lanes for an infinite viewer and a material lit in float; the scalar loop otherwise (a local
// viewer's normalisation and a material lit in double have no SIMD twin).
void light_vertices(SimdTarget simd, const glm::vec3* n_view, const glm::vec3* pos_view, std::size_t count,
                    const MaterialConstants& m, const ShadeConstants& k, bool specular, glm::vec3* color);

// The scalar reference: vertex_color() for each vertex.
void light_vertices_scalar(const glm::vec3* n_view, const glm::vec3* pos_view, std::size_t count,
                           const MaterialConstants& m, const ShadeConstants& k, bool specular,
                           glm::vec3* color);

}  // namespace fastshade
