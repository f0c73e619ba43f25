// inspect_mesh: the README's counts for the shared models, and a small file with every quirk.
#include <gtest/gtest.h>

#include <string>

#include "fastshade/error.h"
#include "fastshade/mesh.h"
#include "io/io_test_util.h"

namespace fastshade {
namespace {

using testing::kModels;
using testing::ScratchDir;
using testing::shared_models;

TEST(InspectMesh, SharedModelsMatchTheReadme) {
  FASTSHADE_REQUIRE_SHARED_MODELS();
  for (const auto& m : kModels) {
    SCOPED_TRACE(m.file);
    const MeshInfo info = inspect_mesh(shared_models() / m.file);
    EXPECT_EQ(static_cast<long>(info.faces), m.faces);
    EXPECT_EQ(static_cast<long>(info.vertices), m.vertices);
    EXPECT_EQ(info.has_normals, m.normals);
    if (m.boundary_edges >= 0) {
      EXPECT_EQ(static_cast<long>(info.boundary_edges), m.boundary_edges);
    }
    if (m.unreferenced >= 0) {
      EXPECT_EQ(static_cast<long>(info.unreferenced_vertices), m.unreferenced);
    }
    if (m.zero_area >= 0) {
      EXPECT_EQ(static_cast<long>(info.zero_area_faces), m.zero_area);
    }
    EXPECT_LE(info.zero_area_faces, info.faces);
    EXPECT_LT(info.unreferenced_vertices, info.vertices);
    for (int a = 0; a < 3; ++a) EXPECT_LT(info.bbox_min[a], info.bbox_max[a]);
  }
}

TEST(InspectMesh, BunnyHasUnreferencedVerticesAndHoles) {
  FASTSHADE_REQUIRE_SHARED_MODELS();
  const MeshInfo info = inspect_mesh(shared_models() / "bunny.ply");
  EXPECT_EQ(info.unreferenced_vertices, 1113u);
  EXPECT_EQ(info.boundary_edges, 223u);
  EXPECT_FALSE(info.has_normals);
}

TEST(InspectMesh, SmallFileWithEveryQuirk) {
  ScratchDir dir;
  // Two triangles sharing edge 1-2 (4 boundary edges), a collinear triangle 5-6-7 (3 more
  // boundary edges, zero area), and vertex 4 on no face.
  const auto p = dir.write("quirks.obj",
                           "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv -3 7 2\n"
                           "v 2 0 0\nv 3 0 0\nv 4 0 -1e-30\n"
                           "f 1 2 3\nf 2 4 3\nf 6 7 8\n");
  const MeshInfo info = inspect_mesh(p);
  EXPECT_EQ(info.vertices, 8u);
  EXPECT_EQ(info.faces, 3u);
  EXPECT_EQ(info.unreferenced_vertices, 1u);
  EXPECT_EQ(info.zero_area_faces, 0u) << "1e-30 off the line is not zero area in double";
  EXPECT_EQ(info.boundary_edges, 7u);
  EXPECT_FALSE(info.has_normals);
  EXPECT_EQ(info.bbox_min, glm::vec3(-3, 0, -1e-30f));
  EXPECT_EQ(info.bbox_max, glm::vec3(4, 7, 2));

  const auto q = dir.write("flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 4\n");
  const MeshInfo flat = inspect_mesh(q);
  EXPECT_EQ(flat.zero_area_faces, 1u);
  EXPECT_EQ(flat.faces, 2u);
}

TEST(InspectMesh, NormalsInFile) {
  ScratchDir dir;
  const auto p = dir.write("n.obj",
                           "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n");
  EXPECT_TRUE(inspect_mesh(p).has_normals);
  const auto partial = dir.write("partial.obj",
                                 "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3\n");
  EXPECT_FALSE(inspect_mesh(partial).has_normals);
}

TEST(InspectMesh, RejectsWhatLoadRejects) {
  ScratchDir dir;
  const auto p = dir.write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
  try {
    inspect_mesh(p);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(p.string()), std::string::npos) << what;
    EXPECT_NE(what.find("out of range"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos);
  }
  EXPECT_THROW(inspect_mesh(dir.path() / "missing.ply"), InputError);
}

}  // namespace
}  // namespace fastshade
