#include "fastshade/brdf_table.h"

#include <algorithm>
#include <chrono>
#include <iterator>

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

BrdfTable measure_brdf_table(Isa isa) {
  const SimdTarget simd = simd_target(isa);
  BrdfTable table;
  table.isa = simd_target_name(simd);
  table.shininess.assign(std::begin(kTableShininess), std::end(kTableShininess));
  for (const BrdfChoice& choice : brdf_choices()) {
    BrdfTableRow& row = table.rows.emplace_back();
    row.brdf = choice;
    for (double n : kTableShininess) row.max_error.push_back(brdf_max_error(make_brdf(choice, n), n, kErrorGridPoints));
    row.ns_per_value = ns_per_eval(simd, make_brdf(choice, 100));
  }
  return table;
}

}  // namespace fastshade
