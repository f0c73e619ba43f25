// For tests only: the scalar twin of the lobe kernel (eval_brdf, light/brdf.h).
#pragma once
#include <cstddef>

#include "frame/brdf_params.h"

namespace fastshade {

// The scalar reference of the SIMD kernel (light/brdf-inl.h): the same float operations in the
// same order. Inputs are N.H values, any float; outputs are in [0, 1], 0 for NaN.
void eval_brdf_scalar(const BrdfParams& p, const float* n_dot_h, float* out, std::size_t count);

}  // namespace fastshade
