// GLSL for fastshade's colour model (docs/scene-format.md, "Colour model"; src/light/lighting.h),
// written as a GL application would, one program per variant so that llvmpipe compiles no
// branch the frame does not take.
#pragma once
#include <string>

namespace peer {

struct ShaderVariant {
  bool phong = true;         // false: gouraud (lit per vertex, colour interpolated)
  bool local_viewer = false;  // V = normalize(-P) instead of (0, 0, 1)
  bool two_sided = false;     // back faces lit with the normal flipped
  int lights = 1;
};

struct ShaderSources {
  std::string vertex, fragment;
};

// Uniforms: u_model_view, u_proj (mat4), u_normal_matrix (mat3), u_ambient, u_kd, u_ks (vec3),
// u_shininess (float), u_l_view, u_h_view, u_light_color (vec3[lights]). Attributes:
// location 0 position, 1 normal (object space). Output: the colour already quantised to
// round(255 v) / 255, so that the RGBA8 store cannot round differently from fastshade.
ShaderSources make_shaders(const ShaderVariant& variant);

}  // namespace peer
