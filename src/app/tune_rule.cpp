#include "app/tune_rule.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

#include "app/format.h"

namespace fastshade {

namespace {

// Why candidate `row` is outside the budget ("" if it is not), naming its worst scenes.
std::string rejection(const std::vector<SceneFigures>& row, std::span<const std::string> names,
                      const TuneCriteria& criteria) {
  std::string why;
  const auto add = [&](const std::string& reason) { why += (why.empty() ? "" : "; ") + reason; };
  std::size_t worst_max = 0, worst_pct = 0;
  for (std::size_t s = 0; s < row.size(); ++s) {
    const SceneFigures& f = row[s];
    if (!std::isfinite(f.median_ms) || !std::isfinite(f.max_abs_lsb) || !std::isfinite(f.pct_covered_over_1lsb))
      add("no figures on " + names[s]);
    if (f.max_abs_lsb > row[worst_max].max_abs_lsb) worst_max = s;
    if (f.pct_covered_over_1lsb > row[worst_pct].pct_covered_over_1lsb) worst_pct = s;
  }
  if (!why.empty()) return why;
  if (row[worst_max].max_abs_lsb > criteria.max_abs_lsb)
    add("max error " + format_double("%g", row[worst_max].max_abs_lsb) + " LSB > " +
        format_double("%g", criteria.max_abs_lsb) + " on " + names[worst_max]);
  if (row[worst_pct].pct_covered_over_1lsb > criteria.max_pct_over_1lsb)
    add(format_double("%.3g", row[worst_pct].pct_covered_over_1lsb) + " % of pixels > 1 LSB (limit " +
        format_double("%g", criteria.max_pct_over_1lsb) + " %) on " + names[worst_pct]);
  return why;
}

}  // namespace

TuneDecision decide_tuning(std::span<const std::vector<SceneFigures>> table,
                           std::span<const std::string> scene_names, const TuneCriteria& criteria) {
  TuneDecision d;
  for (const std::vector<SceneFigures>& row : table) {
    Verdict v;
    double log_sum = 0;
    for (const SceneFigures& f : row) {
      log_sum += std::log(f.median_ms);
      v.worst_max_abs_lsb = std::max(v.worst_max_abs_lsb, f.max_abs_lsb);
      v.worst_pct_over_1lsb = std::max(v.worst_pct_over_1lsb, f.pct_covered_over_1lsb);
    }
    v.geomean_ms = row.empty() ? NAN : std::exp(log_sum / double(row.size()));
    v.rejected_because = row.empty() ? "no scenes" : rejection(row, scene_names, criteria);
    if (v.rejected_because.empty() && !std::isfinite(v.geomean_ms)) v.rejected_because = "no time measured";
    d.verdicts.push_back(std::move(v));
  }
  d.fastest_first.resize(table.size());
  std::iota(d.fastest_first.begin(), d.fastest_first.end(), std::size_t{0});
  // NaN times sort last: compare "is not a number" first.
  const auto key = [&](std::size_t i) {
    const Verdict& v = d.verdicts[i];
    return std::tuple{std::isnan(v.geomean_ms), std::isnan(v.geomean_ms) ? 0.0 : v.geomean_ms, v.worst_max_abs_lsb};
  };
  std::stable_sort(d.fastest_first.begin(), d.fastest_first.end(),
                   [&](std::size_t a, std::size_t b) { return key(a) < key(b); });
  for (std::size_t i : d.fastest_first) {
    if (d.verdicts[i].rejected_because.empty()) {
      d.fastest = d.chosen = i;
      break;
    }
  }
  if (!d.fastest || criteria.baseline >= table.size()) return d;
  const Verdict& baseline = d.verdicts[criteria.baseline];
  d.fastest_gain_pct = 100.0 * (baseline.geomean_ms / d.verdicts[*d.fastest].geomean_ms - 1.0);
  if (baseline.rejected_because.empty() && d.fastest_gain_pct <= criteria.min_gain_pct) d.chosen = criteria.baseline;
  return d;
}

}  // namespace fastshade
