// fastshade brdf-table: each BRDF approximation's max abs error against cos^n on [0, pi/2]
// and its cost in ns per evaluation on this machine's chosen ISA.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "app/commands.h"
#include "core/simd_target.h"
#include "light/brdf.h"

namespace fastshade {

namespace {

const double kTableShininess[] = {1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 1e4};

// Angles per grid (uniform in gamma, and dense in the lobe) for each table entry.
constexpr int kErrorGridPoints = 20000;

// Median over 7 runs of one pass over 64 Ki values in [0, 1] (L2-resident), ns per value.
double ns_per_eval(SimdTarget simd, const BrdfParams& p) {
  std::vector<float> c(65536), out(c.size());
  for (std::size_t i = 0; i < c.size(); ++i) c[i] = float(i) / float(c.size());
  std::vector<double> runs;
  for (int r = 0; r < 7; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    for (int rep = 0; rep < 8; ++rep) eval_brdf(simd, p, c.data(), out.data(), c.size());
    const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count();
    runs.push_back(ns / (8.0 * c.size()));
  }
  std::sort(runs.begin(), runs.end());
  return runs[runs.size() / 2];
}

}  // namespace

int run_brdf_table(Isa isa) {
  const SimdTarget simd = simd_target(isa);
  std::printf("max |approximation - cos^n(gamma)| over gamma in [0, pi/2]; cost in ns per value (%s)\n\n",
              simd_target_name(simd).c_str());
  std::printf("| method |");
  for (double n : kTableShininess) std::printf(" n=%g |", n);
  std::printf(" ns/value |\n|---|");
  for (std::size_t i = 0; i < std::size(kTableShininess); ++i) std::printf("---:|");
  std::printf("---:|\n");
  for (const BrdfChoice& choice : brdf_choices()) {
    std::printf("| %s |", option_name(choice).c_str());
    for (double n : kTableShininess) std::printf(" %.2g |", brdf_max_error(make_brdf(choice, n), n, kErrorGridPoints));
    std::printf(" %.3f |\n", ns_per_eval(simd, make_brdf(choice, 100)));
  }
  return 0;
}

}  // namespace fastshade
