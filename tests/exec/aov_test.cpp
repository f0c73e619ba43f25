// AOVs (include/fastshade/image.h): depth against analytic values, ids against the tests'
// brute-force rasterizer, and the promises: colour unchanged, every drawn pixel identified,
// the same buffers for any thread count and tile size.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <string>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "fastshade/primitives.h"
#include "fastshade/render.h"
#include "fastshade/scene.h"
#include "front/vertex_stage.h"
#include "front/vertex_transform.h"
#include "support/snapped_hit.h"

namespace fastshade {
namespace {

constexpr AovSet kAllAovs{true, true, true, true};

struct Rendered {
  Image color;
  AovImages aovs;
  RenderStats stats;
};

Rendered render_aovs(const Scene& scene, RenderOptions options, const AovSet& which = kAllAovs) {
  Rendered r;
  Renderer renderer(scene, options);
  renderer.render_frame(r.color, which, r.aovs);
  r.stats = renderer.last_stats();
  return r;
}

Scene one_object_scene(Mesh mesh, const glm::mat4& model, const Camera& camera, int width, int height) {
  Scene scene;
  scene.width = width;
  scene.height = height;
  scene.camera = camera;
  scene.materials.push_back(Material{});
  scene.lights.push_back(Light{});
  scene.objects.push_back({std::make_shared<Mesh>(std::move(mesh)), 0, model});
  return scene;
}

// A plane square to the viewing axis, seen from an oblique direction: depth is the camera's
// distance to it at every drawn pixel, the normal the plane's, in world space.
TEST(Aov, DepthAndNormalOfAPlaneSquareToTheView) {
  const glm::vec3 axis = glm::normalize(glm::vec3(1, 2, 2));
  const float distance = 3.0f;
  // make_plane's normal is +Y: turned onto `axis`.
  const glm::vec3 y(0, 1, 0);
  const glm::mat4 model =
      glm::rotate(glm::mat4(1.0f), std::acos(glm::dot(y, axis)), glm::normalize(glm::cross(y, axis)));
  const Scene scene = one_object_scene(make_plane(2.0f, 3), model,
                                       look_at_camera(distance * axis, glm::vec3(0), {0, 1, 0}, 40.0f), 96, 80);
  const Rendered r = render_aovs(scene, RenderOptions{.threads = 2, .tile_px = 16});
  long long drawn = 0;
  for (std::size_t i = 0; i < r.aovs.depth.size(); ++i) {
    if (r.aovs.triangle_id[i] < 0) {
      ASSERT_EQ(r.aovs.depth[i], 0.0f) << "pixel " << i;
      continue;
    }
    ++drawn;
    ASSERT_LE(std::fabs(r.aovs.depth[i] - distance) / distance, 1e-5) << "pixel " << i << ": " << r.aovs.depth[i];
    const glm::vec3 n(r.aovs.normal[3 * i], r.aovs.normal[3 * i + 1], r.aovs.normal[3 * i + 2]);
    ASSERT_LE(glm::length(n - axis), 1e-5f) << "pixel " << i;
    ASSERT_EQ(r.aovs.object_id[i], 0);
  }
  EXPECT_EQ(drawn, r.stats.covered_pixels);
  EXPECT_GT(drawn, 1000);
}

// An icosphere's facets lie between the sphere through its vertices and the sphere touching
// its nearest facet plane, so along each pixel's ray the mesh's depth lies between the two
// spheres' hits. Snapping moves each vertex by up to 1/512 px, which moves the surface along
// the ray by about that, in scene units at the hit, times the slope of the surface against the
// image plane (tan of the angle between the normal and the axis): twice that is allowed, only
// where the slope is below 4 (near the silhouette it grows without bound).
TEST(Aov, DepthOfASphereLiesBetweenItsOuterAndInnerSpheres) {
  const float radius = 1.0f, distance = 4.0f, fovy_deg = 40.0f;
  const int size = 128;
  Mesh sphere = make_icosphere(radius, 3);
  double inner = radius;
  for (const auto& t : sphere.triangles) {
    const glm::dvec3 a(sphere.positions[t[0]]), b(sphere.positions[t[1]]), c(sphere.positions[t[2]]);
    inner = std::min(inner, std::fabs(glm::dot(glm::normalize(glm::cross(b - a, c - a)), a)));
  }
  const Scene scene =
      one_object_scene(std::move(sphere), glm::mat4(1.0f), look_at_camera({0, 0, distance}, {0, 0, 0}, {0, 1, 0}, fovy_deg),
                       size, size);
  const Rendered r = render_aovs(scene, RenderOptions{.threads = 2, .tile_px = 32});
  const double tan_half = std::tan(glm::radians(double(fovy_deg)) / 2);
  const double px_per_unit_at_1 = size / (2 * tan_half);
  // The ray's hit of a sphere of radius rs about (0, 0, -distance) in view space, as its depth.
  auto hit = [&](const glm::dvec3& dir, double rs) {
    const glm::dvec3 c(0, 0, -distance);
    const double b = glm::dot(dir, c), disc = b * b - glm::dot(dir, dir) * (glm::dot(c, c) - rs * rs);
    return disc < 0 ? -1.0 : (b - std::sqrt(disc)) / glm::dot(dir, dir);
  };
  int checked = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const glm::dvec3 dir((2.0 * (x + 0.5) / size - 1.0) * tan_half, (1.0 - 2.0 * (y + 0.5) / size) * tan_half, -1.0);
      const float depth = r.aovs.depth[std::size_t(y) * size + x];
      const double outer_t = hit(dir, radius * 1.001), inner_t = hit(dir, inner);
      if (outer_t < 0) {
        ASSERT_EQ(depth, 0.0f) << "(" << x << ", " << y << ") misses the sphere";
        continue;
      }
      if (inner_t < 0) continue;
      const glm::dvec3 n = glm::normalize(outer_t * dir - glm::dvec3(0, 0, -distance));
      const double slope = std::sqrt(n.x * n.x + n.y * n.y) / n.z;
      if (slope > 4) continue;
      const double snap = 2.0 * slope * outer_t / px_per_unit_at_1 / 512;
      const double lo = hit(dir, radius) - snap, hi = inner_t + snap;
      ASSERT_GE(depth, lo * (1 - 1e-6)) << "(" << x << ", " << y << ")";
      ASSERT_LE(depth, hi * (1 + 1e-6)) << "(" << x << ", " << y << ")";
      ++checked;
    }
  EXPECT_GT(checked, 3000);
}

// Random overlapping triangles in three objects, each triangle square to the view at its own
// depth: at every pixel the ids are those of the nearest triangle the brute-force rasterizer
// (same snapping, same top-left rule) says covers it, and the depth is that triangle's.
TEST(Aov, IdsEqualTheBruteForceRasterizer) {
  const int width = 96, height = 72, per_object = 40, objects = 3;
  std::mt19937 rng(7);
  std::vector<int> depth_rank(per_object * objects);
  std::iota(depth_rank.begin(), depth_rank.end(), 0);
  std::shuffle(depth_rank.begin(), depth_rank.end(), rng);
  std::uniform_real_distribution<float> u(-1.1f, 1.1f);  // a little beyond the frustum's sides
  Scene scene;
  scene.width = width;
  scene.height = height;
  scene.camera = look_at_camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60.0f, 0.1f, 100.0f);
  scene.materials.push_back(Material{});
  const float tan_y = std::tan(glm::radians(30.0f)), tan_x = tan_y * width / height;
  std::vector<float> depth_of;
  for (int o = 0; o < objects; ++o) {
    Mesh mesh;
    mesh.source = "random " + std::to_string(o);
    for (int t = 0; t < per_object; ++t) {
      const float z = 2.0f + 0.05f * depth_rank[o * per_object + t];
      depth_of.push_back(z);
      for (int v = 0; v < 3; ++v) mesh.positions.push_back({u(rng) * tan_x * z, u(rng) * tan_y * z, -z});
      const uint32_t base = static_cast<uint32_t>(t * 3);
      mesh.triangles.push_back({base, base + 1, base + 2});
    }
    recompute_normals(mesh);
    scene.objects.push_back({std::make_shared<Mesh>(std::move(mesh)), 0, glm::mat4(1.0f)});
  }
  // Clip positions exactly as the vertex stage computes them (its scalar reference).
  const ViewTransform xf = view_transform(scene);
  VertexTransform transform;
  transform.model_view = xf.view * glm::mat4(1.0f);
  transform.proj = xf.proj;
  transform.viewport = make_viewport(width, height);
  std::vector<std::array<glm::vec4, 3>> clip;
  for (const Object& object : scene.objects) {
    const std::size_t n = object.mesh->positions.size();
    std::vector<glm::vec4> c(n);
    std::vector<ScreenVertex> screen(n);
    std::vector<uint8_t> flags(n);
    transform_vertices_scalar(transform, object.mesh->positions.data(), nullptr, n,
                              {c.data(), screen.data(), flags.data(), nullptr, nullptr});
    for (const auto& t : object.mesh->triangles) clip.push_back({c[t[0]], c[t[1]], c[t[2]]});
  }
  for (int tile : {8, 64}) {
    const Rendered r = render_aovs(scene, RenderOptions{.threads = 2, .tile_px = tile});
    int drawn = 0;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        int nearest = -1;
        for (int i = 0; i < int(clip.size()); ++i)
          if (test::snapped_hit(clip[i], x, y, width, height) && (nearest < 0 || depth_of[i] < depth_of[nearest])) nearest = i;
        const std::size_t at = std::size_t(y) * width + x;
        const std::string where = "tile " + std::to_string(tile) + " (" + std::to_string(x) + ", " + std::to_string(y) + ")";
        ASSERT_EQ(r.aovs.object_id[at], nearest < 0 ? -1 : nearest / per_object) << where;
        ASSERT_EQ(r.aovs.triangle_id[at], nearest < 0 ? -1 : nearest % per_object) << where;
        if (nearest < 0) continue;
        ++drawn;
        ASSERT_LE(std::fabs(r.aovs.depth[at] - depth_of[nearest]) / depth_of[nearest], 1e-5) << where;
      }
    EXPECT_GT(drawn, width * height / 2);
  }
}

