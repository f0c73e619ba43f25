// Procedural meshes: OpenMesh holds the topology while it is built (shared icosphere midpoints
// come from its edge handles), then the result is copied into the plain Mesh arrays.
#include "fastshade/primitives.h"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "fastshade/error.h"

namespace fastshade {
namespace {

using OMesh = OpenMesh::TriMesh_ArrayKernelT<>;
using VH = OMesh::VertexHandle;

// ---- parameter checks -----------------------------------------------------------------------

std::string format(float value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.9g", double(value));
  return buffer;
}

void check_size(const char* primitive, const char* name, float value) {
  if (!(std::isfinite(value) && value > 0.0f && value <= kMaxPrimitiveSize))
    throw InputError(primitive, std::string(name) + " must be a number in (0, 1e6], got " +
                                    format(value));
}

void check_count(const char* primitive, const char* name, int value, int lo, int hi) {
  if (value < lo || value > hi)
    throw InputError(primitive, std::string(name) + " must be an integer in [" +
                                    std::to_string(lo) + ", " + std::to_string(hi) + "], got " +
                                    std::to_string(value));
}

void check_triangles(const char* primitive, int64_t triangles) {
  if (triangles > kMaxPrimitiveTriangles)
    throw InputError(primitive, std::to_string(triangles) + " triangles asked for, more than " +
                                    std::to_string(kMaxPrimitiveTriangles));
}

// ---- building -------------------------------------------------------------------------------

// Positions and normals are computed in double and rounded once to float.
VH add_vertex(OMesh& mesh, const glm::dvec3& position, const glm::dvec3& normal) {
  VH vh = mesh.add_vertex(OMesh::Point(float(position.x), float(position.y), float(position.z)));
  mesh.set_normal(vh, OMesh::Normal(float(normal.x), float(normal.y), float(normal.z)));
  return vh;
}

// a, b, c counter-clockwise seen from outside.
void add_triangle(OMesh& mesh, VH a, VH b, VH c) {
  // add_face refuses non-manifold input; every builder here is manifold by construction.
  if (!mesh.add_face(a, b, c).is_valid())
    throw std::logic_error("primitive builder made a non-manifold face");
}

OMesh new_mesh() {
  OMesh mesh;
  mesh.request_vertex_normals();
  return mesh;
}

Mesh to_mesh(const OMesh& om, std::string source) {
  Mesh mesh;
  mesh.source = std::move(source);
  mesh.positions.reserve(om.n_vertices());
  mesh.normals.reserve(om.n_vertices());
  for (VH vh : om.vertices()) {
    const OMesh::Point& p = om.point(vh);
    const OMesh::Normal& n = om.normal(vh);
    mesh.positions.emplace_back(p[0], p[1], p[2]);
    mesh.normals.emplace_back(n[0], n[1], n[2]);
  }
  mesh.triangles.reserve(om.n_faces());
  for (auto fh : om.faces()) {
    std::array<uint32_t, 3> tri{};
    int k = 0;
    for (VH vh : om.fv_range(fh)) tri[k++] = uint32_t(vh.idx());  // keeps the winding
    mesh.triangles.push_back(tri);
  }
  return mesh;
}

// A grid of `divisions` x `divisions` quads on the square centred at normal·offset, spanned by
// unit axes a and b with cross(a, b) = normal, side `size`. Each coordinate is one product
// (i/d - 1/2)·size, so two cube faces compute bit-equal positions along their shared edge.
void add_grid(OMesh& mesh, glm::dvec3 normal, glm::dvec3 a, glm::dvec3 b, double offset,
              double size, int divisions) {
  std::vector<VH> grid;  // (divisions + 1)^2, index i + j·(divisions + 1), i along a
  grid.reserve(size_t(divisions + 1) * size_t(divisions + 1));
  for (int j = 0; j <= divisions; ++j) {
    const double v = double(float((double(j) / divisions - 0.5) * size));
    for (int i = 0; i <= divisions; ++i) {
      const double u = double(float((double(i) / divisions - 0.5) * size));
      grid.push_back(add_vertex(mesh, normal * offset + a * u + b * v, normal));
    }
  }
  const int row = divisions + 1;
  for (int j = 0; j < divisions; ++j) {
    for (int i = 0; i < divisions; ++i) {
      VH p00 = grid[size_t(i + j * row)], p10 = grid[size_t(i + 1 + j * row)];
      VH p01 = grid[size_t(i + (j + 1) * row)], p11 = grid[size_t(i + 1 + (j + 1) * row)];
      add_triangle(mesh, p00, p10, p11);  // cross(a, a + b) = cross(a, b) = normal
      add_triangle(mesh, p00, p11, p01);
    }
  }
}

}  // namespace

Mesh make_icosphere(float radius, int subdivisions) {
  check_size("icosphere", "radius", radius);
  check_count("icosphere", "subdivisions", subdivisions, 0, kMaxIcosphereSubdivisions);

  // The icosahedron: the 12 vertices (0, ±1, ±φ) cyclically permuted, on the unit sphere.
  const double phi = std::numbers::phi;
  std::vector<glm::dvec3> dirs = {
      {-1, phi, 0}, {1, phi, 0}, {-1, -phi, 0}, {1, -phi, 0}, {0, -1, phi}, {0, 1, phi},
      {0, -1, -phi}, {0, 1, -phi}, {phi, 0, -1}, {phi, 0, 1}, {-phi, 0, -1}, {-phi, 0, 1}};
  for (glm::dvec3& d : dirs) d = glm::normalize(d);
  static constexpr int kFaces[20][3] = {
      {0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};

  OMesh mesh;
  for (size_t i = 0; i < dirs.size(); ++i) mesh.add_vertex(OMesh::Point(0, 0, 0));
  for (const auto& f : kFaces) add_triangle(mesh, VH(f[0]), VH(f[1]), VH(f[2]));

  // Each level splits every triangle in four at its edge midpoints; a midpoint belongs to the
  // edge, so the two triangles beside it share one vertex.
  for (int level = 0; level < subdivisions; ++level) {
    OMesh next;
    for (size_t i = 0; i < dirs.size(); ++i) next.add_vertex(OMesh::Point(0, 0, 0));
    std::vector<VH> midpoint(mesh.n_edges());
    for (auto eh : mesh.edges()) {
      auto h = mesh.halfedge_handle(eh, 0);
      const glm::dvec3 d = dirs[size_t(mesh.from_vertex_handle(h).idx())] +
                           dirs[size_t(mesh.to_vertex_handle(h).idx())];
      dirs.push_back(glm::normalize(d));
      midpoint[size_t(eh.idx())] = next.add_vertex(OMesh::Point(0, 0, 0));
    }
    for (auto fh : mesh.faces()) {
      auto h0 = mesh.halfedge_handle(fh);  // a -> b
      auto h1 = mesh.next_halfedge_handle(h0);  // b -> c
      auto h2 = mesh.next_halfedge_handle(h1);  // c -> a
      VH a = mesh.from_vertex_handle(h0), b = mesh.to_vertex_handle(h0),
         c = mesh.to_vertex_handle(h1);
      VH ab = midpoint[size_t(mesh.edge_handle(h0).idx())];
      VH bc = midpoint[size_t(mesh.edge_handle(h1).idx())];
      VH ca = midpoint[size_t(mesh.edge_handle(h2).idx())];
      add_triangle(next, a, ab, ca);
      add_triangle(next, b, bc, ab);
      add_triangle(next, c, ca, bc);
      add_triangle(next, ab, bc, ca);
    }
    mesh = std::move(next);
  }

  mesh.request_vertex_normals();
  for (VH vh : mesh.vertices()) {
    const glm::dvec3& d = dirs[size_t(vh.idx())];
    const glm::dvec3 p = d * double(radius);
    mesh.set_point(vh, OMesh::Point(float(p.x), float(p.y), float(p.z)));
    mesh.set_normal(vh, OMesh::Normal(float(d.x), float(d.y), float(d.z)));
  }
  return to_mesh(mesh, "icosphere");
}

Mesh make_uvsphere(float radius, int segments, int rings) {
  check_size("uvsphere", "radius", radius);
  check_count("uvsphere", "segments", segments, 3, kMaxPrimitiveSegments);
  check_count("uvsphere", "rings", rings, 2, kMaxPrimitiveSegments);
  check_triangles("uvsphere", int64_t{2} * segments * (rings - 1));

  // p(θ, φ) = r·(sin θ cos φ, cos θ, sin θ sin φ), θ from +Y; the outward normal is
  // cross(∂p/∂φ, ∂p/∂θ), so a quad is wound φ first, then θ.
  OMesh mesh = new_mesh();
  const double r = radius;
  const VH north = add_vertex(mesh, {0, r, 0}, {0, 1, 0});
  std::vector<VH> ring_vertices;  // (rings - 1) x segments, ring k = 1 .. rings - 1
  ring_vertices.reserve(size_t(rings - 1) * size_t(segments));
  for (int k = 1; k < rings; ++k) {
    const double theta = std::numbers::pi * k / rings;
    for (int i = 0; i < segments; ++i) {
      const double phi = 2.0 * std::numbers::pi * i / segments;
      const glm::dvec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                         std::sin(theta) * std::sin(phi));
      ring_vertices.push_back(add_vertex(mesh, n * r, n));
    }
  }
  const VH south = add_vertex(mesh, {0, -r, 0}, {0, -1, 0});

  auto at = [&](int k, int i) { return ring_vertices[size_t((k - 1) * segments + i % segments)]; };
  for (int i = 0; i < segments; ++i) add_triangle(mesh, north, at(1, i + 1), at(1, i));
  for (int k = 1; k + 1 < rings; ++k) {
    for (int i = 0; i < segments; ++i) {
      add_triangle(mesh, at(k, i), at(k, i + 1), at(k + 1, i + 1));
      add_triangle(mesh, at(k, i), at(k + 1, i + 1), at(k + 1, i));
    }
  }
  for (int i = 0; i < segments; ++i) add_triangle(mesh, at(rings - 1, i), at(rings - 1, i + 1), south);
  return to_mesh(mesh, "uvsphere");
}

Mesh make_torus(float major_radius, float minor_radius, int segments, int sides) {
  check_size("torus", "major", major_radius);
  check_size("torus", "minor", minor_radius);
  if (!(minor_radius < major_radius))
    throw InputError("torus", "minor (" + format(minor_radius) + ") must be less than major (" +
                                  format(major_radius) + ")");
  check_count("torus", "segments", segments, 3, kMaxPrimitiveSegments);
  check_count("torus", "sides", sides, 3, kMaxPrimitiveSegments);
  check_triangles("torus", int64_t{2} * segments * sides);

  // p(u, v) = ((R + r cos v) cos u, r sin v, (R + r cos v) sin u): u around Y, v around the
  // tube. The outward normal (cos v cos u, sin v, cos v sin u) is cross(∂p/∂v, ∂p/∂u), so a
  // quad is wound v first, then u.
  OMesh mesh = new_mesh();
  const double big = major_radius, small = minor_radius;
  std::vector<VH> grid;  // segments x sides, index i·sides + j
  grid.reserve(size_t(segments) * size_t(sides));
  for (int i = 0; i < segments; ++i) {
    const double u = 2.0 * std::numbers::pi * i / segments;
    for (int j = 0; j < sides; ++j) {
      const double v = 2.0 * std::numbers::pi * j / sides;
      const glm::dvec3 n(std::cos(v) * std::cos(u), std::sin(v), std::cos(v) * std::sin(u));
      const glm::dvec3 center(big * std::cos(u), 0.0, big * std::sin(u));
      grid.push_back(add_vertex(mesh, center + small * n, n));
    }
  }
  auto at = [&](int i, int j) { return grid[size_t((i % segments) * sides + j % sides)]; };
  for (int i = 0; i < segments; ++i) {
    for (int j = 0; j < sides; ++j) {
      add_triangle(mesh, at(i, j), at(i, j + 1), at(i + 1, j + 1));
      add_triangle(mesh, at(i, j), at(i + 1, j + 1), at(i + 1, j));
    }
  }
  return to_mesh(mesh, "torus");
}

Mesh make_plane(float size, int divisions) {
  check_size("plane", "size", size);
  check_count("plane", "divisions", divisions, 1, kMaxPrimitiveSegments);
  check_triangles("plane", int64_t{2} * divisions * divisions);
  OMesh mesh = new_mesh();
  add_grid(mesh, {0, 1, 0}, {0, 0, 1}, {1, 0, 0}, 0.0, size, divisions);
  return to_mesh(mesh, "plane");
}

Mesh make_cube(float size, int divisions) {
  check_size("cube", "size", size);
  check_count("cube", "divisions", divisions, 1, kMaxPrimitiveSegments);
  check_triangles("cube", int64_t{12} * divisions * divisions);
  OMesh mesh = new_mesh();
  // (normal, a, b) with cross(a, b) = normal for each face.
  static constexpr double kFaces[6][3][3] = {
      {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},  {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
      {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}},  {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
      {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}}};
  const double half = double(float(0.5 * double(size)));
  for (const auto& f : kFaces) {
    add_grid(mesh, {f[0][0], f[0][1], f[0][2]}, {f[1][0], f[1][1], f[1][2]},
             {f[2][0], f[2][1], f[2][2]}, half, size, divisions);
  }
  return to_mesh(mesh, "cube");
}

}  // namespace fastshade
