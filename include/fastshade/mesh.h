// A triangle mesh as plain arrays: what io/ produces and the front end consumes.
#pragma once
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace fastshade {

struct Mesh {
  std::vector<glm::vec3> positions;              // object space
  std::vector<glm::vec3> normals;                // per vertex, unit length; empty = none
  std::vector<std::array<uint32_t, 3>> triangles;  // indices into positions
  std::string source;                            // file path or primitive name, for messages
};

enum class NormalsMode { Auto, File, Recompute };  // Auto: the file's if present, else recompute

struct MeshLoadOptions {
  NormalsMode normals = NormalsMode::Auto;
  bool weld = false;  // merge vertices with bit-equal positions before anything else
};

// Loads OBJ, OFF, PLY or STL through OpenMesh and checks it: throws InputError naming the
// file for a missing/unreadable file, a directory, no faces, lying headers, out-of-range
// indices, NaN/Inf coordinates, or text that is not 8-bit (UTF-16).
Mesh load_mesh(const std::filesystem::path& path, const MeshLoadOptions& options = {});

// Area-weighted vertex normals from the faces; vertices on no (non-degenerate) face get +Z.
void recompute_normals(Mesh& mesh);

struct MeshInfo {
  std::size_t vertices = 0;
  std::size_t faces = 0;  // triangles after triangulation
  std::size_t zero_area_faces = 0;
  std::size_t unreferenced_vertices = 0;
  std::size_t boundary_edges = 0;  // as OpenMesh's halfedge structure sees them
  glm::vec3 bbox_min{0.0f}, bbox_max{0.0f};
  bool has_normals = false;
};

MeshInfo inspect_mesh(const std::filesystem::path& path);

}  // namespace fastshade
