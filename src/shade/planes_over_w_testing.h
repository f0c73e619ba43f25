// PlanesOverW (shade/planes_over_w-inl.h) on the ISA `simd`, for tests: the kernels inline
// the per-target version.
#pragma once
#include <glm/vec3.hpp>

#include "core/simd_target.h"
#include "raster/planes.h"

namespace fastshade {

void planes_over_w(SimdTarget simd, const Barycentrics& b, const glm::vec3 v[3], double scale, const float inv_w[3], Plane out[4]);

}  // namespace fastshade
