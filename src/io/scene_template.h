// A scene file used as a template for one mesh at a time (fastshade batch): its image, lights,
// materials, viewer, ambient and options are kept, its objects are replaced by the mesh, and its
// camera, which must be a fit camera, frames that mesh.
#pragma once
#include <memory>
#include <string>

#include <glm/mat4x4.hpp>
#include <nlohmann/json.hpp>

#include "fastshade/mesh.h"
#include "fastshade/scene.h"

namespace fastshade {

class SceneTemplate {
 public:
  // `json_text` is a scene file (docs/scene-format.md) named `source` in messages. "objects"
  // may be left out; of the first object only "material", "transform", "normals" and "weld"
  // are kept (they apply to every mesh). The camera must be left out or be {"fit": true, ...}.
  // Throws InputError ("SOURCE: KEY.PATH: problem") for anything a scene file may not hold or
  // a camera that is not a fit camera.
  SceneTemplate(const std::string& json_text, const std::string& source);

  // Overrides the image size (already checked against kMaxImageSide).
  void set_image_size(int width, int height);

  const MeshLoadOptions& mesh_options() const { return mesh_options_; }

  // The scene `fastshade render` makes of the template with the mesh as its only object
  // ({"mesh": FILE} plus the kept keys): the same materials, model matrix and fit camera.
  // Throws InputError naming the mesh if it has no extent to frame.
  Scene scene_for(std::shared_ptr<const Mesh> mesh) const;

  // Everything that decides the images, as canonical JSON (sorted keys, no spacing): the kept
  // template keys, the image size override, the object's kept keys.
  std::string canonical() const;

 private:
  nlohmann::json root_;    // the template with its objects replaced by the kept keys
  nlohmann::json camera_;  // the "camera" value, or null for the default fit camera
  Scene base_;             // the parsed template, without objects
  MeshLoadOptions mesh_options_;
  int material_ = 0;
  glm::mat4 model_{1.0f};
};

// The camera turned by `angle_deg` about the vertical axis through its target: the eye moves
// on the horizontal circle around the target, counter-clockwise seen from above (+Y), so at
// 90° a fit camera looks from +X; target, up, fovy, near and far stay. Computed in double from
// the float camera, rounded to float; 0° returns the camera unchanged. A calibrated camera
// (intrinsics) has no orbit: any other angle throws InputError.
Camera orbit_camera(const Camera& camera, double angle_deg);

// The embedded default template for fastshade batch; scenes/batch.json holds the same text. A
// scene in its own right: its one object (a sphere, which each mesh replaces) previews the look.
const char* default_batch_template_json();

}  // namespace fastshade
