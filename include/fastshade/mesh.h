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

// Loads OBJ, OFF, PLY or STL (extension in any case) through OpenMesh and checks it: throws
// InputError, one line "PATH: problem", for a missing/unreadable/empty file, a directory, an
// unknown extension, no faces (a point cloud), header counts the file size cannot hold, face
// indices out of range (or 0 in OBJ), faces with < 3 vertices, NaN/Inf coordinates, text that
// is not 8-bit (UTF-16), and anything OpenMesh fails to read or silently skips.
// Kept as in the file: zero-area faces, unreferenced vertices, any winding. Polygons become fan
// triangles. Faces whose vertex indices repeat are dropped (a halfedge mesh cannot hold them;
// they have zero area). At non-manifold vertices and edges OpenMesh adds copies of vertices, and
// binary/ASCII STL vertices are merged by position on read: the vertex count is OpenMesh's.
// Normals: File takes the file's (every vertex a face uses must have a finite non-zero one,
// else InputError; "no vertex normals in file" if it has none), normalised; Auto takes them if
// so, else recomputes; Recompute ignores them. Vertices on no face get +Z.
// weld merges bit-equal positions after loading, before normals (first vertex's normal kept).
// Thread-safe: concurrent loads run in parallel (OpenMesh included).
Mesh load_mesh(const std::filesystem::path& path, const MeshLoadOptions& options = {});

// Area-weighted vertex normals: each vertex gets the normalised sum of the unnormalised cross
// products of its triangles (summed in double). Zero-area triangles add nothing; a vertex whose
// sum is zero or non-finite (on no triangle, or only on degenerate ones) gets +Z. Throws
// InputError(mesh.source, ...) if a triangle index is out of range.
void recompute_normals(Mesh& mesh);

// A mesh built in code, checked as a loaded one is: at least one triangle, finite vertices,
// triangle indices in range, normals none or one finite non-zero one per vertex. Throws
// InputError(mesh.source, "vertex 7 is not finite").
void check_mesh(const Mesh& mesh);

struct MeshInfo {
  std::size_t vertices = 0;  // as OpenMesh holds them (its non-manifold copies included)
  std::size_t faces = 0;     // triangles after triangulation
  std::size_t zero_area_faces = 0;        // cross product exactly 0 in double
  std::size_t unreferenced_vertices = 0;  // on no face
  std::size_t boundary_edges = 0;         // as OpenMesh's halfedge structure sees them
  glm::vec3 bbox_min{0.0f}, bbox_max{0.0f};  // over all vertices, unreferenced ones included
  bool has_normals = false;  // the file gives a normal to every vertex a face uses
};

// Reads the file exactly as load_mesh does (same checks, same InputErrors) and counts.
MeshInfo inspect_mesh(const std::filesystem::path& path);

}  // namespace fastshade
