// The specular lobe a frame shades with, as plain data: which approximation of
// cos^n(gamma) = max(N.H, 0)^n, and its parameters fitted to one material's shininess. The
// fits and kernels that read them are the light model's (light/brdf.h; definitions, errors and
// the readings chosen for garbled formulas: docs/KERNELS.md).
#pragma once

namespace fastshade {

enum class BrdfKind {
  Exact,         // c^n as exp2(n log2 c)
  CosK,          // cos^K(sqrt(n/K) gamma), 0 once the argument passes pi/2 (paper, section II)
  Schlick,       // c / (n - n c + c)
  SchlickPow2,   // Schlick with exponent n / 2^m in [1, 2), squared m times (eq. 5 as
                 // docs/PAPER.md reads it)
  Quadratic,     // ((n/2)(c - 1) + 1)^2, 0 past its root (paper, section III)
  QuadraticFit,  // (a (c - 1) + 1)^2 with the minimax a for this n
  Poly2,         // a0 + a1 x + a2 x^2, x = 1 - c, minimax for this n on a fitted support [0, X],
                 // zero past X or the first root
  Poly3,         // the same, cubic
};

// The --brdf choice: a kind, and K for CosK.
struct BrdfChoice {
  BrdfKind kind = BrdfKind::Exact;
  int k = 3;
};

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
