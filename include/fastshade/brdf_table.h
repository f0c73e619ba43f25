// Each BRDF approximation's error against cos^n and its cost on one ISA: what
// `fastshade brdf-table` prints (docs/KERNELS.md).
#pragma once
#include <string>
#include <vector>

#include "fastshade/options.h"

namespace fastshade {

struct BrdfTableRow {
  BrdfChoice brdf;
  std::vector<double> max_error;  // max |approximation - cos^n(gamma)| over [0, pi/2], per shininess
  double ns_per_value = 0;        // at n = 100, median of 7 passes over 64 Ki L2-resident values
};
struct BrdfTable {
  std::string isa;                // the ISA the costs were measured on ("avx512")
  std::vector<double> shininess;  // the columns of max_error
  std::vector<BrdfTableRow> rows;  // every kind, CosK with K = 1 and 3
};

// Measures the table (about a second). Throws InputError for an ISA this CPU cannot run.
BrdfTable measure_brdf_table(Isa isa);

}  // namespace fastshade
