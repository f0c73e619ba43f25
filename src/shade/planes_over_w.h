// PlanesOverW (shade/planes_over_w-inl.h) on the process's ISA, for tests: the kernels inline
// the per-target version.
#pragma once
#include <glm/vec3.hpp>

#include "raster/planes.h"

namespace fastshade {

void planes_over_w(const Barycentrics& b, const glm::vec3 v[3], double scale, const float inv_w[3], Plane out[4]);

}  // namespace fastshade
