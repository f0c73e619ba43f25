// An OpenGL 3.3 core context on Mesa's llvmpipe, with no window and no GPU: EGL's surfaceless
// platform (EGL_MESA_platform_surfaceless) and a context current without any surface.
#pragma once
#include <string>

#include <EGL/egl.h>

namespace peer {

class EglContext {
 public:
  // Forces Mesa's software path onto llvmpipe with `threads` rasterizer threads
  // (LP_NUM_THREADS) before EGL is touched: llvmpipe reads them once, when its screen is
  // created. Throws std::runtime_error if any step fails or the driver is not llvmpipe.
  explicit EglContext(int threads);
  ~EglContext();
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  const std::string& renderer() const { return renderer_; }  // GL_RENDERER
  const std::string& version() const { return version_; }    // GL_VERSION (names Mesa's)

 private:
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  std::string renderer_, version_;
};

}  // namespace peer
