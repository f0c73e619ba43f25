// Cameras: explicit ones are checked, "fit" ones frame the objects' world-space bounding sphere.
#include "io/scene_camera.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "fastshade/error.h"

namespace fastshade {
namespace {

using json_path::kAnyNumber;
using json_path::kInf;
using json_path::kPositive;
using json_path::Range;
using json_path::Reader;
using nlohmann::json;

constexpr double kFitMargin = 1.1;  // near/far sit 1.1 radii in front of/behind the centre
constexpr double kDefaultFitDistance = 3.0;
constexpr double kDefaultFovyDeg = 45.0;
const Range kFovyRange{0, 180, true, true};

struct Sphere {
  glm::dvec3 center{0.0};
  double radius = 0.0;
  bool empty = true;  // no vertices at all
};

// Centre = centre of the AABB of all transformed vertices; radius = the farthest of them.
// Two passes over the vertices, in double, each vertex transformed by its object's model.
Sphere bounding_sphere(const std::vector<Object>& objects) {
  glm::dvec3 lo(kInf), hi(-kInf);
  auto for_each_vertex = [&](auto&& visit) {
    for (const Object& object : objects) {
      if (!object.mesh) continue;
      const glm::dmat4 model(object.model);
      for (const glm::vec3& p : object.mesh->positions)
        visit(glm::dvec3(model * glm::dvec4(glm::dvec3(p), 1.0)));
    }
  };
  Sphere sphere;
  for_each_vertex([&](const glm::dvec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
    sphere.empty = false;
  });
  if (sphere.empty) return sphere;
  sphere.center = 0.5 * (lo + hi);
  double r2 = 0.0;
  for_each_vertex([&](const glm::dvec3& p) {
    const glm::dvec3 d = p - sphere.center;
    r2 = std::max(r2, glm::dot(d, d));
  });
  sphere.radius = std::sqrt(r2);
  return sphere;
}

Camera fit_sphere(const Sphere& sphere, double distance, double fovy_deg) {
  Camera camera;
  camera.target = glm::vec3(sphere.center);
  camera.eye = glm::vec3(sphere.center + glm::dvec3(0.0, 0.0, distance * sphere.radius));
  camera.up = glm::vec3(0, 1, 0);
  camera.fovy_deg = float(fovy_deg);
  camera.near = float((distance - kFitMargin) * sphere.radius);
  camera.far = float((distance + kFitMargin) * sphere.radius);
  return camera;
}

// The checks every camera must pass, on the float values the renderer will use; returns the
// key at fault and the problem, or an empty key.
std::pair<std::string, std::string> camera_problem(const Camera& c) {
  const glm::dvec3 view = glm::dvec3(c.target) - glm::dvec3(c.eye);
  const glm::dvec3 up(c.up);
  if (!(c.fovy_deg > 0.0f && c.fovy_deg < 180.0f))
    return {"fovy_deg", "expected a number in (0, 180), got " + json_path::format_number(c.fovy_deg)};
  if (!(std::isfinite(c.near) && c.near > 0.0f))
    return {"near", "expected a number > 0, got " + json_path::format_number(c.near)};
  if (!(std::isfinite(c.far) && c.far > c.near))
    return {"far", "must be greater than near (" + json_path::format_number(c.near) + "), got " +
                       json_path::format_number(c.far)};
  if (!(glm::dot(view, view) > 0.0)) return {"target", "must differ from eye"};
  if (!(glm::dot(up, up) > 0.0)) return {"up", "must not be the zero vector"};
  // sin of the angle between up and the view direction; 1e-6 rad is "parallel".
  const double sine = glm::length(glm::cross(glm::normalize(view), glm::normalize(up)));
  if (!(sine > 1e-6)) return {"up", "must not be parallel to the view direction (target - eye)"};
  return {};
}

// OpenCV's camera axes (y down, z forward) to OpenGL's (y up, looking down -z): a half turn
// about x, applied on the camera side of the pose.
const glm::dmat4 kOpenCvToOpenGl(1, 0, 0, 0, 0, -1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1);

// A pose whose rotation part is orthonormal within this (the rounding of a calibration tool's
// printed digits; 1e-4 is 0.006 degrees) and whose determinant is +1 is rigid.
constexpr double kRigidTolerance = 1e-4;

// The checks of a calibrated camera, as camera_problem() for the explicit one.
std::pair<std::string, std::string> calibrated_problem(const Intrinsics& k, const glm::dmat4& pose, float near,
                                                       float far) {
  const std::pair<const char*, double> focal[] = {{"intrinsics.fx", k.fx}, {"intrinsics.fy", k.fy}};
  for (const auto& [key, value] : focal)
    if (!(std::isfinite(value) && value > 0.0))
      return {key, "expected a finite number > 0 (pixels), got " + json_path::format_number(value)};
  const std::pair<const char*, double> centre[] = {{"intrinsics.cx", k.cx}, {"intrinsics.cy", k.cy}};
  for (const auto& [key, value] : centre)
    if (!std::isfinite(value))
      return {key, "expected a finite number (pixels), got " + json_path::format_number(value)};
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(pose[c][r])) return {"pose", "has a non-finite entry in row " + std::to_string(r)};
  if (pose[0][3] != 0.0 || pose[1][3] != 0.0 || pose[2][3] != 0.0 || pose[3][3] != 1.0)
    return {"pose", "the last row must be [0, 0, 0, 1]"};
  const glm::dmat3 rotation(pose);
  const glm::dmat3 gram = glm::transpose(rotation) * rotation;
  double worst = 0.0;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) worst = std::max(worst, std::fabs(gram[c][r] - (c == r ? 1.0 : 0.0)));
  if (!(worst <= kRigidTolerance) || !(glm::determinant(rotation) > 0.0))
    return {"pose", "not a rigid transform (its 3x3 part must be a rotation: orthonormal within 1e-4, "
                    "determinant +1; R^T R deviates by " + json_path::format_number(worst) + ")"};
  if (!(std::isfinite(near) && near > 0.0f))
    return {"near", "expected a number > 0, got " + json_path::format_number(near)};
  if (!(std::isfinite(far) && far > near))
    return {"far", "must be greater than near (" + json_path::format_number(near) + "), got " +
                       json_path::format_number(far)};
  return {};
}

