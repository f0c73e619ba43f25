// Self-occlusion: which meshes qualify (topology and volume), and that culling the back faces
// they hide changes no pixel, on the scenes, the shared meshes from several sides (the bunny's
// holes in view among them), inward-wound meshes and objects the near plane cuts.
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "fastshade/error.h"
#include "fastshade/render.h"
#include "fastshade/scene.h"
#include "front/scene_geometry.h"
#include "front/self_occlusion.h"
#include "support/shared_models.h"

namespace fastshade {
namespace {

// An octahedron: closed, outward (counter-clockwise seen from outside), 6 vertices.
Mesh octahedron() {
  Mesh m;
  m.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  m.source = "octahedron";
  return m;
}

Mesh reversed(Mesh m) {
  for (auto& t : m.triangles) std::swap(t[1], t[2]);
  return m;
}

MeshClosure closure_of(std::vector<Mesh> meshes, glm::mat4 model = glm::mat4(1.0f)) {
  Scene scene;
  scene.materials.push_back({});
  for (Mesh& m : meshes) {
    recompute_normals(m);
    scene.objects.push_back({std::make_shared<const Mesh>(std::move(m)), 0, model});
  }
  const SceneGeometry g = flatten_scene(scene);
  std::vector<MeshClosure> c = analyze_closures(g);
  EXPECT_EQ(c.size(), g.objects.size());
  return c.front();
}

Mesh merged(const Mesh& a, const Mesh& b) {
  Mesh m = a;
  const uint32_t base = static_cast<uint32_t>(m.positions.size());
  m.positions.insert(m.positions.end(), b.positions.begin(), b.positions.end());
  for (auto t : b.triangles) m.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  return m;
}

TEST(SelfOcclusionTopology, ClosedMeshesAreSolidWithTheirWindingsSide) {
  const MeshClosure out = closure_of({octahedron()});
  EXPECT_TRUE(out.solid);
  EXPECT_TRUE(out.outward);
  EXPECT_TRUE(out.rim_vertices.empty());
  const MeshClosure in = closure_of({reversed(octahedron())});
  EXPECT_TRUE(in.solid);
  EXPECT_FALSE(in.outward);
  // A mirroring model matrix turns an outward winding inward on screen.
  const MeshClosure mirrored = closure_of({octahedron()}, glm::scale(glm::mat4(1.0f), glm::vec3(-1, 1, 1)));
  EXPECT_TRUE(mirrored.solid);
  EXPECT_FALSE(mirrored.outward);
  // Two parts wound alike qualify; one of them wound inward does not.
  Mesh shifted = octahedron();
  for (auto& p : shifted.positions) p.x += 5;
  EXPECT_TRUE(closure_of({merged(octahedron(), shifted)}).solid);
  EXPECT_FALSE(closure_of({merged(octahedron(), reversed(shifted))}).solid);
}

TEST(SelfOcclusionTopology, OpenMeshesKeepTheirRimsAndBadOnesDoNotQualify) {
  Mesh open = octahedron();
  open.triangles.erase(open.triangles.begin());  // a triangular hole at the top front
  const MeshClosure c = closure_of({open});
  EXPECT_TRUE(c.solid);
  ASSERT_EQ(c.rim_begin.size(), 2u);
  EXPECT_EQ(c.rim_vertices.size(), 3u);

  Mesh misoriented = octahedron();
  std::swap(misoriented.triangles[3][1], misoriented.triangles[3][2]);
  EXPECT_FALSE(closure_of({misoriented}).solid);

  Mesh fin = octahedron();  // a third face on the edge 0-2
  fin.positions.push_back({2, 2, 0});
  fin.triangles.push_back({0, 2, 6});
  EXPECT_FALSE(closure_of({fin}).solid);

  Mesh sheet;  // flat: capping its rim encloses nothing
  sheet.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  sheet.triangles = {{0, 1, 2}, {0, 2, 3}};
  EXPECT_FALSE(closure_of({sheet}).solid);
}

// Renders `scene` with hidden faces skipped and drawn: the images must be identical.
RenderStats expect_same_image(const Scene& scene, const std::string& what, const std::string& method = "gouraud") {
  RenderOptions skip, draw;
  skip.method = draw.method = parse_option<ShadingMethod>(method, "method");
  draw.hidden_faces = HiddenFaces::Draw;
  RenderStats s, d;
  const Image a = render(scene, skip, 1, &s), b = render(scene, draw, 1, &d);
  EXPECT_EQ(d.triangles_hidden, 0) << what;
  std::size_t diff = 0;
  for (std::size_t i = 0; i < a.rgb.size(); i += 3)
    diff += a.rgb[i] != b.rgb[i] || a.rgb[i + 1] != b.rgb[i + 1] || a.rgb[i + 2] != b.rgb[i + 2];
  EXPECT_EQ(diff, 0u) << what << ": pixels that differ with hidden faces skipped (" << s.triangles_hidden
                      << " hidden)";
  EXPECT_EQ(s.triangles_culled - s.triangles_hidden, d.triangles_culled) << what;
  return s;
}

std::string mesh_scene(const std::string& mesh, const std::string& rotate) {
  return R"({"image": {"width": 480, "height": 360},
    "camera": {"fit": true, "distance": 2.5, "fovy_deg": 45},
    "lights": [{"direction": [1, 1, 1], "color": [1, 1, 1]}], "ambient": [0.1, 0.1, 0.1],
    "materials": {"m": {"diffuse": 0.7, "specular": 0.5, "shininess": 32}},
    "objects": [{"mesh": ")" + mesh + R"(", "material": "m", "normals": "recompute",
                 "transform": {"rotate_deg": )" + rotate + "}}]}";
}