Scene default_scene() { return parse_scene(default_scene_json(), "default", "."); }

long long count_ids(const std::vector<int32_t>& ids) {
  return std::count_if(ids.begin(), ids.end(), [](int32_t id) { return id >= 0; });
}

// For every method (and Gouraud's split triangles): the colour is the one without AOVs, byte
// for byte, and every pixel the frame counts as drawn has ids, a depth and a unit normal.
TEST(Aov, ColourUnchangedAndEveryDrawnPixelIdentified) {
  const Scene scene = default_scene();
  std::vector<RenderOptions> configs;
  for (const auto& [method, name] : OptionSpellings<ShadingMethod>::kValues)
    configs.push_back(RenderOptions{.threads = 2, .method = method});
  configs.push_back(RenderOptions{.threads = 2, .method = ShadingMethod::Gouraud, .gouraud = GouraudMode::Sierpinski});
  configs.push_back(RenderOptions{.threads = 2, .method = ShadingMethod::Phong, .hidden_faces = HiddenFaces::Draw});
  for (const RenderOptions& options : configs) {
    const std::string what = options.to_string();
    RenderStats stats;
    const Image plain = render(scene, options, 1, &stats);
    const Rendered r = render_aovs(scene, options);
    EXPECT_TRUE(plain.rgb == r.color.rgb) << what;
    EXPECT_EQ(count_ids(r.aovs.triangle_id), stats.covered_pixels) << what;
    EXPECT_EQ(count_ids(r.aovs.object_id), stats.covered_pixels) << what;
    for (std::size_t i = 0; i < r.aovs.depth.size(); ++i) {
      const bool drawn = r.aovs.triangle_id[i] >= 0;
      ASSERT_EQ(r.aovs.depth[i] > 0.0f, drawn) << what << " pixel " << i;
      const glm::vec3 n(r.aovs.normal[3 * i], r.aovs.normal[3 * i + 1], r.aovs.normal[3 * i + 2]);
      ASSERT_NEAR(glm::length(n), drawn ? 1.0f : 0.0f, 1e-5f) << what << " pixel " << i;
    }
  }
}