Camera make_calibrated(const Intrinsics& k, const glm::dmat4& pose, PoseConvention convention, float near,
                       float far) {
  Camera camera;
  camera.intrinsics = k;
  camera.camera_to_world = convention == PoseConvention::OpenCV ? pose * kOpenCvToOpenGl : pose;
  camera.near = near;
  camera.far = far;
  return camera;
}

}  // namespace

Camera look_at_camera(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up, float fovy_deg, float near,
                      float far) {
  const Camera camera{eye, target, up, fovy_deg, near, far};
  if (auto [key, problem] = camera_problem(camera); !key.empty()) throw InputError(key, problem);
  return camera;
}

void check_camera(const Camera& c) {
  if (c.intrinsics) {
    if (auto [key, problem] = calibrated_problem(*c.intrinsics, c.camera_to_world, c.near, c.far); !key.empty())
      throw InputError("camera." + key, problem);
  } else if (auto [key, problem] = camera_problem(c); !key.empty()) {
    throw InputError("camera." + key, problem);
  }
}

Camera calibrated_camera(const Intrinsics& k, const glm::dmat4& pose, PoseConvention convention, float near,
                         float far) {
  if (auto [key, problem] = calibrated_problem(k, pose, near, far); !key.empty()) throw InputError(key, problem);
  return make_calibrated(k, pose, convention, near, far);
}

Camera fit_camera(const std::vector<Object>& objects, float distance, float fovy_deg) {
  const Sphere sphere = bounding_sphere(objects);
  if (sphere.empty || !(sphere.radius > 0.0) || !std::isfinite(sphere.radius))
    throw InputError("fit camera", "the objects have no extent to frame");
  if (!(distance > kFitMargin))
    throw InputError("fit camera", "distance must be > 1.1, got " + std::to_string(distance));
  return fit_sphere(sphere, distance, fovy_deg);
}

