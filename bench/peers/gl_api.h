// The OpenGL 3.3 core API, declared from Khronos' glcorearb.h; libOpenGL (glvnd) exports
// every core entry point, so no loader is needed.
#pragma once
#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>
