// Procedural primitives: counts, analytic normals, winding, closedness, parameter checks.
#include "fastshade/primitives.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <utility>

#include <glm/geometric.hpp>

#include "fastshade/error.h"

namespace fastshade {
namespace {

using Edge = std::pair<uint32_t, uint32_t>;

// Vertex ids after merging bit-equal positions (the cube splits its vertices at the edges).
std::vector<uint32_t> weld_ids(const Mesh& mesh) {
  std::map<std::array<float, 3>, uint32_t> ids;
  std::vector<uint32_t> out;
  for (const glm::vec3& p : mesh.positions)
    out.push_back(ids.emplace(std::array<float, 3>{p.x, p.y, p.z}, uint32_t(ids.size())).first->second);
  return out;
}

// Directed edges of the welded mesh with their multiplicity.
std::map<Edge, int> directed_edges(const Mesh& mesh) {
  const std::vector<uint32_t> id = weld_ids(mesh);
  std::map<Edge, int> edges;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++edges[{id[t[size_t(k)]], id[t[size_t((k + 1) % 3)]]}];
  return edges;
}

// Closed and consistently oriented: every directed edge appears once and its reverse once, so
// every undirected edge has exactly two faces, wound in opposite directions.
void expect_closed(const Mesh& mesh) {
  const auto edges = directed_edges(mesh);
  int bad = 0;
  for (const auto& [edge, count] : edges) {
    auto reverse = edges.find({edge.second, edge.first});
    if (count != 1 || reverse == edges.end() || reverse->second != 1) ++bad;
  }
  EXPECT_EQ(bad, 0) << mesh.source << ": edges not shared by exactly two faces";
}

size_t boundary_edges(const Mesh& mesh) {
  const auto edges = directed_edges(mesh);
  size_t n = 0;
  for (const auto& [edge, count] : edges) n += edges.count({edge.second, edge.first}) == 0;
  return n;
}

// Euler characteristic V - E + F on the welded mesh.
long euler(const Mesh& mesh) {
  const std::vector<uint32_t> id = weld_ids(mesh);
  std::set<uint32_t> vertices(id.begin(), id.end());
  std::set<Edge> edges;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      uint32_t a = id[t[size_t(k)]], b = id[t[size_t((k + 1) % 3)]];
      edges.insert({std::min(a, b), std::max(a, b)});
    }
  return long(vertices.size()) - long(edges.size()) + long(mesh.triangles.size());
}

void expect_valid(const Mesh& mesh) {
  ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
  for (const auto& t : mesh.triangles)
    for (uint32_t i : t) ASSERT_LT(i, mesh.positions.size());
  for (const glm::vec3& n : mesh.normals) ASSERT_NEAR(glm::length(n), 1.0f, 1e-6f);
}

// Counter-clockwise seen from where the normals point: the geometric normal agrees with them.
void expect_winding_matches_normals(const Mesh& mesh) {
  int bad = 0;
  for (const auto& t : mesh.triangles) {
    const glm::vec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    const glm::vec3 n = mesh.normals[t[0]] + mesh.normals[t[1]] + mesh.normals[t[2]];
    if (!(glm::dot(glm::cross(b - a, c - a), n) > 0.0f)) ++bad;
  }
  EXPECT_EQ(bad, 0) << mesh.source << ": triangles wound against their normals";
}

// Normal equals the analytic one at every vertex; `expected` maps a position to it.
void expect_normals(const Mesh& mesh, const std::function<glm::vec3(glm::vec3)>& expected,
                    float tolerance = 1e-5f) {
  float worst = 0.0f;
  for (size_t i = 0; i < mesh.positions.size(); ++i)
    worst = std::max(worst, glm::length(mesh.normals[i] - expected(mesh.positions[i])));
  EXPECT_LT(worst, tolerance) << mesh.source;
}

TEST(Primitives, IcosphereCountsAndSharing) {
  for (int s = 0; s <= 4; ++s) {
    const Mesh mesh = make_icosphere(2.0f, s);
    const size_t pow4 = size_t(1) << (2 * s);
    EXPECT_EQ(mesh.triangles.size(), 20 * pow4) << "s=" << s;
    EXPECT_EQ(mesh.positions.size(), 10 * pow4 + 2) << "s=" << s;
    // Shared midpoints: no two vertices at the same place.
    std::set<uint32_t> distinct;
    for (uint32_t id : weld_ids(mesh)) distinct.insert(id);
    EXPECT_EQ(distinct.size(), mesh.positions.size()) << "duplicate vertices at s=" << s;
  }
}

TEST(Primitives, IcosphereGeometry) {
  const Mesh mesh = make_icosphere(2.5f, 3);
  expect_valid(mesh);
  for (const glm::vec3& p : mesh.positions) ASSERT_NEAR(glm::length(p), 2.5f, 2.5f * 1e-6f);
  expect_normals(mesh, [](glm::vec3 p) { return glm::normalize(p); });
  expect_winding_matches_normals(mesh);
  expect_closed(mesh);
  EXPECT_EQ(euler(mesh), 2);
}

TEST(Primitives, UvSphere) {
  const int segments = 24, rings = 12;
  const Mesh mesh = make_uvsphere(1.5f, segments, rings);
  expect_valid(mesh);
  EXPECT_EQ(mesh.positions.size(), size_t(2 + segments * (rings - 1)));
  EXPECT_EQ(mesh.triangles.size(), size_t(2 * segments * (rings - 1)));
  for (const glm::vec3& p : mesh.positions) ASSERT_NEAR(glm::length(p), 1.5f, 1e-5f);
  expect_normals(mesh, [](glm::vec3 p) { return glm::normalize(p); });
  expect_winding_matches_normals(mesh);
  expect_closed(mesh);
  EXPECT_EQ(euler(mesh), 2);
  // The poles sit on the Y axis.
  float top = -1, bottom = 1;
  for (const glm::vec3& p : mesh.positions) top = std::max(top, p.y), bottom = std::min(bottom, p.y);
  EXPECT_EQ(top, 1.5f);
  EXPECT_EQ(bottom, -1.5f);
  // The smallest case is still a closed solid.
  const Mesh tiny = make_uvsphere(1.0f, 3, 2);
  EXPECT_EQ(tiny.triangles.size(), 6u);
  expect_winding_matches_normals(tiny);
  expect_closed(tiny);
}

TEST(Primitives, Torus) {
  const float major = 1.2f, minor = 0.4f;
  const int segments = 32, sides = 16;
  const Mesh mesh = make_torus(major, minor, segments, sides);
  expect_valid(mesh);
  EXPECT_EQ(mesh.positions.size(), size_t(segments * sides));
  EXPECT_EQ(mesh.triangles.size(), size_t(2 * segments * sides));
  // Outward from the tube's centre circle (radius `major` in the XZ plane).
  auto tube_normal = [&](glm::vec3 p) {
    const glm::vec3 ring = major * glm::normalize(glm::vec3(p.x, 0.0f, p.z));
    return glm::normalize(p - ring);
  };
  for (const glm::vec3& p : mesh.positions) {
    const glm::vec3 ring = major * glm::normalize(glm::vec3(p.x, 0.0f, p.z));
    ASSERT_NEAR(glm::length(p - ring), minor, 1e-5f);
  }
  expect_normals(mesh, tube_normal);
  expect_winding_matches_normals(mesh);
  expect_closed(mesh);
  EXPECT_EQ(euler(mesh), 0);
}

TEST(Primitives, Plane) {
  const int d = 5;
  const Mesh mesh = make_plane(3.0f, d);
  expect_valid(mesh);
  EXPECT_EQ(mesh.positions.size(), size_t((d + 1) * (d + 1)));
  EXPECT_EQ(mesh.triangles.size(), size_t(2 * d * d));
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    EXPECT_EQ(mesh.positions[i].y, 0.0f);
    EXPECT_LE(std::fabs(mesh.positions[i].x), 1.5f);
    EXPECT_LE(std::fabs(mesh.positions[i].z), 1.5f);
    EXPECT_EQ(mesh.normals[i], glm::vec3(0, 1, 0));
  }
  expect_winding_matches_normals(mesh);
  EXPECT_EQ(boundary_edges(mesh), size_t(4 * d));
  EXPECT_EQ(euler(mesh), 1);
}

