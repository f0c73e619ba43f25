// Per-frame shading constants, resolved to view space: what every shading kernel reads.
#pragma once
#include <vector>

#include <glm/vec3.hpp>

#include "frame/brdf_params.h"

namespace fastshade {

struct LightView {
  glm::vec3 l_view;    // unit direction toward the light
  glm::vec3 h_view;    // unit half vector for the infinite viewer, normalize(L + (0,0,1))
  glm::vec3 color;
};

struct MaterialConstants {
  glm::vec3 kd, ks;
  float shininess;
  double shininess_d;
  BrdfParams lobe;  // the frame's specular approximation, fitted to this shininess
  // Float Blinn-Phong cannot hold 1 LSB for this material (docs/STABILITY.md, "Fallbacks"):
  // per-pixel methods draw its triangles with the reference, Gouraud lights its vertices in
  // double.
  bool shade_in_double = false;
};

struct ShadeConstants {
  std::vector<LightView> lights;
  std::vector<MaterialConstants> materials;
  glm::vec3 ambient{0.0f};
  glm::vec3 background{0.0f};
  bool local_viewer = false;
  bool two_sided = false;
  bool srgb = false;
  BrdfChoice brdf;  // --brdf
  float hybrid_tolerance = 0;  // hybrid and --normals adaptive: error allowed, colour units (--max-error)
  PhongNormals normals = PhongNormals::Normalize;  // --normals
};

}  // namespace fastshade
