#include "gl_frame.h"

#include <cstring>
#include <stdexcept>
#include <string>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "front/scene_geometry.h"
#include "front/shade_setup.h"
#include "light/lighting.h"
#include "shaders.h"

namespace peer {

namespace {

using fastshade::Scene;

// Three vec3 uniforms a light; 64 lights use 576 of the 1024 fragment uniform components
// GL 3.3 guarantees, leaving room for the matrices and the material.
constexpr int kMaxLights = 64;

// Throws with the driver's log if a shader did not compile or a program did not link.
void check(GLuint object, GLenum status, void (*get_iv)(GLuint, GLenum, GLint*),
           void (*get_log)(GLuint, GLsizei, GLsizei*, GLchar*), const std::string& what) {
  GLint ok = 0;
  get_iv(object, status, &ok);
  if (ok) return;
  char log[4096];
  get_log(object, sizeof log, nullptr, log);
  throw std::runtime_error(what + ": " + log);
}

GLuint compile(GLenum stage, const std::string& source) {
  const GLuint shader = glCreateShader(stage);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  check(shader, GL_COMPILE_STATUS, glGetShaderiv, glGetShaderInfoLog,
        stage == GL_VERTEX_SHADER ? "vertex shader" : "fragment shader");
  return shader;
}

GLuint link(const ShaderSources& sources) {
  const GLuint vs = compile(GL_VERTEX_SHADER, sources.vertex);
  const GLuint fs = compile(GL_FRAGMENT_SHADER, sources.fragment);
  const GLuint program = glCreateProgram();
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  glLinkProgram(program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  check(program, GL_LINK_STATUS, glGetProgramiv, glGetProgramInfoLog, "shader link");
  return program;
}

template <typename T>
GLuint static_buffer(GLenum target, const std::vector<T>& data) {
  GLuint buffer = 0;
  glGenBuffers(1, &buffer);
  glBindBuffer(target, buffer);
  glBufferData(target, static_cast<GLsizeiptr>(data.size() * sizeof(T)), data.data(), GL_STATIC_DRAW);
  return buffer;
}

GLuint renderbuffer(GLenum format, int width, int height) {
  GLuint rb = 0;
  glGenRenderbuffers(1, &rb);
  glBindRenderbuffer(GL_RENDERBUFFER, rb);
  glRenderbufferStorage(GL_RENDERBUFFER, format, width, height);
  return rb;
}

}  // namespace

GlFrame::GlFrame(const Scene& scene, bool phong, bool cull_back)
    : width_(scene.width), height_(scene.height) {
  // fastshade's own front-end inputs: the geometry it rasterises, its camera matrices and its
  // view-space lights and materials (no sRGB, exact BRDF: the `phong` and `reference` setting).
  const fastshade::SceneGeometry geometry = fastshade::flatten_scene(scene);
  const fastshade::ViewTransform xf = fastshade::view_transform(scene);
  const fastshade::ShadeConstants k = fastshade::shade_constants(scene, xf);
  const int lights = static_cast<int>(k.lights.size());
  if (lights > kMaxLights)
    throw std::runtime_error(scene.source + ": " + std::to_string(lights) + " lights; this peer draws at most " +
                             std::to_string(kMaxLights));
  // flatten_scene appends each object's triangles in scene order.
  std::size_t first_triangle = 0;
  for (std::size_t i = 0; i < geometry.objects.size(); ++i) {
    const fastshade::ObjectRange& range = geometry.objects[i];
    const std::size_t count = scene.objects[i].mesh->triangles.size();
    const glm::mat4 model_view = xf.view * range.model;
    const glm::mat3 normal_matrix = glm::inverseTranspose(glm::mat3(model_view));
    const fastshade::MaterialConstants& m = k.materials[range.material];
    ObjectDraw d;
    std::memcpy(d.model_view, glm::value_ptr(model_view), sizeof d.model_view);
    std::memcpy(d.normal_matrix, glm::value_ptr(normal_matrix), sizeof d.normal_matrix);
    std::memcpy(d.kd, glm::value_ptr(m.kd), sizeof d.kd);
    std::memcpy(d.ks, glm::value_ptr(m.ks), sizeof d.ks);
    d.shininess = m.shininess;
    d.first_index_bytes = first_triangle * 3 * sizeof(uint32_t);
    d.index_count = static_cast<GLsizei>(count * 3);
    if (count > 0) objects_.push_back(d);
    first_triangle += count;
  }

  glGenFramebuffers(1, &framebuffer_);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  color_ = renderbuffer(GL_RGBA8, width_, height_);
  depth_ = renderbuffer(GL_DEPTH_COMPONENT32F, width_, height_);  // fastshade: float depth, LESS
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("the RGBA8 + DEPTH32F framebuffer is incomplete");

  // Static vertex data, uploaded once: only the frame is timed.
  glGenVertexArrays(1, &vertex_array_);
  glBindVertexArray(vertex_array_);
  positions_ = static_buffer(GL_ARRAY_BUFFER, geometry.positions);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  glEnableVertexAttribArray(0);
  normals_ = static_buffer(GL_ARRAY_BUFFER, geometry.normals);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  glEnableVertexAttribArray(1);
  indices_ = static_buffer(GL_ELEMENT_ARRAY_BUFFER, geometry.triangles);

  program_ = link(make_shaders({.phong = phong,
                                .local_viewer = k.local_viewer,
                                .two_sided = k.two_sided,
                                .lights = lights}));
  glUseProgram(program_);
  u_model_view_ = glGetUniformLocation(program_, "u_model_view");
  u_normal_matrix_ = glGetUniformLocation(program_, "u_normal_matrix");
  u_kd_ = glGetUniformLocation(program_, "u_kd");
  u_ks_ = glGetUniformLocation(program_, "u_ks");
  u_shininess_ = glGetUniformLocation(program_, "u_shininess");
  glUniformMatrix4fv(glGetUniformLocation(program_, "u_proj"), 1, GL_FALSE, glm::value_ptr(xf.proj));
  glUniform3fv(glGetUniformLocation(program_, "u_ambient"), 1, glm::value_ptr(k.ambient));
  std::vector<glm::vec3> l_view, h_view, color;
  for (const fastshade::LightView& light : k.lights) {
    l_view.push_back(light.l_view);
    h_view.push_back(light.h_view);
    color.push_back(light.color);
  }
  if (lights > 0) {
    glUniform3fv(glGetUniformLocation(program_, "u_l_view"), lights, glm::value_ptr(l_view[0]));
    glUniform3fv(glGetUniformLocation(program_, "u_h_view"), lights, glm::value_ptr(h_view[0]));
    glUniform3fv(glGetUniformLocation(program_, "u_light_color"), lights, glm::value_ptr(color[0]));
  }

  glViewport(0, 0, width_, height_);
  glDisable(GL_DITHER);  // fastshade rounds; GL may dither an RGBA8 store unless told not to
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  // fastshade culls what is clockwise on screen: GL's default front face (CCW, y up).
  if (scene.cull == fastshade::Cull::Back || cull_back) glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glFrontFace(GL_CCW);
  // The background as fastshade quantises it, so that the clear stores the same bytes.
  float clear_rgb[3];
  for (int c = 0; c < 3; ++c) clear_rgb[c] = fastshade::quantize(k.background[c], false) / 255.0f;
  glClearColor(clear_rgb[0], clear_rgb[1], clear_rgb[2], 1.0f);
  glClearDepth(1.0);
  if (const GLenum error = glGetError(); error != GL_NO_ERROR)
    throw std::runtime_error("GL error " + std::to_string(error) + " while setting up the frame");
}

GlFrame::~GlFrame() {
  glDeleteProgram(program_);
  const GLuint buffers[] = {positions_, normals_, indices_};
  glDeleteBuffers(3, buffers);
  glDeleteVertexArrays(1, &vertex_array_);
  const GLuint renderbuffers[] = {color_, depth_};
  glDeleteRenderbuffers(2, renderbuffers);
  glDeleteFramebuffers(1, &framebuffer_);
}

void GlFrame::draw() {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glUseProgram(program_);
  glBindVertexArray(vertex_array_);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  for (const ObjectDraw& d : objects_) {
    glUniformMatrix4fv(u_model_view_, 1, GL_FALSE, d.model_view);
    glUniformMatrix3fv(u_normal_matrix_, 1, GL_FALSE, d.normal_matrix);
    glUniform3fv(u_kd_, 1, d.kd);
    glUniform3fv(u_ks_, 1, d.ks);
    glUniform1f(u_shininess_, d.shininess);
    glDrawElements(GL_TRIANGLES, d.index_count, GL_UNSIGNED_INT,
                   reinterpret_cast<const void*>(d.first_index_bytes));
  }
}

fastshade::Image GlFrame::read() {
  std::vector<uint8_t> rgba(std::size_t(width_) * height_ * 4);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  fastshade::Image image;
  image.width = width_;
  image.height = height_;
  image.rgb.resize(std::size_t(width_) * height_ * 3);
  for (int y = 0; y < height_; ++y) {  // GL's row 0 is the bottom one
    const uint8_t* src = rgba.data() + std::size_t(height_ - 1 - y) * width_ * 4;
    uint8_t* dst = image.rgb.data() + std::size_t(y) * width_ * 3;
    for (int x = 0; x < width_; ++x)
      for (int c = 0; c < 3; ++c) dst[3 * x + c] = src[4 * x + c];
  }
  return image;
}

}  // namespace peer
