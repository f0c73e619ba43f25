// Approximations of the specular lobe cos^n(gamma) = max(N.H, 0)^n (frame/brdf_params.h): the
// paper's and the classics, each a small float kernel with parameters fixed per material
// (shininess) once per frame. Definitions, errors and the readings chosen for garbled formulas:
// docs/KERNELS.md.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "core/simd_target.h"
#include "frame/brdf_params.h"

namespace fastshade {

// Every kind once, CosK with K = 1 and 3: what tables and tests sweep.
std::vector<BrdfChoice> brdf_choices();

// Fits and precomputes the parameters for shininess n in [1, 1e6] (fits take well under a
// millisecond; done once per material and frame).
BrdfParams make_brdf(const BrdfChoice& choice, double n);

// One value, as the kernel's scalar twin computes it (light/brdf_testing.h): for scalar paths (Gouraud's vertex lighting).
float eval_brdf_one(const BrdfParams& p, float n_dot_h);

// The SIMD kernel on the ISA `simd` (core/simd_target.h), for tests and tables.
void eval_brdf(SimdTarget simd, const BrdfParams& p, const float* n_dot_h, float* out, std::size_t count);

// cos^n(gamma) exactly, in double, for c = cos(gamma) (0 for c <= 0).
double cos_power(double c, double n);

// max |approximation - cos^n(gamma)| over gamma in [0, pi/2] by the SIMD kernel, on `points` + 1
// angles uniform in gamma and as many uniform in the lobe's [0, 10 / sqrt(n)]: what
// `fastshade brdf-table` reports (with 20000).
double brdf_max_error(const BrdfParams& p, double n, int points);

}  // namespace fastshade
