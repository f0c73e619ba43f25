// fastshade's frame drawn with OpenGL: the same flattened geometry, matrices and shading
// constants fastshade computes (front/scene_geometry.h, front/vertex_stage.h), uploaded once,
// drawn into an off-screen RGBA8 + 32-bit float depth framebuffer.
#pragma once
#include <cstdint>
#include <vector>

#include "fastshade/image.h"
#include "fastshade/scene.h"
#include "gl_api.h"

namespace peer {

class GlFrame {
 public:
  // Needs a current GL 3.3 context. `phong` false = gouraud. `cull_back`: GL culls back faces
  // (as pyrender does by default) even where the scene does not. Output is linear (fastshade
  // without --srgb). Throws std::runtime_error on a shader or framebuffer error or a scene
  // with more lights than the shaders take.
  GlFrame(const fastshade::Scene& scene, bool phong, bool cull_back);
  ~GlFrame();
  GlFrame(const GlFrame&) = delete;
  GlFrame& operator=(const GlFrame&) = delete;

  // Clears and issues the draws; returns without waiting (the caller times up to glFinish).
  void draw();
  // Reads the framebuffer back, top row first, as fastshade's Image.
  fastshade::Image read();

 private:
  struct ObjectDraw {
    float model_view[16], normal_matrix[9];
    float kd[3], ks[3], shininess;
    std::uintptr_t first_index_bytes;
    GLsizei index_count;
  };

  int width_, height_;
  std::vector<ObjectDraw> objects_;
  GLuint framebuffer_ = 0, color_ = 0, depth_ = 0;
  GLuint program_ = 0, vertex_array_ = 0, positions_ = 0, normals_ = 0, indices_ = 0;
  GLint u_model_view_, u_normal_matrix_, u_kd_, u_ks_, u_shininess_;
};

}  // namespace peer
