// inspect_mesh: counts over the TriMesh exactly as OpenMesh built it.
#include <algorithm>
#include <vector>

#include <glm/common.hpp>

#include "fastshade/mesh.h"
#include "io/openmesh_read.h"

namespace fastshade {

MeshInfo inspect_mesh(const std::filesystem::path& path) {
  io::OmRead read;
  io::read_checked(path, /*want_normals=*/true, read);
  const io::OmMesh& om = read.mesh;

  MeshInfo info;
  info.vertices = om.n_vertices();
  info.faces = om.n_faces();
  info.has_normals = read.has_file_normals;

  std::vector<uint8_t> used(info.vertices, 0);
  const auto* points = om.points();
  for (const auto fh : om.faces()) {
    auto h = om.halfedge_handle(fh);
    int v[3];
    for (int& vi : v) {
      vi = om.to_vertex_handle(h).idx();
      used[static_cast<std::size_t>(vi)] = 1;
      h = om.next_halfedge_handle(h);
    }
    // Zero area means a cross product of exactly 0 in double: no threshold.
    double d[2][3];
    for (int c = 0; c < 3; ++c) {
      d[0][c] = double(points[v[1]][c]) - double(points[v[0]][c]);
      d[1][c] = double(points[v[2]][c]) - double(points[v[0]][c]);
    }
    const double cx = d[0][1] * d[1][2] - d[0][2] * d[1][1];
    const double cy = d[0][2] * d[1][0] - d[0][0] * d[1][2];
    const double cz = d[0][0] * d[1][1] - d[0][1] * d[1][0];
    if (cx == 0.0 && cy == 0.0 && cz == 0.0) ++info.zero_area_faces;
  }
  info.unreferenced_vertices =
      static_cast<std::size_t>(std::count(used.begin(), used.end(), uint8_t{0}));
  for (const auto eh : om.edges()) {
    if (om.is_boundary(eh)) ++info.boundary_edges;
  }
  // Over all vertices, unreferenced ones included: the extent of what the file holds.
  if (info.vertices > 0) {
    info.bbox_min = info.bbox_max = glm::vec3(points[0][0], points[0][1], points[0][2]);
    for (std::size_t i = 1; i < info.vertices; ++i) {
      const glm::vec3 p(points[i][0], points[i][1], points[i][2]);
      info.bbox_min = glm::min(info.bbox_min, p);
      info.bbox_max = glm::max(info.bbox_max, p);
    }
  }
  return info;
}

}  // namespace fastshade
