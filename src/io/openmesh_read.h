// Reads a mesh file into an OpenMesh TriMesh after precheck_mesh_file, and checks what OpenMesh
// built: nothing it skipped silently (bad indices, short faces, a truncated file), no NaN/Inf
// position, at least one face. Shared by load_mesh and inspect_mesh.
#pragma once
#include <cstdint>
#include <filesystem>
#include <vector>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

namespace fastshade::io {

using OmMesh = OpenMesh::TriMesh_ArrayKernelT<>;

struct OmRead {
  OmMesh mesh;  // has vertex normals requested when read with want_normals
  // Per vertex: the file gave it a normal (raw, maybe zero or NaN). Vertices OpenMesh
  // duplicated at non-manifold spots inherit their original's. Empty without want_normals.
  std::vector<uint8_t> file_normal;
  // True when the file gave a normal to every vertex some face uses.
  bool has_file_normals = false;
  std::size_t duplicated_vertices = 0;  // added by OpenMesh at non-manifold vertices/edges
  std::size_t dropped_degenerate_faces = 0;  // repeated vertex indices: OpenMesh cannot store
};

// Throws InputError("PATH: problem") for anything wrong with the file. Thread-safe: concurrent
// calls read in parallel, each through an OpenMesh reader object of its own.
void read_checked(const std::filesystem::path& path, bool want_normals, OmRead& out);

}  // namespace fastshade::io