TEST(SelfOcclusionFrames, SharedMeshesFromSixSidesAreUnchanged) {
  struct Case {
    const char* file;
    bool closed;  // the shared models' README: every edge on two faces
  };
  const Case cases[] = {{"spot.obj", true},       {"horse.ply", true},    {"bunny.ply", false},
                        {"dragon_11k.ply", false}, {"suzanne.obj", false}, {"fandisk.off", true}};
  for (const Case& m : cases) FASTSHADE_REQUIRE_SHARED_MODEL(m.file);
  for (const Case& m : cases) {
    long long hidden = 0;
    for (const char* rotate : {"[0, 0, 0]", "[90, 0, 0]", "[-90, 0, 0]", "[0, 90, 0]", "[0, 180, 0]", "[0, -90, 0]"}) {
      const Scene scene = parse_scene(mesh_scene((testing::shared_models() / m.file).string(), rotate), m.file, ".");
      hidden += expect_same_image(scene, std::string(m.file) + " rotated " + rotate).triangles_hidden;
    }
    // Closed meshes and the bunny (holes underneath only) hide about half their faces.
    if (m.closed || std::string(m.file) == "bunny.ply") {
      EXPECT_GT(hidden, 0) << m.file;
    }
  }
}

TEST(SelfOcclusionFrames, SceneFilesAndEveryMethodAreUnchanged) {
  const std::filesystem::path scenes = std::filesystem::path(FASTSHADE_SOURCE_DIR) / "scenes";
  for (const char* file : {"default.json", "spheres.json", "torus_local.json"}) {
    const Scene scene = load_scene(scenes / file);
    for (const char* method : {"auto", "phong", "gouraud", "hybrid", "reference"}) {
      const long long hidden = expect_same_image(scene, std::string(file) + " " + method, method).triangles_hidden;
      // torus_local.json culls back faces itself: an inward-wound mesh's occluders would be gone.
      if (scene.cull == Cull::Back) {
        EXPECT_EQ(hidden, 0) << file;
      } else {
        EXPECT_GT(hidden, 0) << file;
      }
    }
  }
}

TEST(SelfOcclusionFrames, NothingIsCulledWhereTheNearPlaneCutsTheMeshOrTheEyeIsInside) {
  const auto sphere_scene = [](const char* eye) {
    return std::string(R"({"image": {"width": 160, "height": 120},
      "camera": {"eye": )") + eye + R"(, "target": [0, 0, 0], "up": [0, 1, 0], "fovy_deg": 60, "near": 0.5, "far": 100},
      "lights": [{"direction": [0, 0, 1], "color": [1, 1, 1]}],
      "materials": {"m": {"diffuse": 0.6, "specular": 0.5, "shininess": 50}},
      "objects": [{"primitive": "icosphere", "material": "m"}]})";
  };
  // Eye outside, far enough: culled. Near plane through the sphere, and eye at its centre: none.
  EXPECT_GT(expect_same_image(parse_scene(sphere_scene("[0, 0, 4]"), "outside", "."), "outside").triangles_hidden, 0);
  EXPECT_EQ(expect_same_image(parse_scene(sphere_scene("[0, 0, 1.2]"), "cut", "."), "cut").triangles_hidden, 0);
  EXPECT_EQ(expect_same_image(parse_scene(sphere_scene("[0, 0, 0.2]"), "inside", "."), "inside").triangles_hidden, 0);
}

TEST(SelfOcclusionFrames, AnUnknownChoiceIsRefused) {
  RenderOptions bad;
  bad.hidden_faces = static_cast<HiddenFaces>(7);  // outside the enum
  EXPECT_THROW(validate(bad), InputError);
}

}  // namespace
}  // namespace fastshade
