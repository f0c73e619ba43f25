// Area-weighted vertex normals.
#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "fastshade/error.h"
#include "fastshade/mesh.h"

namespace fastshade {

void recompute_normals(Mesh& mesh) {
  const std::size_t n = mesh.positions.size();
  // Sums in double: a vertex of the 871k dragon collects a dozen cross products of very
  // different sizes, and float sums would depend on face order more than needed.
  std::vector<glm::dvec3> sum(n, glm::dvec3(0.0));
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    for (const uint32_t v : tri) {
      if (v >= n) {
        throw InputError(mesh.source, "triangle " + std::to_string(t) + " references vertex " +
                                          std::to_string(v) + " but the mesh has " +
                                          std::to_string(n) + " vertices");
      }
    }
    const glm::dvec3 p0(mesh.positions[tri[0]]);
    const glm::dvec3 p1(mesh.positions[tri[1]]);
    const glm::dvec3 p2(mesh.positions[tri[2]]);
    // |cross| is twice the area: the unnormalised cross product is the area weight. A
    // zero-area triangle adds exactly zero; a non-finite one (only from non-finite positions,
    // which loading rejects) is skipped so it cannot poison its vertices.
    const glm::dvec3 c = glm::cross(p1 - p0, p2 - p0);
    if (!(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z))) continue;
    sum[tri[0]] += c;
    sum[tri[1]] += c;
    sum[tri[2]] += c;
  }
  mesh.normals.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double len = glm::length(sum[i]);
    mesh.normals[i] = (len > 0.0 && std::isfinite(len)) ? glm::vec3(sum[i] / len)
                                                        : glm::vec3(0.0f, 0.0f, 1.0f);
  }
}

}  // namespace fastshade
