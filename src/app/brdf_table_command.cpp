// fastshade brdf-table: each BRDF approximation's max abs error against cos^n on [0, pi/2]
// and its cost in ns per evaluation on this machine's chosen ISA, as a markdown table.
#include <cstdio>

#include "app/commands.h"
#include "fastshade/brdf_table.h"

namespace fastshade {

int run_brdf_table(Isa isa) {
  const BrdfTable table = measure_brdf_table(isa);
  std::printf("max |approximation - cos^n(gamma)| over gamma in [0, pi/2]; cost in ns per value (%s)\n\n",
              table.isa.c_str());
  std::printf("| method |");
  for (double n : table.shininess) std::printf(" n=%g |", n);
  std::printf(" ns/value |\n|---|");
  for (std::size_t i = 0; i < table.shininess.size(); ++i) std::printf("---:|");
  std::printf("---:|\n");
  for (const BrdfTableRow& row : table.rows) {
    std::printf("| %s |", option_name(row.brdf).c_str());
    for (double e : row.max_error) std::printf(" %.2g |", e);
    std::printf(" %.3f |\n", row.ns_per_value);
  }
  return 0;
}

}  // namespace fastshade
