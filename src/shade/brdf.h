// Approximations of the specular lobe cos^n(gamma) = max(N.H, 0)^n: the paper's and the
// classics, each a small float kernel with parameters fixed per material (shininess) once per
// frame. Definitions, errors and the readings chosen for garbled formulas: docs/KERNELS.md.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace fastshade {

enum class BrdfKind {
  Exact,         // c^n as exp2(n log2 c)
  CosK,          // cos^K(sqrt(n/K) gamma), 0 once the argument passes pi/2 (paper, section II)
  Schlick,       // c / (n - n c + c)
  SchlickPow2,   // Schlick with exponent n / 2^m in [1, 2), squared m times (eq. 5 as NOTES reads it)
  Quadratic,     // ((n/2)(c - 1) + 1)^2, 0 past its root (paper, section III)
  QuadraticFit,  // (a (c - 1) + 1)^2 with the minimax a for this n
  Poly2,         // a0 + a1 x + a2 x^2, x = 1 - c, minimax for this n on a fitted support [0, X],
                 // zero past X or the first root
  Poly3,         // the same, cubic
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

// Parses "exact", "cosk:K" (K integer 1..8), "schlick", "schlick-pow2", "quadratic",
// "quadratic-fit", "poly2", "poly3"; throws InputError naming `where` otherwise.
struct BrdfChoice {
  BrdfKind kind = BrdfKind::Exact;
  int k = 3;
  std::string name() const;
};
BrdfChoice parse_brdf(std::string_view text, const std::string& where);
std::vector<std::string> brdf_names();  // one spelling each, "cosk:3" for CosK

// Fits and precomputes the parameters for shininess n in [1, 1e6] (fits take well under a
// millisecond; done once per material and frame).
BrdfParams make_brdf(const BrdfChoice& choice, double n);

// One value, as eval_brdf_scalar: for scalar paths (Gouraud's vertex lighting).
float eval_brdf_one(const BrdfParams& p, float n_dot_h);

// The scalar reference of the SIMD kernel (shade/brdf-inl.h): the same float operations in the
// same order. Inputs are N.H values, any float; outputs are in [0, 1], 0 for NaN.
void eval_brdf_scalar(const BrdfParams& p, const float* n_dot_h, float* out, std::size_t count);

// The SIMD kernel on the process's chosen ISA (exec/isa.h), for tests and tables.
void eval_brdf(const BrdfParams& p, const float* n_dot_h, float* out, std::size_t count);

// cos^n(gamma) exactly, in double, for c = cos(gamma) (0 for c <= 0).
double cos_power(double c, double n);

// max |approximation - cos^n(gamma)| over gamma in [0, pi/2] by the SIMD kernel, on `points` + 1
// angles uniform in gamma and as many uniform in the lobe's [0, 10 / sqrt(n)]: what
// `fastshade brdf-table` reports (with 20000).
double brdf_max_error(const BrdfParams& p, double n, int points);

}  // namespace fastshade
