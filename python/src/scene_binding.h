// The Python-side scene: the C++ Scene and a camera that may still have to be fitted.
#pragma once
#include "fastshade/scene.h"

namespace fastshade::python {

struct PyCamera {
  Camera camera;
  bool fit = true;  // Camera.fit(): framed when rendered, once the objects are known
  float fit_distance = 2.5f, fit_fovy_deg = 45.0f;
};

struct PyScene {
  Scene scene;
  PyCamera camera;
};

// The scene as the renderer takes it: the camera fitted if it is to be, every part checked.
Scene resolved_scene(const PyScene& scene);

}  // namespace fastshade::python
