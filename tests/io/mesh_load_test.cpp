// load_mesh and recompute_normals: the shared models, malformed files, welding, normals.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <set>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include <glm/geometric.hpp>

#include "fastshade/error.h"
#include "fastshade/mesh.h"
#include "io/io_test_util.h"
#include "io/mesh_weld.h"

namespace fastshade {
namespace {

using testing::kModels;
using testing::ScratchDir;
using testing::shared_models;

// load_mesh must throw InputError naming the file, on one line, containing `expect`.
void expect_load_error(const std::filesystem::path& path, const std::string& expect,
                       const MeshLoadOptions& options = {}) {
  SCOPED_TRACE(path.string());
  try {
    load_mesh(path, options);
    ADD_FAILURE() << "no InputError for " << path;
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(path.string()), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    EXPECT_NE(what.find(expect), std::string::npos) << "expected '" << expect << "' in: " << what;
  }
}

void expect_unit_normals(const Mesh& mesh) {
  ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
  for (std::size_t i = 0; i < mesh.normals.size(); ++i) {
    const float len = glm::length(mesh.normals[i]);
    ASSERT_TRUE(std::isfinite(len)) << "vertex " << i;
    ASSERT_NEAR(len, 1.0f, 1e-5f) << "vertex " << i;
  }
}

void expect_valid_indices(const Mesh& mesh) {
  for (const auto& tri : mesh.triangles) {
    for (const uint32_t v : tri) ASSERT_LT(v, mesh.positions.size());
  }
}

TEST(LoadMesh, EverySharedModelLoadsWithReadmeCounts) {
  FASTSHADE_REQUIRE_SHARED_MODELS();
  for (const auto& m : kModels) {
    SCOPED_TRACE(m.file);
    const auto path = shared_models() / m.file;
    const Mesh mesh = load_mesh(path);
    EXPECT_EQ(static_cast<long>(mesh.triangles.size()), m.faces);
    EXPECT_EQ(static_cast<long>(mesh.positions.size()), m.vertices);
    EXPECT_EQ(mesh.source, path.string());
    expect_valid_indices(mesh);
    expect_unit_normals(mesh);
  }
}

TEST(LoadMesh, UpperCaseExtensionLoads) {
  ScratchDir dir;
  const auto p = dir.write("tri.OBJ", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const Mesh mesh = load_mesh(p);
  EXPECT_EQ(mesh.triangles.size(), 1u);
  EXPECT_EQ(mesh.positions.size(), 3u);
}

TEST(LoadMesh, ObjPolygonsAreFanTriangulatedAndNegativeIndicesWork) {
  ScratchDir dir;
  const auto p = dir.write("quad.obj",
                           "# a unit quad written with relative indices\n"
                           "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                           "f -4 -3 -2 -1\n");
  const Mesh mesh = load_mesh(p);
  ASSERT_EQ(mesh.triangles.size(), 2u);
  for (const auto& tri : mesh.triangles) {
    const glm::vec3 n = glm::cross(mesh.positions[tri[1]] - mesh.positions[tri[0]],
                                   mesh.positions[tri[2]] - mesh.positions[tri[0]]);
    EXPECT_GT(n.z, 0.0f) << "winding kept";
  }
}

TEST(LoadMesh, KeepsZeroAreaFacesAndUnreferencedVertices) {
  ScratchDir dir;
  // Face 2 is collinear (zero area, distinct indices); vertex 6 is used by no face.
  const auto p = dir.write("odd.obj",
                           "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nv 3 0 0\nv 4 0 0\nv 9 9 9\n"
                           "f 1 2 3\nf 4 5 6\n");
  const Mesh mesh = load_mesh(p);
  EXPECT_EQ(mesh.positions.size(), 7u);
  EXPECT_EQ(mesh.triangles.size(), 2u);
  expect_unit_normals(mesh);
  EXPECT_EQ(mesh.normals[6], glm::vec3(0, 0, 1)) << "unreferenced vertex gets +Z";
  EXPECT_EQ(mesh.normals[4], glm::vec3(0, 0, 1)) << "zero-area face contributes nothing";
}

TEST(LoadMesh, OffAndPlyPolygons) {
  ScratchDir dir;
  const Mesh off = load_mesh(dir.write("quad.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n"));
  EXPECT_EQ(off.triangles.size(), 2u);
  const Mesh ply = load_mesh(dir.write(
      "quad.ply",
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n"));
  EXPECT_EQ(ply.triangles.size(), 2u);
}

TEST(LoadMesh, NonManifoldEdgeCopiesKeepTheirFileNormals) {
  ScratchDir dir;
  // Three triangles on edge 1-2, two of them using it in the same direction: OpenMesh cannot
  // add the third and adds it on copies of its 3 vertices.
  const auto p = dir.write("fin.obj",
                           "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nvn 0 0 1\n"
                           "f 1//1 2//1 3//1\nf 2//1 1//1 4//1\nf 1//1 2//1 5//1\n");
  const MeshInfo info = inspect_mesh(p);
  EXPECT_EQ(info.vertices, 8u);
  EXPECT_EQ(info.faces, 3u);
  EXPECT_TRUE(info.has_normals);
  const Mesh mesh = load_mesh(p, {NormalsMode::File, false});
  ASSERT_EQ(mesh.normals.size(), 8u);
  for (const auto& n : mesh.normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
  EXPECT_EQ(load_mesh(p, {NormalsMode::File, true}).positions.size(), 5u) << "weld re-merges";
}

// ---- malformed input -------------------------------------------------------------------

TEST(LoadMeshErrors, MissingFileDirectoryAndUnknownExtension) {
  ScratchDir dir;
  expect_load_error(dir.path() / "nope.obj", "no such file");
  std::filesystem::create_directory(dir.path() / "folder.obj");
  expect_load_error(dir.path() / "folder.obj", "directory");
  expect_load_error(dir.write("mesh.xyz", "v 0 0 0\n"), "unknown extension");
  expect_load_error(dir.write("mesh", "v 0 0 0\n"), "no file extension");
}

TEST(LoadMeshErrors, EmptyFiles) {
  ScratchDir dir;
  for (const char* name : {"empty.obj", "empty.off", "empty.ply", "empty.stl"}) {
    expect_load_error(dir.write(name, ""), "empty file");
  }
}

TEST(LoadMeshErrors, UnreadableFile) {
  if (::geteuid() == 0) {
    GTEST_SKIP() << "running as root: chmod 000 does not stop root from reading";
  }
  ScratchDir dir;
  const auto p = dir.write("secret.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  std::filesystem::permissions(p, std::filesystem::perms::none);
  expect_load_error(p, "cannot open for reading");
}

TEST(LoadMeshErrors, OffHeaderLyingAboutFaces) {
  ScratchDir dir;
  const auto p = dir.write("OutOfMemory.off",
                           "OFF\n3 353535235358 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  expect_load_error(p, "header declares 3 vertices and 353535235358 faces but the file has");
  // assimp's invalid/OutOfMemory.off lies about its vertices (the first count).
  const auto v = dir.write("OutOfVertices.off", "OFF\n353535235358 6 0\n-0.5 -0.5 0.5\n");
  expect_load_error(v, "header declares 353535235358 vertices and 6 faces");
  std::string bin = "OFF BINARY\n";
  const uint32_t counts[3] = {3, 4000000000u, 0};
  bin.append(reinterpret_cast<const char*>(counts), sizeof counts);
  bin.append(3 * 12, '\0');
  expect_load_error(dir.write("binary.off", bin), "4000000000 faces but the file has");
}

TEST(LoadMeshErrors, PlyHeaderLyingAboutFaces) {
  ScratchDir dir;
  const std::string header_bin =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1000000000\n"
      "property list uchar int vertex_indices\nend_header\n";
  std::string bin = header_bin + std::string(3 * 12, '\0');
  bin += std::string("\x03\x00\x00\x00\x00\x01\x00\x00\x00\x02\x00\x00\x00", 13);
  expect_load_error(dir.write("liar_bin.ply", bin), "1000000000 faces but the file has");

  const std::string ascii =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1000000000\nproperty list uchar int vertex_indices\n"
      "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  expect_load_error(dir.write("liar_ascii.ply", ascii), "1000000000 faces but the file has");
}

// Found by fuzzing (fuzz/regressions/mesh_ply, where a garbled property line left the face
// element without properties): records of no properties take no bytes, so no file size
// bounded the count.
TEST(LoadMeshErrors, PlyElementWithoutProperties) {
  ScratchDir dir;
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 100000000\n"
      "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  expect_load_error(dir.write("no_properties.ply", ply),
                    "the PLY element 'face' declares 100000000 records but no properties");
}

// Found by fuzzing (fuzz/regressions/mesh_off): OpenMesh reads a binary face's indices with no
// end-of-file check, so a vertex count of 4e9 looped 4e9 times.
TEST(LoadMeshErrors, OffBinaryFaceListPastTheEnd) {
  ScratchDir dir;
  std::string bin = "OFF BINARY\n";
  const uint32_t counts[3] = {3, 2, 0};
  bin.append(reinterpret_cast<const char*>(counts), sizeof counts);
  const float xyz[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  bin.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
  const uint32_t faces[5] = {3, 0, 1, 2, 4000000000u};
  bin.append(reinterpret_cast<const char*>(faces), sizeof faces);
  bin.append(16, '\0');
  expect_load_error(dir.write("long_face.off", bin), "OFF BINARY face 1 lists 4000000000 vertices but only 16 bytes follow");
  // With the C prefix each vertex carries three 4-byte colour values; faces carry none that
  // load_mesh reads.
  std::string colored = "COFF BINARY\n";
  const uint32_t one_face[3] = {3, 1, 0};
  colored.append(reinterpret_cast<const char*>(one_face), sizeof one_face);
  for (int v = 0; v < 3; ++v) {
    const float p[3] = {float(v == 1), float(v == 2), 0};
    const uint32_t rgb[3] = {255, 128, 0};
    colored.append(reinterpret_cast<const char*>(p), sizeof p).append(reinterpret_cast<const char*>(rgb), sizeof rgb);
  }
  const uint32_t tri[4] = {3, 0, 1, 2};
  colored.append(reinterpret_cast<const char*>(tri), sizeof tri);
  EXPECT_EQ(load_mesh(dir.write("colored.off", colored)).triangles.size(), 1u);
  // The same file with an honest second face loads.
  std::string ok = bin.substr(0, bin.size() - 20);
  const uint32_t second[4] = {3, 0, 2, 1};
  ok.append(reinterpret_cast<const char*>(second), sizeof second);
  EXPECT_EQ(load_mesh(dir.write("two_faces.off", ok)).triangles.size(), 2u);
}

// Found by fuzzing (fuzz/regressions): OpenMesh reads an ASCII OFF face's count as `unsigned`;
// "-1" became 4294967295 and "1.5" failed its stream with the last count left standing, and it
// then looped that many times. A PLY format version that is not a number, or an unknown header
// word, spun OpenMesh's header loop forever.
TEST(LoadMeshErrors, OffAsciiFaceCountsAndPlyHeaderWords) {
  ScratchDir dir;
  const std::string verts = "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n";
  expect_load_error(dir.write("fraction.off", verts + "3 0 1 2\n1.5 0 1 2\n"),
                    "line 7: face 1's vertex count is '1.5', not a whole number");
  expect_load_error(dir.write("negative.off", verts + "-1 0 1 2\n3 0 1 2\n"),
                    "face 0's vertex count is '-1', not a whole number");
  expect_load_error(dir.write("long.off", verts + "3 0 1 2\n9 0 1 2\n"),
                    "face 1 lists 9 vertices but only 3 numbers follow");
  // Whatever follows a vertex's three numbers on its line is skipped, as OpenMesh does.
  EXPECT_EQ(load_mesh(dir.write("trailing.off", "OFF\n3 1 0\n0 0 0 7 7\n1 0 0\n0 1 0 1.5\n3 0 1 2\n"))
                .triangles.size(),
            1u);
  const std::string ply = "ply\nformat ascii x.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                          "property float z\nend_header\n0 0 0\n1 0 0\n0 1 0\n";
  expect_load_error(dir.write("version.ply", ply), "line 2: expected 'format ascii 1.0', found 'format ascii x.0'");
  std::string huge = ply;
  huge.replace(huge.find("x.0"), 3, "5" + std::string(60, '5') + ".0");  // no float holds it
  expect_load_error(dir.write("huge_version.ply", huge), "line 2: expected 'format ascii 1.0'");
  // An unknown header word put OpenMesh's word-by-word reading out of step: it never met end_header.
  const std::string unknown = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                              "property float z\nalement face 1\nend_header\n0 0 0\n1 0 0\n0 1 0\n";
  expect_load_error(dir.write("unknown.ply", unknown), "line 7: unknown PLY header line 'alement face 1'");
}

// Found by fuzzing (fuzz/regressions/mesh_ply): a list count OpenMesh believed and looped on.
TEST(LoadMeshErrors, PlyListLongerThanTheFile) {
  ScratchDir dir;
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                             "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  expect_load_error(dir.write("overflow.ply", header + "0 0 0\n1 0 0\n0 1 0\n131111111111111111111111 0 2 1\n"),
                    "line 13: face 0 has a list of '131111111111111111111111' items, but only 3 numbers follow");
  expect_load_error(dir.write("long.ply", header + "0 0 0\n1 0 0\n0 1 0\n7 0 2 1\n"),
                    "face 0 has a list of '7' items, but only 3 numbers follow");
  std::string bin = "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                    "property float z\nelement face 1\nproperty list int int vertex_indices\nend_header\n";
  bin.append(36, '\0');
  bin.append("\x7F\xFF\xFF\xFF", 4);  // 2^31 - 1 indices
  bin.append(12, '\0');
  expect_load_error(dir.write("long_bin.ply", bin), "face 0 has a list of 2147483647 items, but only 12 bytes follow");
}

// Found by fuzzing: OpenMesh reads a binary PLY's coordinates, normals and texture
// coordinates only from float or double; for an integer type it printed four lines of its own
// to stderr before failing. ASCII files convert any type.
TEST(LoadMeshErrors, BinaryPlyIntegerCoordinatesAreRefusedInOneLine) {
  ScratchDir dir;
  std::string bin = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty uint32 x\nproperty float y\n"
                    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  bin.append(36, '\0');
  bin.append("\x03\x00\x00\x00\x00\x01\x00\x00\x00\x02\x00\x00\x00", 13);
  expect_load_error(dir.write("int_x.ply", bin),
                    "the binary PLY vertex property 'x' is an integer type; OpenMesh reads it only as float or double");
  const std::string ascii = "ply\nformat ascii 1.0\nelement vertex 3\nproperty uint32 x\nproperty float y\n"
                            "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                            "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  EXPECT_EQ(load_mesh(dir.write("int_x_ascii.ply", ascii)).triangles.size(), 1u);
}

TEST(LoadMeshErrors, TruncatedAsciiPly) {
  ScratchDir dir;
  // Within the byte bound (the numbers are long) but one face short.
  const std::string ascii =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 2\nproperty list uchar int vertex_indices\n"
      "end_header\n0.000000 0.000000 0.000000\n1.000000 0.000000 0.000000\n"
      "0.000000 1.000000 0.000000\n3 0 1 2\n";
  expect_load_error(dir.write("short.ply", ascii), "truncated");
}

TEST(LoadMeshErrors, ObjBadIndices) {
  ScratchDir dir;
  const std::string verts = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  expect_load_error(dir.write("range.obj", verts + "f 1 2 9\n"), "line 4: vertex index 9 out of range");
  expect_load_error(dir.write("zero.obj", verts + "f 0 1 2\n"), "line 4: vertex index 0");
  expect_load_error(dir.write("negative.obj", verts + "f -1 -2 -9\n"),
                    "line 4: relative vertex index -9");
  expect_load_error(dir.write("normal.obj", verts + "vn 0 0 1\nf 1//1 2//1 3//7\n"),
                    "normal index 7 out of range");
  expect_load_error(dir.write("short_face.obj", verts + "f 1 2\n"), "face has 2 vertices");
  expect_load_error(dir.write("empty_face.obj", verts + "f\n"), "face has 0 vertices");
  expect_load_error(dir.write("junk.obj", verts + "f 1 2 x\n"), "cannot read 'x'");
}

TEST(LoadMeshErrors, PlyAndOffBadIndices) {
  ScratchDir dir;
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 2\nproperty list uchar int vertex_indices\n"
      "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 7\n";
  expect_load_error(dir.write("range.ply", ply), "face 1 (counting from 0) references vertex 7");
  const std::string off = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n";
  expect_load_error(dir.write("range.off", off), "references vertex -1");
}

TEST(LoadMeshErrors, NonFiniteCoordinates) {
  ScratchDir dir;
  const std::string rest = "v 1 0 0\nv 0 1 0\nf 1 2 3\n";
  expect_load_error(dir.write("nan.obj", "v nan 0 0\n" + rest), "line 1: non-finite number 'nan'");
  expect_load_error(dir.write("inf.obj", "v inf 0 0\n" + rest), "line 1: non-finite number 'inf'");
  expect_load_error(dir.write("huge.obj", "v 1e39 0 0\n" + rest), "does not fit in a float");
  expect_load_error(dir.write("nan.off", "OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n"),
                    "line 4: non-finite number 'nan'");
  // Binary PLY: the value reaches OpenMesh, and the loaded positions are checked.
  std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n";
  const float coords[9] = {0, 0, 0, 1, 0, 0, 0, std::nanf(""), 0};
  ply.append(reinterpret_cast<const char*>(coords), sizeof coords);
  ply += std::string("\x03\x00\x00\x00\x00\x01\x00\x00\x00\x02\x00\x00\x00", 13);
  expect_load_error(dir.write("nan.ply", ply), "vertex 2 (counting from 0) has a non-finite");
}

TEST(LoadMeshErrors, Utf16Text) {
  ScratchDir dir;
  const std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  std::string le = "\xFF\xFE", be;
  for (const char c : text) {
    le += c;
    le += '\0';
    be += '\0';
    be += c;
  }
  expect_load_error(dir.write("box_UTF16LE.obj", le), "UTF-16");
  expect_load_error(dir.write("box_UTF16BE.obj", be), "NUL byte");  // no BOM
  expect_load_error(dir.write("bom.off", "\xFE\xFF" + be), "UTF-16");
}

TEST(LoadMeshErrors, PointCloudHasNoFaces) {
  ScratchDir dir;
  expect_load_error(dir.write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"), "no faces");
  expect_load_error(dir.write("comments.obj", "# nothing here\n"), "no faces");
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n0 0 0\n1 0 0\n";
  expect_load_error(dir.write("points.ply", ply), "no faces");
}

TEST(LoadMeshErrors, NotTheFormatTheExtensionSays) {
  ScratchDir dir;
  expect_load_error(dir.write("text.ply", "hello\n"), "not a PLY file");
  expect_load_error(dir.write("text.off", "hello\n"), "not an OFF file");
  expect_load_error(dir.write("text.stl", "hello, not a mesh\n"), "neither a binary STL");
}

// ---- normals ---------------------------------------------------------------------------

TEST(LoadMeshNormals, FileModeNeedsNormals) {
  ScratchDir dir;
  const auto p = dir.write("plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  expect_load_error(p, "no vertex normals in file", {NormalsMode::File, false});

  // Stored normals are normalised; a zero one is unusable in File mode, recomputed in Auto.
  const auto good = dir.write("good.obj",
                              "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 2\nvn 0 3 0\n"
                              "f 1//1 2//1 3//2\n");
  const Mesh mesh = load_mesh(good, {NormalsMode::File, false});
  EXPECT_EQ(mesh.normals[0], glm::vec3(0, 0, 1));
  EXPECT_EQ(mesh.normals[2], glm::vec3(0, 1, 0));
  const auto zero = dir.write("zero.obj",
                              "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvn 0 0 0\n"
                              "f 1//1 2//1 3//2\n");
  expect_load_error(zero, "unusable vertex normals", {NormalsMode::File, false});
  const Mesh autom = load_mesh(zero);
  for (const auto& n : autom.normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
}

TEST(LoadMeshNormals, HorseKeepsItsInwardFileNormals) {
  FASTSHADE_REQUIRE_SHARED_MODELS();
  const auto path = shared_models() / "horse.ply";
  const Mesh file = load_mesh(path, {NormalsMode::File, false});
  const Mesh computed = load_mesh(path, {NormalsMode::Recompute, false});
  expect_unit_normals(file);
  expect_unit_normals(computed);
  ASSERT_EQ(file.positions.size(), computed.positions.size());
  // Faces and stored normals both point inward: they agree, and nothing flipped them.
  std::size_t agree = 0;
  for (std::size_t i = 0; i < file.normals.size(); ++i) {
    agree += glm::dot(file.normals[i], computed.normals[i]) > 0.0f;
  }
  EXPECT_GT(agree, file.normals.size() * 95 / 100);
  EXPECT_NE(file.normals, computed.normals) << "File mode must not recompute";
}

TEST(LoadMeshNormals, AutoRecomputesWithoutFileNormals) {
  FASTSHADE_REQUIRE_SHARED_MODELS();
  const Mesh a = load_mesh(shared_models() / "spot.obj");
  const Mesh r = load_mesh(shared_models() / "spot.obj", {NormalsMode::Recompute, false});
  EXPECT_EQ(a.normals, r.normals);
  expect_load_error(shared_models() / "spot.obj", "no vertex normals in file",
                    {NormalsMode::File, false});
}

TEST(LoadMeshNormals, DragonZeroAreaFacesGiveNoNaN) {
  FASTSHADE_REQUIRE_SHARED_MODELS();
  // 12% of its faces have zero area.
  const Mesh mesh = load_mesh(shared_models() / "dragon_871k.ply");
  expect_unit_normals(mesh);
}

// A regular tetrahedron centred on the origin, faces wound outward.
Mesh tetrahedron() {
  Mesh m;
  m.positions = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  m.triangles = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  m.source = "tetrahedron";
  return m;
}

TEST(RecomputeNormals, TetrahedronVertexNormalsPointAwayFromTheCentre) {
  Mesh m = tetrahedron();
  recompute_normals(m);
  ASSERT_EQ(m.normals.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    const glm::vec3 expected = glm::normalize(m.positions[i]);
    EXPECT_NEAR(m.normals[i].x, expected.x, 1e-6f) << i;
    EXPECT_NEAR(m.normals[i].y, expected.y, 1e-6f) << i;
    EXPECT_NEAR(m.normals[i].z, expected.z, 1e-6f) << i;
  }
}

TEST(RecomputeNormals, AreaWeighted) {
  // Vertex 0 is shared by a triangle in z=0 of area 2 (normal +Z) and one in y=0 of area 0.5
  // (normal +Y): cross products (0,0,4) and (0,1,0) sum to (0,1,4).
  Mesh m;
  m.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 0, 1}, {1, 0, 0}};
  m.triangles = {{0, 1, 2}, {0, 3, 4}};
  recompute_normals(m);
  const glm::vec3 expected = glm::normalize(glm::vec3(0, 1, 4));
  EXPECT_NEAR(m.normals[0].y, expected.y, 1e-6f);
  EXPECT_NEAR(m.normals[0].z, expected.z, 1e-6f);
  EXPECT_EQ(m.normals[1], glm::vec3(0, 0, 1));
  EXPECT_EQ(m.normals[3], glm::vec3(0, 1, 0));
}

TEST(RecomputeNormals, ZeroAreaFacesAndLooseVerticesGetNoNaN) {
  Mesh m = tetrahedron();
  recompute_normals(m);
  const auto reference = m.normals;
  m.positions.push_back({5, 5, 5});                      // 4: on no face
  m.positions.push_back({0, 0, 0});                      // 5..7: a collinear triangle
  m.positions.push_back({1, 0, 0});
  m.positions.push_back({2, 0, 0});
  m.triangles.push_back({0, 0, 1});                      // repeated index: zero area
  m.triangles.push_back({5, 6, 7});
  recompute_normals(m);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(m.normals[i], reference[i]) << i;
  for (std::size_t i = 4; i < 8; ++i) EXPECT_EQ(m.normals[i], glm::vec3(0, 0, 1)) << i;
}

TEST(RecomputeNormals, RejectsOutOfRangeTriangles) {
  Mesh m = tetrahedron();
  m.triangles.push_back({0, 1, 4});
  EXPECT_THROW(recompute_normals(m), InputError);
}

// ---- weld ------------------------------------------------------------------------------

// The tetrahedron as an STL stores it: three unshared vertices per facet.
Mesh tetrahedron_soup() {
  const Mesh t = tetrahedron();
  Mesh soup;
  soup.source = "soup";
  for (const auto& tri : t.triangles) {
    const auto base = static_cast<uint32_t>(soup.positions.size());
    for (const uint32_t v : tri) soup.positions.push_back(t.positions[v]);
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  return soup;
}

TEST(Weld, MergesUnsharedFacetVertices) {
  Mesh soup = tetrahedron_soup();
  ASSERT_EQ(soup.positions.size(), 12u);
  const Mesh before = soup;
  EXPECT_EQ(io::weld_vertices(soup), 8u);
  ASSERT_EQ(soup.positions.size(), 4u);
  ASSERT_EQ(soup.triangles.size(), 4u);
  for (std::size_t t = 0; t < 4; ++t) {
    for (std::size_t k = 0; k < 3; ++k) {
      EXPECT_EQ(soup.positions[soup.triangles[t][k]], before.positions[before.triangles[t][k]]);
    }
  }
  // Welded, the soup is the tetrahedron again, with its smooth normals.
  recompute_normals(soup);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(glm::dot(soup.normals[i], glm::normalize(soup.positions[i])), 1.0f, 1e-6f);
  }
}

TEST(Weld, KeepsSignedZerosApart) {
  Mesh m;
  m.positions = {{0.0f, 0, 0}, {-0.0f, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.triangles = {{0, 2, 3}, {1, 2, 3}};
  EXPECT_EQ(io::weld_vertices(m), 0u);
  EXPECT_EQ(m.positions.size(), 4u);
}

std::string binary_stl(const Mesh& soup) {
  std::string out(80, ' ');
  const auto n = static_cast<uint32_t>(soup.triangles.size());
  out.append(reinterpret_cast<const char*>(&n), 4);
  for (const auto& tri : soup.triangles) {
    const float normal[3] = {0, 0, 0};
    out.append(reinterpret_cast<const char*>(normal), 12);
    for (const uint32_t v : tri) out.append(reinterpret_cast<const char*>(&soup.positions[v]), 12);
    out.append(2, '\0');
  }
  return out;
}

TEST(Weld, LoadMeshWeldsAnUnweldedObj) {
  ScratchDir dir;
  // The soup as an OBJ keeps its 12 vertices (OpenMesh merges only STL); weld makes it 4.
  const Mesh soup = tetrahedron_soup();
  std::string obj;
  for (const auto& p : soup.positions) {
    obj += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
  }
  for (const auto& t : soup.triangles) {
    obj += "f " + std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " +
           std::to_string(t[2] + 1) + "\n";
  }
  const auto p = dir.write("soup.obj", obj);
  EXPECT_EQ(load_mesh(p).positions.size(), 12u);
  const Mesh welded = load_mesh(p, {NormalsMode::Auto, true});
  EXPECT_EQ(welded.positions.size(), 4u);
  EXPECT_EQ(welded.triangles.size(), 4u);
  expect_unit_normals(welded);

  // As a binary STL, OpenMesh's reader already merges equal positions.
  const auto stl = dir.write("soup.stl", binary_stl(soup));
  EXPECT_EQ(load_mesh(stl).positions.size(), 4u);
  EXPECT_EQ(load_mesh(stl, {NormalsMode::Auto, true}).positions.size(), 4u);
}

TEST(Weld, TeapotObjWeldsToItsDistinctPositions) {
  FASTSHADE_REQUIRE_SHARED_MODELS();
  const auto path = shared_models() / "teapot.obj";
  const Mesh plain = load_mesh(path);
  std::set<std::tuple<uint32_t, uint32_t, uint32_t>> distinct;  // bit patterns, as weld
  for (const auto& p : plain.positions) {
    distinct.insert({std::bit_cast<uint32_t>(p.x), std::bit_cast<uint32_t>(p.y),
                     std::bit_cast<uint32_t>(p.z)});
  }
  const Mesh welded = load_mesh(path, {NormalsMode::Auto, true});
  EXPECT_LT(welded.positions.size(), plain.positions.size());
  EXPECT_EQ(welded.positions.size(), distinct.size());
  EXPECT_EQ(welded.triangles.size(), plain.triangles.size());
  expect_valid_indices(welded);
  expect_unit_normals(welded);
}

// Loads run in parallel, each through an OpenMesh reader of its own: every format, read by
// several threads at once, gives exactly what a lone read gives.
TEST(LoadMesh, ConcurrentLoadsMatchSerialOnes) {
  FASTSHADE_REQUIRE_SHARED_MODELS();
  const char* files[] = {"suzanne.obj", "suzanne.ply", "cow.ply", "fandisk.off", "teapot.stl",
                         "dragon_11k.ply", "spot.obj"};
  std::vector<Mesh> serial;
  for (const char* file : files) serial.push_back(load_mesh(shared_models() / file));
  constexpr int kThreads = 4;
  std::vector<std::vector<Mesh>> parallel(kThreads);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      for (std::size_t i = 0; i < std::size(files); ++i)  // each thread in another order
        parallel[t].push_back(load_mesh(shared_models() / files[(i + t) % std::size(files)]));
    });
  }
  for (std::thread& thread : threads) thread.join();
  for (int t = 0; t < kThreads; ++t) {
    for (std::size_t i = 0; i < std::size(files); ++i) {
      const Mesh& want = serial[(i + t) % std::size(files)];
      const Mesh& got = parallel[t][i];
      EXPECT_EQ(got.positions, want.positions) << want.source;
      EXPECT_EQ(got.normals, want.normals) << want.source;
      EXPECT_EQ(got.triangles, want.triangles) << want.source;
    }
  }
}

}  // namespace
}  // namespace fastshade
