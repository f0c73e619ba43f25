// fastshade.Material, Camera and Scene: a scene built in code (or read from the CLI's JSON).
#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <string>

#include <glm/geometric.hpp>
#include <nanobind/ndarray.h>
#include <nanobind/stl/array.h>
#include <nanobind/stl/filesystem.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/shared_ptr.h>
#include <nanobind/stl/string.h>

#include "bindings.h"
#include "fastshade/error.h"
#include "fastshade/scene.h"
#include "scene_binding.h"

namespace nb = nanobind;

namespace fastshade::python {

namespace {

using Vec3 = std::array<double, 3>;
using Matrix4 = nb::ndarray<const double, nb::shape<4, 4>, nb::c_contig, nb::device::cpu>;
using Matrix3 = nb::ndarray<const double, nb::shape<3, 3>, nb::c_contig, nb::device::cpu>;

glm::vec3 to_vec3(const Vec3& v) { return glm::vec3(float(v[0]), float(v[1]), float(v[2])); }

// Row-major numpy 4x4 to glm's column-major matrix.
glm::dmat4 to_dmat4(const Matrix4& a) {
  glm::dmat4 m;
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 4; ++col) m[col][row] = a(row, col);
  return m;
}

Material make_material(const Vec3& diffuse, const Vec3& specular, double shininess) {
  const Material material{.name = "", .diffuse = to_vec3(diffuse), .specular = to_vec3(specular), .shininess = shininess};
  check_material(material);
  return material;
}

}  // namespace

Scene resolved_scene(const PyScene& s) {
  Scene scene = s.scene;
  if (s.camera.fit) {
    if (scene.objects.empty()) throw InputError("objects", "expected at least one object");
    scene.camera = fit_camera(scene.objects, s.camera.fit_distance, s.camera.fit_fovy_deg);
  } else {
    scene.camera = s.camera.camera;
  }
  check_scene(scene);
  return scene;
}

