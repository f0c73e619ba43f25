#include "egl_context.h"

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string_view>

#include <EGL/eglext.h>

#include "gl_api.h"

namespace peer {

namespace {

[[noreturn]] void fail(const std::string& what) {
  char code[32];
  std::snprintf(code, sizeof code, " (EGL error 0x%04X)", eglGetError());
  throw std::runtime_error(what + code);
}

bool has_extension(const char* list, std::string_view name) {
  const std::string_view all = list ? list : "";
  for (std::size_t at = all.find(name); at != std::string_view::npos; at = all.find(name, at + 1)) {
    const std::size_t end = at + name.size();
    if ((at == 0 || all[at - 1] == ' ') && (end == all.size() || all[end] == ' ')) return true;
  }
  return false;
}

}  // namespace

EglContext::EglContext(int threads) {
  // Mesa's knobs: no hardware driver, gallium's llvmpipe (not softpipe), its thread count.
  setenv("LIBGL_ALWAYS_SOFTWARE", "1", 1);
  setenv("GALLIUM_DRIVER", "llvmpipe", 1);
  setenv("LP_NUM_THREADS", std::to_string(threads).c_str(), 1);

  if (!has_extension(eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS), "EGL_MESA_platform_surfaceless"))
    throw std::runtime_error("EGL has no EGL_MESA_platform_surfaceless (is libegl-mesa0 installed?)");
  display_ = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display_ == EGL_NO_DISPLAY) fail("eglGetPlatformDisplay(surfaceless) failed");
  if (!eglInitialize(display_, nullptr, nullptr)) fail("eglInitialize failed");
  const char* display_extensions = eglQueryString(display_, EGL_EXTENSIONS);
  for (const char* needed : {"EGL_KHR_no_config_context", "EGL_KHR_surfaceless_context"})
    if (!has_extension(display_extensions, needed))
      throw std::runtime_error(std::string("the surfaceless EGL display lacks ") + needed);
  if (!eglBindAPI(EGL_OPENGL_API)) fail("eglBindAPI(EGL_OPENGL_API) failed");
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                               EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                               EGL_NONE};
  context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
  if (context_ == EGL_NO_CONTEXT) fail("eglCreateContext(OpenGL 3.3 core) failed");
  if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) fail("eglMakeCurrent failed");

  renderer_ = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  version_ = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  if (renderer_.find("llvmpipe") == std::string::npos)
    throw std::runtime_error("GL_RENDERER is \"" + renderer_ + "\", not llvmpipe");
}

EglContext::~EglContext() {
  if (display_ == EGL_NO_DISPLAY) return;
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
  eglTerminate(display_);
}

}  // namespace peer
