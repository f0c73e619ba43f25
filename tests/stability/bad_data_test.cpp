// NaN, infinity, zero-length and non-unit data on the way into the renderer, for every
// method: file data is rejected with one clear error naming the file (docs/PIPELINE.md, "Bad
// input"); in-memory meshes through the API are checked at render() (normals) or have the
// triangles on a non-finite vertex dropped and counted (positions); non-unit file normals are
// normalised, so they render exactly as unit ones.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "fastshade/error.h"
#include "fastshade/render.h"
#include "fastshade/scene.h"
#include "io/io_test_util.h"
#include "stability/stability_harness.h"

namespace fastshade::stability {
namespace {

using fastshade::testing::ScratchDir;

// A scene with one mesh file, the suite's colours, a fitted camera; `extra` adds object keys.
std::string scene_with_mesh(const std::string& file, const std::string& extra = "") {
  return R"({"image": {"width": 48, "height": 48, "background": [0.1, 0.1, 0.1]}, "ambient": [0.15, 0.15, 0.15],
             "lights": [{"direction": [0.3, 0.2, 1]}],
             "materials": {"m": {"diffuse": 0.35, "specular": 0.5, "shininess": 37.5}},
             "objects": [{"mesh": ")" + file + "\"" + extra + "}]}";
}

// A square of two triangles facing +z, with a normal line per vertex (OBJ "vn").
std::string square_obj(const std::string& normals) {
  return "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n" + normals + "f 1//1 2//2 3//3\nf 1//1 3//3 4//4\n";
}

void expect_scene_error(const ScratchDir& dir, const std::string& scene_json, const std::string& needle) {
  try {
    parse_scene(scene_json, "scene.json", dir.path());
    FAIL() << "accepted; expected an error naming '" << needle << "'";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(needle), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << "one line: " << what;
  }
}

TEST(StabilityBadData, NonFiniteFileDataIsRejectedWithAClearError) {
  ScratchDir dir;
  const std::string unit = "vn 0 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\n";
  dir.write("nan_normal.obj", square_obj("vn 0 0 1\nvn nan 0 1\nvn 0 0 1\nvn 0 0 1\n"));
  dir.write("inf_normal.obj", square_obj("vn 0 0 1\nvn 0 -inf 1\nvn 0 0 1\nvn 0 0 1\n"));
  dir.write("nan_position.obj", "v -1 -1 0\nv 1 nan 0\nv 1 1 0\nf 1 2 3\n");
  dir.write("inf_position.off", "OFF\n3 1 0\n-1 -1 0\n1 -1 inf\n1 1 0\n3 0 1 2\n");
  for (const char* mode : {"", R"(, "normals": "file")"}) {
    expect_scene_error(dir, scene_with_mesh("nan_normal.obj", mode),
                       "nan_normal.obj: line 6: non-finite number 'nan' in a normal");
    expect_scene_error(dir, scene_with_mesh("inf_normal.obj", mode),
                       "inf_normal.obj: line 6: non-finite number '-inf' in a normal");
  }
  expect_scene_error(dir, scene_with_mesh("nan_position.obj"), "nan_position.obj: line 2: non-finite number 'nan'");
  expect_scene_error(dir, scene_with_mesh("inf_position.off"), "inf_position.off: line 4: non-finite number 'inf'");
  // A number a float cannot hold is infinity to the renderer: rejected the same way.
  dir.write("huge.obj", square_obj("vn 0 0 1\nvn 0 0 1e39\nvn 0 0 1\nvn 0 0 1\n"));
  expect_scene_error(dir, scene_with_mesh("huge.obj"), "huge.obj");
}

// Zero-length file normals: an error when the file's normals are asked for, recomputed by
// default; non-unit ones are normalised: scaled by powers of two (so that normalising is exact
// in float), the image is byte for byte the unit normals' one.
TEST(StabilityBadData, ZeroLengthAndNonUnitFileNormals) {
  ScratchDir dir;
  dir.write("unit.obj", square_obj("vn 0.6 0 0.8\nvn 0 0.6 0.8\nvn -0.6 0 0.8\nvn 0 -0.6 0.8\n"));
  dir.write("scaled.obj", square_obj("vn 4.8 0 6.4\nvn 0 0.0005859375 0.00078125\n"
                                     "vn -629145.6 0 838860.8\nvn 0 -0.3 0.4\n"));
  dir.write("zero.obj", square_obj("vn 0.3 0 1\nvn 0 0 0\nvn -0.3 0 1\nvn 0 -0.3 1\n"));
  expect_scene_error(dir, scene_with_mesh("zero.obj", R"(, "normals": "file")"), "zero.obj");
  const Scene unit = parse_scene(scene_with_mesh("unit.obj"), "scene.json", dir.path());
  const Scene scaled = parse_scene(scene_with_mesh("scaled.obj"), "scene.json", dir.path());
  const Scene zero = parse_scene(scene_with_mesh("zero.obj"), "scene.json", dir.path());
  for (const MethodConfig& config : method_configs()) {
    const Image a = render(unit, config.options), b = render(scaled, config.options);
    EXPECT_EQ(a.rgb, b.rgb) << config.label << ": non-unit file normals must render as unit ones";
    const Case recomputed{"zero-length file normals, recomputed", zero};
    expect_plausible(recomputed, render(zero, config.options), config.label);
  }
}

// Positions: triangles on a NaN or infinite vertex are dropped and counted, the rest render
// as if those triangles were not there.
TEST(StabilityBadData, NonFinitePositionsInMemoryAreDroppedAndCounted) {
  Scene clean = base_scene(64, 64, 37.5, glm::vec3(0.3f, 0.2f, 1.0f));
  pixel_camera(clean);
  Mesh mesh = grid_mesh(4, 4, {-30, -30}, {30, 30}, dome(half_vector(clean), 0.4));
  Scene bad = clean;
  add_object(clean, mesh);
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  const uint32_t first = uint32_t(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), {{nan, 0, 0}, {0, inf, 0}, {0, 0, -inf}});
  mesh.normals.insert(mesh.normals.end(), 3, glm::vec3(0, 0, 1));
  // Each bad vertex joined to two good ones: three triangles to drop.
  for (uint32_t i = 0; i < 3; ++i) mesh.triangles.push_back({first + i, 0, 6});
  add_object(bad, std::move(mesh));
  for (const MethodConfig& config : method_configs()) {
    RenderStats clean_stats, bad_stats;
    const Image a = render(clean, config.options, 1, &clean_stats);
    const Image b = render(bad, config.options, 1, &bad_stats);
    EXPECT_EQ(bad_stats.triangles_dropped, clean_stats.triangles_dropped + 3) << config.label;
    EXPECT_EQ(a.rgb, b.rgb) << config.label;
  }
}

// Normals: a zero, NaN or infinite normal in a mesh handed to render() is one clear error
// naming the mesh and the vertex, as load_mesh gives for files; finite ones of any length are
// scaled to unit length (in float, 1e-30 would normalise to infinity and 1e30 to zero).
TEST(StabilityBadData, UnusableNormalsInMemoryAreRejected) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  for (glm::vec3 bad : {glm::vec3(0.0f), glm::vec3(nan, 0, 1), glm::vec3(0, inf, 1)}) {
    Scene scene = base_scene(32, 32, 37.5, glm::vec3(0, 0, 1));
    pixel_camera(scene);
    Mesh mesh = grid_mesh(2, 2, {-10, -10}, {10, 10}, [](double, double) { return glm::vec3(0, 0, 1); });
    mesh.source = "memory mesh";
    mesh.normals[4] = bad;
    add_object(scene, std::move(mesh));
    for (const MethodConfig& config : method_configs()) {
      try {
        render(scene, config.options);
        ADD_FAILURE() << config.label << ": a mesh with normal (" << bad.x << ", " << bad.y << ", " << bad.z
                      << ") rendered";
      } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("memory mesh: vertex 4"), std::string::npos) << e.what();
      }
    }
  }
  Scene unit = base_scene(32, 32, 37.5, glm::vec3(0.3f, 0.2f, 1.0f));
  pixel_camera(unit);
  Scene scaled = unit;
  const Mesh mesh = grid_mesh(2, 2, {-10, -10}, {10, 10}, dome(half_vector(unit), 0.3));
  Mesh tiny = mesh, huge = mesh;
  for (glm::vec3& n : tiny.normals) n *= 1e-30f;
  for (glm::vec3& n : huge.normals) n *= 1e30f;
  add_object(unit, mesh);
  add_object(scaled, tiny);
  add_object(scaled, huge, glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -1)));
  for (const MethodConfig& config : method_configs()) {
    const Case c{"normals of length 1e-30 and 1e30", scaled};
    expect_plausible(c, render(scaled, config.options), config.label);
    Scene tiny_only = unit;
    tiny_only.objects[0].mesh = std::make_shared<const Mesh>(tiny);
    EXPECT_LE(max_difference(render(unit, config.options), render(tiny_only, config.options)), 1) << config.label;
  }
}

}  // namespace
}  // namespace fastshade::stability
