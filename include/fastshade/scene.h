// A scene as the renderer sees it: everything resolved (meshes loaded, camera framed).
#pragma once
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "fastshade/mesh.h"

namespace fastshade {

// A calibrated pinhole camera's intrinsic matrix K, in pixels, in OpenCV's convention: a
// camera-space point (X, Y, Z), Z forward, lands at u = fx X/Z + cx, v = fy Y/Z + cy, where the
// centre of pixel (0, 0) is u = v = 0 and v grows downward.
struct Intrinsics {
  double fx = 0, fy = 0, cx = 0, cy = 0;
};

// The axes a camera-to-world pose is given in. OpenCV: x right, y down, z forward. OpenGL: x
// right, y up, looking down -z.
enum class PoseConvention { OpenCV, OpenGL };

struct Camera {
  glm::vec3 eye{0, 0, 5}, target{0, 0, 0}, up{0, 1, 0};
  float fovy_deg = 45.0f;
  float near = 0.1f, far = 100.0f;
  // A calibrated camera (calibrated_camera()): K and the camera-to-world pose in OpenGL axes, a
  // rigid transform, which replace eye, target, up and fovy_deg.
  std::optional<Intrinsics> intrinsics;
  glm::dmat4 camera_to_world{1.0};
};

// An eye/target camera, checked as the scene format checks one: throws InputError naming the
// value at fault ("target: must differ from eye", "fovy_deg: ...").
Camera look_at_camera(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up = {0, 1, 0},
                      float fovy_deg = 45.0f, float near = 0.1f, float far = 100.0f);

// A calibrated camera from K and a camera-to-world pose (4x4, a rotation and a translation) in
// either convention, seeing from `near` to `far` along its axis. Throws InputError naming the
// value at fault ("intrinsics.fx: expected a finite number > 0, got 0", "pose: not a rigid
// transform ...").
Camera calibrated_camera(const Intrinsics& k, const glm::dmat4& pose, PoseConvention convention, float near = 0.01f,
                         float far = 1000.0f);

enum class LightSpace { World, View };

struct Light {  // directional
  glm::vec3 direction{0, 0, 1};  // toward the light, unit length, in `space`
  glm::vec3 color{1, 1, 1};
  LightSpace space = LightSpace::View;
};

enum class Viewer { Infinite, Local };  // Infinite: V = (0,0,1) in view space (the paper's case)

struct Material {
  std::string name;
  glm::vec3 diffuse{0.7f};   // kd
  glm::vec3 specular{0.5f};  // ks
  double shininess = 32.0;   // Blinn-Phong exponent n, any real >= 1
};

struct Object {
  std::shared_ptr<const Mesh> mesh;
  int material = 0;  // index into Scene::materials
  glm::mat4 model{1.0f};
};

enum class Cull { None, Back };

struct Scene {
  int width = 640, height = 480;
  glm::vec3 background{0, 0, 0};
  Camera camera;
  std::vector<Light> lights;
  Viewer viewer = Viewer::Infinite;
  glm::vec3 ambient{0, 0, 0};
  std::vector<Material> materials;
  std::vector<Object> objects;
  Cull cull = Cull::None;
  bool two_sided = false;  // flip the normal on back faces
  std::string source;      // the scene file, for messages
};

// Limits on what a scene may ask for (also used by the command line).
inline constexpr int kMaxImageSide = 16384;

// Parses and resolves a scene file; meshes are read relative to its directory. Throws
// InputError naming the key path ("objects[2].material: no material \"gold\"").
Scene load_scene(const std::filesystem::path& path);

// The same from JSON text; `source` names it in messages, `base_dir` resolves mesh paths.
Scene parse_scene(const std::string& json_text, const std::string& source,
                  const std::filesystem::path& base_dir);

// A material checked as a scene file's is (colours finite and >= 0, shininess in [1, 1e6]);
// throws InputError naming `key` ("material.shininess: expected [1, 1e+06], got 0.5").
void check_material(const Material& material, const std::string& key = "material");

// A scene built in code, checked as a scene file is: image size, colours, lights, materials,
// objects (mesh present, finite vertices, triangle indices in range, normals one per vertex,
// material index, finite model matrix) and camera. Throws InputError naming the part at fault
// ("materials[1].shininess: expected [1, 1e+06], got 0.5", "objects[0].mesh: vertex 7 is not
// finite"). Renderer does not call it: a parsed scene is already checked.
void check_scene(const Scene& scene);

// The embedded default scene: procedural meshes only.
const char* default_scene_json();

// World-space bounding sphere framing as the "fit" camera does it (exposed for tests).
Camera fit_camera(const std::vector<Object>& objects, float distance, float fovy_deg);

}  // namespace fastshade
