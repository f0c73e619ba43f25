#include "shaders.h"

namespace peer {

namespace {

// Blinn-Phong as src/light/lighting.h has it: view space, ambient added as given, specular
// not gated by N.L, max(N.H, 0)^n with N.H clamped to 1 first. The infinite viewer's half
// vectors come from fastshade's own ShadeConstants (u_h_view), zero for a light straight
// behind the viewer; a local viewer's are normalize(L + V), zero when L + V is.
constexpr const char* kLighting = R"(
uniform vec3 u_ambient, u_kd, u_ks;
uniform float u_shininess;
#if LIGHTS > 0
uniform vec3 u_l_view[LIGHTS], u_h_view[LIGHTS], u_light_color[LIGHTS];
#endif

vec3 blinn_phong(vec3 n_view, vec3 v_view) {
  vec3 c = u_ambient;
#if LIGHTS > 0
  for (int i = 0; i < LIGHTS; ++i) {
#if LOCAL_VIEWER
    vec3 h = u_l_view[i] + v_view;
    float h2 = dot(h, h);
    h = h2 > 0.0 ? h * inversesqrt(h2) : vec3(0.0);
#else
    vec3 h = u_h_view[i];
#endif
    float diffuse = max(dot(n_view, u_l_view[i]), 0.0);
    float n_dot_h = min(dot(n_view, h), 1.0);
    float specular = n_dot_h > 0.0 ? pow(n_dot_h, u_shininess) : 0.0;
    c += u_light_color[i] * (u_kd * diffuse + u_ks * specular);
  }
#endif
  return c;
}
)";

constexpr const char* kVertex = R"(
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
uniform mat4 u_model_view, u_proj;
uniform mat3 u_normal_matrix;
#if PHONG
out vec3 v_normal_view;
#if LOCAL_VIEWER
out vec3 v_position_view;
#endif
#else
out vec3 v_color;
#if TWO_SIDED
out vec3 v_color_back;  // the side is known only per fragment: light both
#endif
#endif

void main() {
  // model-view then projection, as fastshade's vertex stage multiplies them (no fused MVP).
  vec4 position_view = u_model_view * vec4(a_position, 1.0);
  gl_Position = u_proj * position_view;
  vec3 n_view = normalize(u_normal_matrix * a_normal);
#if PHONG
  v_normal_view = n_view;
#if LOCAL_VIEWER
  v_position_view = position_view.xyz;
#endif
#else
#if LOCAL_VIEWER
  vec3 v_view = normalize(-position_view.xyz);
#else
  vec3 v_view = vec3(0.0, 0.0, 1.0);
#endif
  v_color = clamp(blinn_phong(n_view, v_view), 0.0, 1.0);
#if TWO_SIDED
  v_color_back = clamp(blinn_phong(-n_view, v_view), 0.0, 1.0);
#endif
#endif
}
)";

constexpr const char* kFragment = R"(
#if PHONG
in vec3 v_normal_view;
#if LOCAL_VIEWER
in vec3 v_position_view;
#endif
#else
in vec3 v_color;
#if TWO_SIDED
in vec3 v_color_back;
#endif
#endif
out vec4 out_color;

void main() {
#if PHONG
  float len2 = dot(v_normal_view, v_normal_view);
  vec3 n_view = len2 > 0.0 ? v_normal_view * inversesqrt(len2) : vec3(0.0);
#if TWO_SIDED
  if (!gl_FrontFacing) n_view = -n_view;
#endif
#if LOCAL_VIEWER
  vec3 v_view = normalize(-v_position_view);
#else
  vec3 v_view = vec3(0.0, 0.0, 1.0);
#endif
  vec3 c = blinn_phong(n_view, v_view);
#elif TWO_SIDED
  vec3 c = gl_FrontFacing ? v_color : v_color_back;
#else
  vec3 c = v_color;
#endif
  // fastshade writes floor(255 v + 0.5) of v clamped to [0, 1]; a multiple of 1/255 is stored
  // exactly by any float-to-unorm8 rounding.
  out_color = vec4(floor(clamp(c, 0.0, 1.0) * 255.0 + 0.5) / 255.0, 1.0);
}
)";

std::string header(const ShaderVariant& v) {
  auto flag = [](const char* name, bool on) { return "#define " + std::string(name) + (on ? " 1\n" : " 0\n"); };
  return "#version 330 core\n" + flag("PHONG", v.phong) + flag("LOCAL_VIEWER", v.local_viewer) +
         flag("TWO_SIDED", v.two_sided) + "#define LIGHTS " + std::to_string(v.lights) + "\n";
}

}  // namespace

ShaderSources make_shaders(const ShaderVariant& variant) {
  const std::string head = header(variant);
  // Gouraud lights in the vertex shader, phong in the fragment shader.
  return {head + (variant.phong ? "" : kLighting) + kVertex,
          head + (variant.phong ? kLighting : "") + kFragment};
}

}  // namespace peer
