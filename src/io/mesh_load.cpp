// load_mesh: OpenMesh TriMesh -> plain arrays, then weld and normals as asked.
#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "fastshade/mesh.h"
#include "io/mesh_checks.h"
#include "io/mesh_weld.h"
#include "io/openmesh_read.h"

namespace fastshade {

namespace {

bool usable_normal(const glm::vec3& n) {
  const float len2 = glm::dot(n, n);
  return std::isfinite(len2) && len2 > 0.0f;
}

}  // namespace

Mesh load_mesh(const std::filesystem::path& path, const MeshLoadOptions& options) {
  const bool want_normals = options.normals != NormalsMode::Recompute;
  io::OmRead read;
  io::read_checked(path, want_normals, read);
  const io::OmMesh& om = read.mesh;

  Mesh mesh;
  mesh.source = path.string();
  const std::size_t nv = om.n_vertices();
  const std::size_t nf = om.n_faces();
  mesh.positions.resize(nv);
  const auto* points = om.points();
  for (std::size_t i = 0; i < nv; ++i) {
    mesh.positions[i] = glm::vec3(points[i][0], points[i][1], points[i][2]);
  }
  // Each face's three vertices in the order of its halfedge cycle, which starts at the face's
  // halfedge and keeps the file's winding.
  mesh.triangles.resize(nf);
  for (std::size_t f = 0; f < nf; ++f) {
    auto h = om.halfedge_handle(OpenMesh::FaceHandle(static_cast<int>(f)));
    for (int k = 0; k < 3; ++k) {
      mesh.triangles[f][static_cast<std::size_t>(k)] =
          static_cast<uint32_t>(om.to_vertex_handle(h).idx());
      h = om.next_halfedge_handle(h);
    }
  }

  // File normals, if the file gave every used vertex one; checked after welding, which keeps
  // the first of the merged vertices' normals.
  bool file_normals = false;
  if (want_normals && read.has_file_normals) {
    const auto* normals = om.vertex_normals();
    mesh.normals.resize(nv);
    for (std::size_t i = 0; i < nv; ++i) {
      mesh.normals[i] = read.file_normal[i]
                            ? glm::vec3(normals[i][0], normals[i][1], normals[i][2])
                            : glm::vec3(0.0f);
    }
    file_normals = true;
  }

  if (options.weld) io::weld_vertices(mesh);

  if (file_normals) {
    // Every vertex a triangle uses needs a finite non-zero normal; unused vertices get +Z.
    std::vector<uint8_t> used(mesh.positions.size(), 0);
    for (const auto& tri : mesh.triangles) used[tri[0]] = used[tri[1]] = used[tri[2]] = 1;
    std::size_t bad = 0, first_bad = 0;
    for (std::size_t i = 0; i < mesh.normals.size(); ++i) {
      glm::vec3& n = mesh.normals[i];
      if (usable_normal(n)) {
        n = glm::normalize(n);
      } else if (used[i]) {
        if (bad++ == 0) first_bad = i;
      } else {
        n = glm::vec3(0.0f, 0.0f, 1.0f);
      }
    }
    if (bad > 0) {
      if (options.normals == NormalsMode::File) {
        const glm::vec3 n = mesh.normals[first_bad];
        io::fail(path, "unusable vertex normals in file: " + std::to_string(bad) +
                           " zero or non-finite, the first at vertex " +
                           std::to_string(first_bad) + " (" + std::to_string(n.x) + ", " +
                           std::to_string(n.y) + ", " + std::to_string(n.z) + ")");
      }
      file_normals = false;  // Auto: recompute instead
    }
  } else if (options.normals == NormalsMode::File) {
    io::fail(path, "no vertex normals in file");
  }
  if (!file_normals) recompute_normals(mesh);
  return mesh;
}

}  // namespace fastshade