void bind_scene(nb::module_& m) {
  nb::class_<Material>(m, "Material", "Blinn-Phong material: colour = kd (N.L) + ks (N.H)^shininess per light.")
      .def(nb::new_([](const Vec3& diffuse, const Vec3& specular, double shininess) {
             return make_material(diffuse, specular, shininess);
           }),
           nb::arg("diffuse") = Vec3{0.7, 0.7, 0.7}, nb::arg("specular") = Vec3{0.5, 0.5, 0.5},
           nb::arg("shininess") = 32.0)
      .def_prop_ro("diffuse", [](const Material& x) { return Vec3{x.diffuse.r, x.diffuse.g, x.diffuse.b}; })
      .def_prop_ro("specular", [](const Material& x) { return Vec3{x.specular.r, x.specular.g, x.specular.b}; })
      .def_prop_ro("shininess", [](const Material& x) { return x.shininess; });

  nb::class_<PyCamera>(m, "Camera", "A camera: fitted to the objects, eye/target, or calibrated (K and a pose).")
      .def_static(
          "fit",
          [](float distance, float fovy_deg) {
            if (!(distance > 1.1f)) throw InputError("distance", "expected > 1.1 (bounding radii), got " + std::to_string(distance));
            if (!(fovy_deg > 0.0f && fovy_deg < 180.0f)) throw InputError("fovy_deg", "expected (0, 180)");
            PyCamera c;
            c.fit = true, c.fit_distance = distance, c.fit_fovy_deg = fovy_deg;
            return c;
          },
          nb::arg("distance") = 2.5f, nb::arg("fovy_deg") = 45.0f,
          "Frames the objects' bounding sphere from +Z at `distance` radii (resolved when rendered).")
      .def_static(
          "look_at",
          [](const Vec3& eye, const Vec3& target, const Vec3& up, float fovy_deg, float near, float far) {
            return PyCamera{.camera = look_at_camera(to_vec3(eye), to_vec3(target), to_vec3(up), fovy_deg, near, far),
                            .fit = false};
          },
          nb::arg("eye"), nb::arg("target"), nb::arg("up") = Vec3{0, 1, 0}, nb::arg("fovy_deg") = 45.0f,
          nb::arg("near") = 0.1f, nb::arg("far") = 100.0f)
      .def_static(
          "from_intrinsics",
          [](Matrix3 k, std::optional<Matrix4> pose, const std::string& convention, float near, float far) {
            if (k(2, 0) != 0.0 || k(2, 1) != 0.0 || k(2, 2) != 1.0 || k(1, 0) != 0.0 || k(0, 1) != 0.0)
              throw InputError("K", "expected [[fx, 0, cx], [0, fy, cy], [0, 0, 1]] (no skew)");
            PoseConvention pc;
            if (convention == "opencv") pc = PoseConvention::OpenCV;
            else if (convention == "opengl") pc = PoseConvention::OpenGL;
            else throw InputError("convention", "expected 'opencv' or 'opengl', got '" + convention + "'");
            const Intrinsics intrinsics{k(0, 0), k(1, 1), k(0, 2), k(1, 2)};
            return PyCamera{.camera = calibrated_camera(intrinsics, pose ? to_dmat4(*pose) : glm::dmat4(1.0), pc, near, far),
                            .fit = false};
          },
          nb::arg("K"), nb::arg("pose").none() = nb::none(), nb::arg("convention") = "opencv",
          nb::arg("near") = 0.01f, nb::arg("far") = 1000.0f,
          "A calibrated pinhole camera: K in pixels (OpenCV's: pixel (0, 0)'s centre at u = v = 0), "
          "pose camera-to-world (4x4, rigid) in 'opencv' (y down, z forward) or 'opengl' axes.");

  nb::class_<PyScene>(m, "Scene", "Objects, materials, lights and a camera; image size in pixels.")
      .def(nb::new_([](int width, int height, const Vec3& background, const Vec3& ambient) {
             PyScene s;
             s.scene.width = width, s.scene.height = height;
             s.scene.background = to_vec3(background), s.scene.ambient = to_vec3(ambient);
             s.scene.materials.clear();
             s.scene.source = "scene";
             for (auto [key, side] : {std::pair{"width", width}, std::pair{"height", height}})
               if (side < 1 || side > kMaxImageSide)
                 throw InputError(key, "expected 1 to " + std::to_string(kMaxImageSide) + ", got " + std::to_string(side));
             return s;
           }),
           nb::arg("width"), nb::arg("height"), nb::arg("background") = Vec3{0, 0, 0},
           nb::arg("ambient") = Vec3{0, 0, 0})
      .def_static(
          "from_file",
          [](const std::filesystem::path& path) {
            PyScene s;
            {
              nb::gil_scoped_release unlocked;
              s.scene = load_scene(path);
            }
            s.camera = PyCamera{.camera = s.scene.camera, .fit = false};
            return s;
          },
          nb::arg("path"), "Reads a scene file of the command line (docs/scene-format.md).")
      .def(
          "add_object",
          [](PyScene& s, std::shared_ptr<Mesh> mesh, std::optional<Material> material, std::optional<Matrix4> transform) {
            Object object;
            object.mesh = std::move(mesh);
            s.scene.materials.push_back(material ? *material : Material{});
            object.material = static_cast<int>(s.scene.materials.size()) - 1;
            if (transform) object.model = glm::mat4(to_dmat4(*transform));
            s.scene.objects.push_back(object);
            return static_cast<int>(s.scene.objects.size()) - 1;
          },
          nb::arg("mesh"), nb::arg("material").none() = nb::none(), nb::arg("transform").none() = nb::none(),
          "Adds an object (a 4x4 row-major model matrix, default identity); returns its index, the object id.")
      .def(
          "add_light",
          [](PyScene& s, const Vec3& direction, const Vec3& color, const std::string& space) {
            const glm::dvec3 d(direction[0], direction[1], direction[2]);
            const double length = glm::length(d);
            if (!(length > 0.0 && std::isfinite(length))) throw InputError("direction", "expected a finite non-zero vector");
            Light light;
            light.direction = glm::vec3(d / length);
            light.color = to_vec3(color);
            if (space == "view") light.space = LightSpace::View;
            else if (space == "world") light.space = LightSpace::World;
            else throw InputError("space", "expected 'view' or 'world', got '" + space + "'");
            s.scene.lights.push_back(light);
          },
          nb::arg("direction"), nb::arg("color") = Vec3{1, 1, 1}, nb::arg("space") = "view",
          "A directional light: `direction` toward the light, in view space (moves with the camera) or world space.")
      .def_rw("camera", &PyScene::camera)
      .def_prop_ro("width", [](const PyScene& s) { return s.scene.width; })
      .def_prop_ro("height", [](const PyScene& s) { return s.scene.height; })
      .def_prop_ro("object_count", [](const PyScene& s) { return s.scene.objects.size(); });
}

}  // namespace fastshade::python