TEST(Primitives, Cube) {
  const int d = 3;
  const Mesh mesh = make_cube(2.0f, d);
  expect_valid(mesh);
  EXPECT_EQ(mesh.positions.size(), size_t(6 * (d + 1) * (d + 1)));
  EXPECT_EQ(mesh.triangles.size(), size_t(12 * d * d));
  // Flat faces: all three normals of a triangle equal its geometric normal, an axis.
  std::map<std::array<float, 3>, int> per_normal;
  for (const auto& t : mesh.triangles) {
    const glm::vec3 n = mesh.normals[t[0]];
    EXPECT_EQ(mesh.normals[t[1]], n);
    EXPECT_EQ(mesh.normals[t[2]], n);
    const glm::vec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    EXPECT_LT(glm::length(glm::normalize(glm::cross(b - a, c - a)) - n), 1e-6f);
    ++per_normal[{n.x, n.y, n.z}];
    // Every vertex of a face lies on its side of the cube.
    EXPECT_EQ(glm::dot(a, n), 1.0f);
  }
  EXPECT_EQ(per_normal.size(), 6u);
  for (const auto& [n, count] : per_normal) EXPECT_EQ(count, 2 * d * d);
  for (const glm::vec3& p : mesh.positions) {
    EXPECT_LE(std::fabs(p.x), 1.0f);
    EXPECT_LE(std::fabs(p.y), 1.0f);
    EXPECT_LE(std::fabs(p.z), 1.0f);
  }
  expect_winding_matches_normals(mesh);
  expect_closed(mesh);  // faces meet at bit-equal positions along the edges
  EXPECT_EQ(euler(mesh), 2);
}

