#include <cstdio>

#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "fastshade/mesh.h"

namespace fastshade {

int run_info(const std::string& path, bool json) {
  const MeshInfo info = inspect_mesh(path);
  if (json) {
    const nlohmann::json j = {{"mesh", path},
                              {"vertices", info.vertices},
                              {"faces", info.faces},
                              {"zero_area_faces", info.zero_area_faces},
                              {"unreferenced_vertices", info.unreferenced_vertices},
                              {"boundary_edges", info.boundary_edges},
                              {"bbox_min", {info.bbox_min.x, info.bbox_min.y, info.bbox_min.z}},
                              {"bbox_max", {info.bbox_max.x, info.bbox_max.y, info.bbox_max.z}},
                              {"has_normals", info.has_normals}};
    std::printf("%s\n", j.dump(2).c_str());
    return 0;
  }
  std::printf(
      "%s\n  vertices               %zu\n  faces                  %zu\n  zero-area faces        %zu\n"
      "  unreferenced vertices  %zu\n  boundary edges         %zu\n"
      "  bounding box           (%g, %g, %g) - (%g, %g, %g)\n  stored normals         %s\n",
      path.c_str(), info.vertices, info.faces, info.zero_area_faces, info.unreferenced_vertices,
      info.boundary_edges, info.bbox_min.x, info.bbox_min.y, info.bbox_min.z, info.bbox_max.x,
      info.bbox_max.y, info.bbox_max.z, info.has_normals ? "yes" : "no");
  return 0;
}

}  // namespace fastshade