TEST(Aov, OnlyTheAskedBuffersAreFilled) {
  const Rendered r = render_aovs(default_scene(), RenderOptions{.threads = 1}, AovSet{.depth = true});
  EXPECT_EQ(r.aovs.depth.size(), std::size_t(r.color.width) * r.color.height);
  EXPECT_TRUE(r.aovs.normal.empty());
  EXPECT_TRUE(r.aovs.triangle_id.empty());
  EXPECT_TRUE(r.aovs.object_id.empty());
  // A renderer that drew AOVs draws a frame without them as a fresh one does.
  Renderer renderer(default_scene(), RenderOptions{.threads = 1});
  Image with, without;
  AovImages aovs;
  renderer.render_frame(with, kAllAovs, aovs);
  renderer.render_frame(without, AovSet{}, aovs);
  EXPECT_TRUE(with.rgb == without.rgb);
  EXPECT_TRUE(aovs.depth.empty() && aovs.triangle_id.empty());
}

TEST(Aov, BitIdenticalForAnyThreadCountAndTileSize) {
  const Scene scene = default_scene();
  const Rendered first = render_aovs(scene, RenderOptions{.threads = 1, .tile_px = 8});
  for (int threads : {1, 2, 4})
    for (int tile : {8, 64, 256}) {
      const Rendered r = render_aovs(scene, RenderOptions{.threads = threads, .tile_px = tile});
      const std::string what = std::to_string(threads) + " threads, tile " + std::to_string(tile);
      EXPECT_TRUE(r.aovs.depth == first.aovs.depth) << what;
      EXPECT_TRUE(r.aovs.normal == first.aovs.normal) << what;
      EXPECT_TRUE(r.aovs.triangle_id == first.aovs.triangle_id) << what;
      EXPECT_TRUE(r.aovs.object_id == first.aovs.object_id) << what;
    }
}

}  // namespace
}  // namespace fastshade
