// The embedded default scene: procedural meshes only, so the program renders something
// without any file. scenes/default.json holds the same text (a test keeps them equal).
#include "fastshade/scene.h"

namespace fastshade {

const char* default_scene_json() {
  return R"json({
  "image": {"width": 1280, "height": 720, "background": [0.10, 0.11, 0.13]},
  "camera": {"eye": [0, 2.3, 5.4], "target": [0, -0.3, -0.2], "up": [0, 1, 0],
             "fovy_deg": 40, "near": 0.5, "far": 30},
  "viewer": "infinite",
  "ambient": [0.05, 0.05, 0.06],
  "lights": [
    {"type": "directional", "direction": [-0.6, 1.0, 0.7], "color": [0.85, 0.82, 0.76],
     "space": "world"},
    {"type": "directional", "direction": [0.5, 0.3, 1.0], "color": [0.30, 0.33, 0.40],
     "space": "view"}
  ],
  "materials": {
    "matte":   {"diffuse": [0.55, 0.55, 0.52], "specular": 0.08, "shininess": 10},
    "plastic": {"diffuse": [0.75, 0.12, 0.10], "specular": 0.50, "shininess": 100},
    "gold":    {"diffuse": [0.55, 0.40, 0.12], "specular": [0.95, 0.85, 0.55], "shininess": 1000}
  },
  "objects": [
    {"primitive": "plane", "size": 10, "divisions": 4, "material": "matte",
     "transform": {"translate": [0, -1, 0]}},
    {"primitive": "icosphere", "radius": 1, "subdivisions": 4, "material": "plastic",
     "transform": {"translate": [-1.5, 0, 0]}},
    {"primitive": "torus", "major": 0.75, "minor": 0.28, "segments": 96, "sides": 48,
     "material": "gold", "transform": {"translate": [1.45, -0.05, 0.2], "rotate_deg": [60, -20, 0]}},
    {"primitive": "cube", "size": 1.1, "material": "matte",
     "transform": {"translate": [0.05, -0.45, -2.0], "rotate_deg": [0, 35, 0]}}
  ],
  "options": {"cull": "none", "two_sided": false}
}
)json";
}

}  // namespace fastshade
