// The specular lobe a frame shades with, as plain data: which approximation of
// cos^n(gamma) = max(N.H, 0)^n, and its parameters fitted to one material's shininess. The
// fits and kernels that read them are the light model's (light/brdf.h; definitions, errors and
// the readings chosen for garbled formulas: docs/KERNELS.md).
#pragma once
#include "fastshade/options.h"

namespace fastshade {

struct BrdfParams {
  BrdfKind kind = BrdfKind::Exact;
  float n = 1;           // the shininess
  int k = 3;             // CosK: the power K
  float scale = 1;       // CosK: sqrt(n / K); Quadratic*: the slope a
  float n_reduced = 1;   // SchlickPow2: n / 2^m
  int squarings = 0;     // SchlickPow2: m
  float poly[4] = {};    // Poly*: a0, a1, a2, a3
  float x_root = 1;      // Poly*: zero from here on (the support or the first root)
};

}  // namespace fastshade
