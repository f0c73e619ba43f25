// A calibrated camera draws where its K says: u = fx X/Z + cx, v = fy Y/Z + cy, the centre of
// pixel (0, 0) at u = v = 0; the same physical camera gives the same image in either convention,
// and K and pose equivalent to an eye/target camera give that camera's image.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "fastshade/render.h"
#include "fastshade/scene.h"

namespace fastshade {
namespace {

constexpr int kWidth = 256, kHeight = 192;

// A camera-facing square of side `side` centred at `centre` (world space), lit by ambient only
// on black: every drawn pixel is non-black.
Scene square_scene(const glm::dvec3& centre, double side) {
  const std::string json = R"({"image": {"width": 256, "height": 192, "background": [0, 0, 0]},
    "ambient": [0.5, 0.5, 0.5], "lights": [],
    "objects": [{"primitive": "plane", "size": )" + std::to_string(side) +
                           R"(, "transform": {"rotate_deg": [90, 0, 0], "translate": [)" +
                           std::to_string(centre.x) + ", " + std::to_string(centre.y) + ", " +
                           std::to_string(centre.z) + "]}}]}";
  return parse_scene(json, "square.json", ".");
}

struct Centroid {
  double u = 0, v = 0;
  long long pixels = 0;
};
Centroid drawn_centroid(const Image& image) {
  Centroid c;
  for (int v = 0; v < image.height; ++v)
    for (int u = 0; u < image.width; ++u) {
      const uint8_t* p = &image.rgb[(std::size_t(v) * image.width + u) * 3];
      if (p[0] | p[1] | p[2]) {
        c.u += u, c.v += v;
        ++c.pixels;
      }
    }
  if (c.pixels) c.u /= double(c.pixels), c.v /= double(c.pixels);
  return c;
}

Image render_with(Scene scene, const Camera& camera) {
  scene.camera = camera;
  RenderOptions o;
  o.threads = 2;
  return render(scene, o);
}

TEST(CalibratedProjection, ASquareLandsWhereKPutsIt) {
  const Intrinsics k{500.0, 450.0, 120.3, 90.7};
  const glm::dvec3 points[] = {{0.1, -0.05, 2.0}, {-0.15, 0.1, 3.0}, {0.0, 0.0, 1.5}};
  for (const glm::dvec3& p : points) {
    // The identity pose in OpenCV's convention: camera space is world space, z forward.
    const Image image = render_with(square_scene(p, 0.04), calibrated_camera(k, glm::dmat4(1.0), PoseConvention::OpenCV));
    const Centroid c = drawn_centroid(image);
    ASSERT_GT(c.pixels, 20) << "the square at z = " << p.z << " was not drawn";
    EXPECT_NEAR(c.u, k.fx * p.x / p.z + k.cx, 0.5) << "z = " << p.z;
    EXPECT_NEAR(c.v, k.fy * p.y / p.z + k.cy, 0.5) << "z = " << p.z;
    // Sharper: exactly the pixels whose centres (integer u, v) fall inside the projected square
    // (none of these squares has an edge near a centre), which half a pixel of offset would move.
    const double half = 0.02;
    const int u0 = int(std::ceil(k.fx * (p.x - half) / p.z + k.cx)), u1 = int(std::floor(k.fx * (p.x + half) / p.z + k.cx));
    const int v0 = int(std::ceil(k.fy * (p.y - half) / p.z + k.cy)), v1 = int(std::floor(k.fy * (p.y + half) / p.z + k.cy));
    EXPECT_EQ(c.pixels, static_cast<long long>(u1 - u0 + 1) * (v1 - v0 + 1)) << "z = " << p.z;
    EXPECT_DOUBLE_EQ(c.u, 0.5 * (u0 + u1)) << "z = " << p.z;
    EXPECT_DOUBLE_EQ(c.v, 0.5 * (v0 + v1)) << "z = " << p.z;
  }
}

TEST(CalibratedProjection, OpenCvAndOpenGlPosesOfOneCameraGiveOneImage) {
  const Intrinsics k{300.0, 310.0, 130.0, 95.0};
  // Camera-to-world in OpenCV axes: turned 20 degrees about y and 10 about x, 3 units back.
  const glm::dmat4 turn = glm::rotate(glm::rotate(glm::dmat4(1.0), glm::radians(20.0), glm::dvec3(0, 1, 0)),
                                      glm::radians(10.0), glm::dvec3(1, 0, 0));
  glm::dmat4 pose_cv = turn;
  pose_cv[3] = glm::dvec4(glm::dvec3(turn * glm::dvec4(0, 0, -3, 0)), 1.0);
  // The same camera in OpenGL axes: its y and z axes point the other way.
  glm::dmat4 pose_gl = pose_cv;
  pose_gl[1] = -pose_cv[1];
  pose_gl[2] = -pose_cv[2];
  const Scene scene = square_scene({0.05, 0.0, 0.2}, 0.5);
  const Image cv = render_with(scene, calibrated_camera(k, pose_cv, PoseConvention::OpenCV));
  const Image gl = render_with(scene, calibrated_camera(k, pose_gl, PoseConvention::OpenGL));
  ASSERT_GT(drawn_centroid(cv).pixels, 1000);
  EXPECT_EQ(cv.rgb, gl.rgb);
}

TEST(CalibratedProjection, KOfAnEyeTargetCameraGivesItsImage) {
  Scene scene = parse_scene(R"({"image": {"width": 256, "height": 192},
    "camera": {"eye": [0.4, 0.8, 3.5], "target": [0, 0, 0], "fovy_deg": 40, "near": 0.5, "far": 20},
    "lights": [{"direction": [0.3, 0.5, 1]}],
    "objects": [{"primitive": "icosphere", "subdivisions": 4}]})", "sphere.json", ".");
  const Camera& c = scene.camera;
  // A symmetric frustum: the principal point at the image centre (pixel centres at integers),
  // fy from the field of view, square pixels.
  const double fy = 0.5 * kHeight / std::tan(glm::radians(double(c.fovy_deg)) / 2.0);
  const Intrinsics k{fy, fy, kWidth / 2.0 - 0.5, kHeight / 2.0 - 0.5};
  const glm::dmat4 pose_gl = glm::inverse(glm::lookAt(glm::dvec3(c.eye), glm::dvec3(c.target), glm::dvec3(c.up)));
  const Image explicit_image = render_with(scene, c);
  const Image calibrated_image = render_with(scene, calibrated_camera(k, pose_gl, PoseConvention::OpenGL, c.near, c.far));
  // The matrices agree to float rounding, not bit for bit: a pixel whose centre sits on an edge
  // may flip, and a colour may move by an LSB.
  long long differ = 0, far_off = 0;
  for (std::size_t i = 0; i < explicit_image.rgb.size(); ++i) {
    const int d = std::abs(int(explicit_image.rgb[i]) - int(calibrated_image.rgb[i]));
    differ += d > 1;
    far_off += d > 40;
  }
  EXPECT_LT(differ, static_cast<long long>(explicit_image.rgb.size() / 1000)) << "channels off by more than 1 LSB";
  EXPECT_LT(far_off, 60) << "channels far off: the cameras disagree, not their rounding";
}

}  // namespace
}  // namespace fastshade
