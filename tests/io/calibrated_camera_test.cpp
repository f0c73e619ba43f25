// Calibrated cameras in scene files and in code: K and a pose in either convention, and every
// bad value an error naming its key.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

#include "fastshade/error.h"
#include "fastshade/scene.h"

namespace fastshade {
namespace {

std::string scene_with_camera(const std::string& camera) {
  return R"({"image": {"width": 64, "height": 48}, "camera": )" + camera +
         R"(, "objects": [{"primitive": "cube"}]})";
}

// The message of the InputError the camera gets ("" and a failure if none).
std::string error_of(const std::string& camera) {
  try {
    parse_scene(scene_with_camera(camera), "scene.json", ".");
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted: " << camera;
  return "";
}

const std::string kK = R"({"fx": 50, "fy": 50, "cx": 31.5, "cy": 23.5})";
const std::string kPose = R"([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, -3], [0, 0, 0, 1]])";

TEST(CalibratedCamera, ParsesKPoseAndConvention) {
  const Scene scene = parse_scene(
      scene_with_camera(R"({"intrinsics": )" + kK + R"(, "pose": )" + kPose +
                        R"(, "convention": "opencv", "near": 0.5, "far": 20})"),
      "scene.json", ".");
  ASSERT_TRUE(scene.camera.intrinsics.has_value());
  EXPECT_EQ(scene.camera.intrinsics->fx, 50.0);
  EXPECT_EQ(scene.camera.intrinsics->cy, 23.5);
  EXPECT_EQ(scene.camera.near, 0.5f);
  EXPECT_EQ(scene.camera.far, 20.0f);
  // OpenCV's y and z axes flipped into OpenGL's; the row-major translation kept.
  EXPECT_EQ(scene.camera.camera_to_world[1][1], -1.0);
  EXPECT_EQ(scene.camera.camera_to_world[2][2], -1.0);
  EXPECT_EQ(scene.camera.camera_to_world[3][2], -3.0);
}

// docs/scene-format.md's worked example (its one jsonc block), in a scene: the camera 4 units
// back on +Z looking at the origin, so a point on the world's +X axis lands right of centre.
TEST(CalibratedCamera, DocumentedExampleParses) {
  std::ifstream in(std::filesystem::path(FASTSHADE_SOURCE_DIR) / "docs" / "scene-format.md");
  ASSERT_TRUE(in);
  const std::string doc((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t start = doc.find("```jsonc\n");
  ASSERT_NE(start, std::string::npos);
  const std::size_t end = doc.find("```", start + 9);
  ASSERT_NE(end, std::string::npos);
  const Scene scene = parse_scene(R"({"image": {"width": 640, "height": 480}, )" + doc.substr(start + 9, end - start - 9) +
                                      R"(, "objects": [{"primitive": "cube"}]})",
                                  "scene-format.md", ".");
  ASSERT_TRUE(scene.camera.intrinsics.has_value());
  EXPECT_EQ(scene.camera.intrinsics->cx, 319.5);
  // OpenGL axes after conversion: looking down -z, which is the world's -Z; eye at (0, 0, 4).
  EXPECT_EQ(scene.camera.camera_to_world[2][2], 1.0);
  EXPECT_EQ(scene.camera.camera_to_world[1][1], 1.0);
  EXPECT_EQ(scene.camera.camera_to_world[3][2], 4.0);
}

TEST(CalibratedCamera, BadValuesNameTheirKey) {
  const auto with_k = [](const std::string& k, const std::string& pose = kPose) {
    return R"({"intrinsics": )" + k + R"(, "pose": )" + pose + R"(, "convention": "opencv"})";
  };
  EXPECT_NE(error_of(with_k(R"({"fx": 0, "fy": 50, "cx": 1, "cy": 1})")).find("camera.intrinsics.fx: expected a finite number > 0"),
            std::string::npos);
  EXPECT_NE(error_of(with_k(R"({"fx": 50, "fy": -2, "cx": 1, "cy": 1})")).find("camera.intrinsics.fy"),
            std::string::npos);
  EXPECT_NE(error_of(with_k(R"({"fx": 50, "fy": 50, "cx": 1})")).find("camera.intrinsics.cy: missing"),
            std::string::npos);
  EXPECT_NE(error_of(with_k(R"({"fx": 50, "fy": 50, "cx": "a", "cy": 1})")).find("camera.intrinsics.cx"),
            std::string::npos);
  // A scaled rotation, a mirror, a projective last row, a wrong shape.
  EXPECT_NE(error_of(with_k(kK, R"([[2, 0, 0, 0], [0, 2, 0, 0], [0, 0, 2, 0], [0, 0, 0, 1]])"))
                .find("camera.pose: not a rigid transform"),
            std::string::npos);
  EXPECT_NE(error_of(with_k(kK, R"([[-1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])"))
                .find("camera.pose: not a rigid transform"),
            std::string::npos);
  EXPECT_NE(error_of(with_k(kK, R"([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 1, 1]])"))
                .find("camera.pose: the last row"),
            std::string::npos);
  EXPECT_NE(error_of(with_k(kK, R"([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]])")).find("camera.pose: expected 4 rows"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"intrinsics": )" + kK + "}").find("camera.convention: missing"), std::string::npos);
  EXPECT_NE(error_of(R"({"intrinsics": )" + kK + R"(, "convention": "vulkan"})").find("camera.convention"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"intrinsics": )" + kK + R"(, "convention": "opengl", "eye": [0, 0, 1]})").find("camera.eye"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"intrinsics": )" + kK + R"(, "convention": "opengl", "near": 2, "far": 1})").find("camera.far"),
            std::string::npos);
}

TEST(CalibratedCamera, InCodeTheSameChecks) {
  const glm::dmat4 identity(1.0);
  EXPECT_NO_THROW(calibrated_camera({50, 50, 31.5, 23.5}, identity, PoseConvention::OpenGL));
  EXPECT_THROW(calibrated_camera({std::numeric_limits<double>::quiet_NaN(), 50, 1, 1}, identity, PoseConvention::OpenCV),
               InputError);
  EXPECT_THROW(calibrated_camera({50, 50, std::numeric_limits<double>::infinity(), 1}, identity, PoseConvention::OpenCV),
               InputError);
  glm::dmat4 sheared(1.0);
  sheared[1][0] = 0.1;
  try {
    calibrated_camera({50, 50, 1, 1}, sheared, PoseConvention::OpenCV);
    ADD_FAILURE() << "a sheared pose was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("pose: not a rigid transform", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace fastshade