// Throws InputError with a one-line message naming `word`.
void expect_rejected(const std::function<Mesh()>& make, const std::string& word) {
  try {
    make();
    ADD_FAILURE() << "accepted, expected an error about " << word;
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(word), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

TEST(Primitives, BadParametersRejected) {
  const float nan = std::nanf("");
  const float inf = INFINITY;
  expect_rejected([] { return make_icosphere(1, 9); }, "subdivisions");
  expect_rejected([] { return make_icosphere(1, -1); }, "subdivisions");
  expect_rejected([] { return make_icosphere(0, 2); }, "radius");
  expect_rejected([] { return make_icosphere(-1, 2); }, "radius");
  expect_rejected([&] { return make_icosphere(nan, 2); }, "radius");
  expect_rejected([&] { return make_icosphere(inf, 2); }, "radius");
  expect_rejected([] { return make_icosphere(2e6f, 2); }, "radius");
  expect_rejected([] { return make_uvsphere(1, 4097, 8); }, "segments");
  expect_rejected([] { return make_uvsphere(1, 2, 8); }, "segments");
  expect_rejected([] { return make_uvsphere(1, 8, 1); }, "rings");
  expect_rejected([] { return make_uvsphere(1, 4096, 4096); }, "triangles");
  expect_rejected([] { return make_torus(1, 0.3f, 4097, 8); }, "segments");
  expect_rejected([] { return make_torus(1, 0.3f, 8, 2); }, "sides");
  expect_rejected([] { return make_torus(1, 1, 8, 8); }, "minor");
  expect_rejected([] { return make_torus(1, 2, 8, 8); }, "minor");
  expect_rejected([&] { return make_torus(nan, 0.3f, 8, 8); }, "major");
  expect_rejected([] { return make_torus(1, 0, 8, 8); }, "minor");
  expect_rejected([] { return make_plane(0, 1); }, "size");
  expect_rejected([] { return make_plane(1, 0); }, "divisions");
  expect_rejected([] { return make_plane(1, 4096); }, "triangles");
  expect_rejected([] { return make_cube(-2, 1); }, "size");
  expect_rejected([] { return make_cube(1, 0); }, "divisions");
  expect_rejected([] { return make_cube(1, 1000); }, "triangles");
}

TEST(Primitives, SourceNamesThePrimitive) {
  EXPECT_EQ(make_icosphere(1, 0).source, "icosphere");
  EXPECT_EQ(make_uvsphere(1, 3, 2).source, "uvsphere");
  EXPECT_EQ(make_torus(1, 0.5f, 3, 3).source, "torus");
  EXPECT_EQ(make_plane(1, 1).source, "plane");
  EXPECT_EQ(make_cube(1, 1).source, "cube");
}

}  // namespace
}  // namespace fastshade