namespace {

// {"intrinsics": {"fx", "fy", "cx", "cy"}, "pose": 4 rows of 4, "convention", "near", "far"}.
Camera parse_calibrated(const Reader& r, const json& j) {
  r.expect_object(j, "camera", {"intrinsics", "pose", "convention", "near", "far"});
  const json& k_json = j.at("intrinsics");
  if (!k_json.is_object()) r.fail("camera.intrinsics", "expected an object, got " + json_path::describe(k_json));
  r.expect_object(k_json, "camera.intrinsics", {"fx", "fy", "cx", "cy"});
  Intrinsics k;
  for (auto [key, field] : {std::pair{"fx", &Intrinsics::fx}, std::pair{"fy", &Intrinsics::fy},
                            std::pair{"cx", &Intrinsics::cx}, std::pair{"cy", &Intrinsics::cy}}) {
    const std::string path = json_path::child("camera.intrinsics", key);
    const json* v = Reader::find(k_json, key);
    if (!v) r.fail(path, "missing (K needs fx, fy, cx and cy, in pixels)");
    k.*field = r.number(*v, path, kAnyNumber);
  }
  const json* convention_json = Reader::find(j, "convention");
  if (!convention_json)
    r.fail("camera.convention", "missing (\"opencv\": y down, z forward; \"opengl\": y up, looking down -z)");
  const PoseConvention convention =
      r.choice(*convention_json, "camera.convention", {"opencv", "opengl"}) == 0 ? PoseConvention::OpenCV
                                                                                 : PoseConvention::OpenGL;
  glm::dmat4 pose(1.0);
  if (const json* pose_json = Reader::find(j, "pose")) {
    const json& rows = r.expect_array(*pose_json, "camera.pose");
    if (rows.size() != 4)
      r.fail("camera.pose", "expected 4 rows of 4 numbers (row-major), got " + std::to_string(rows.size()) + " rows");
    for (int row = 0; row < 4; ++row) {
      const std::string row_path = json_path::element("camera.pose", row);
      const json& cells = r.expect_array(rows[row], row_path);
      if (cells.size() != 4) r.fail(row_path, "expected 4 numbers, got " + std::to_string(cells.size()));
      for (int col = 0; col < 4; ++col)
        pose[col][row] = r.number(cells[col], json_path::element(row_path, col), kAnyNumber);
    }
  }
  float near = 0.01f, far = 1000.0f;
  if (const json* v = Reader::find(j, "near")) near = float(r.number(*v, "camera.near", kPositive));
  if (const json* v = Reader::find(j, "far")) far = float(r.number(*v, "camera.far", kPositive));
  if (auto [key, problem] = calibrated_problem(k, pose, near, far); !key.empty()) r.fail("camera." + key, problem);
  return make_calibrated(k, pose, convention, near, far);
}

}  // namespace

Camera parse_camera(const Reader& r, const json* j, const std::vector<Object>& objects) {
  bool fit = j == nullptr;
  if (j) {
    if (!j->is_object()) r.fail("camera", "expected an object, got " + json_path::describe(*j));
    if (const json* f = Reader::find(*j, "fit")) fit = r.boolean(*f, "camera.fit");
  }

  Camera camera;
  if (fit) {
    double distance = kDefaultFitDistance, fovy = kDefaultFovyDeg;
    if (j) {
      r.expect_object(*j, "camera", {"fit", "distance", "fovy_deg"});
      if (const json* v = Reader::find(*j, "distance"))
        distance = r.number(*v, "camera.distance", Range{kFitMargin, kInf, true});
      if (const json* v = Reader::find(*j, "fovy_deg")) fovy = r.number(*v, "camera.fovy_deg", kFovyRange);
    }
    const Sphere sphere = bounding_sphere(objects);
    if (sphere.empty || !(sphere.radius > 0.0))
      r.fail("camera.fit", "the objects have no extent to frame");
    camera = fit_sphere(sphere, distance, fovy);
    if (auto [key, problem] = camera_problem(camera); !key.empty())
      r.fail("camera.fit", "the fitted camera is degenerate (" + key + ": " + problem +
                               "), bounding radius " + json_path::format_number(sphere.radius));
    return camera;
  }

  if (Reader::find(*j, "intrinsics")) return parse_calibrated(r, *j);
  r.expect_object(*j, "camera", {"fit", "eye", "target", "up", "fovy_deg", "near", "far", "intrinsics"});
  for (const char* key : {"eye", "target"}) {
    if (!Reader::find(*j, key))
      r.fail(json_path::child("camera", key),
             "missing (give \"eye\" and \"target\", or \"fit\": true)");
  }
  camera.eye = glm::vec3(r.vec3(j->at("eye"), "camera.eye", kAnyNumber));
  camera.target = glm::vec3(r.vec3(j->at("target"), "camera.target", kAnyNumber));
  if (const json* v = Reader::find(*j, "up")) camera.up = glm::vec3(r.vec3(*v, "camera.up", kAnyNumber));
  if (const json* v = Reader::find(*j, "fovy_deg"))
    camera.fovy_deg = float(r.number(*v, "camera.fovy_deg", kFovyRange));
  if (const json* v = Reader::find(*j, "near"))
    camera.near = float(r.number(*v, "camera.near", kPositive));
  if (const json* v = Reader::find(*j, "far"))
    camera.far = float(r.number(*v, "camera.far", kPositive));
  if (auto [key, problem] = camera_problem(camera); !key.empty())
    r.fail(json_path::child("camera", key), problem);
  return camera;
}

}  // namespace fastshade
