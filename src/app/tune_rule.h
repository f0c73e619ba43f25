// `fastshade tune`'s decision, as a pure function of the measured table: the fastest
// candidate whose error stays within the budget on every scene.
#pragma once
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace fastshade {

// One candidate on one scene.
struct SceneFigures {
  double median_ms = 0;              // median frame time
  double max_abs_lsb = 0;            // against `reference`, in 8-bit steps
  double pct_covered_over_1lsb = 0;  // covered pixels off by more than 1 LSB, %
};

struct TuneCriteria {
  double max_abs_lsb = 1;            // --max-error
  double max_pct_over_1lsb = 100;    // --max-pct-over-1lsb (100: no limit)
  // --min-gain: the baseline (render's defaults) is kept unless the fastest candidate within
  // the budget beats it by more than this, in %: on a shared machine, smaller differences
  // are noise and would make the choice change from run to run.
  double min_gain_pct = 3;
  std::size_t baseline = 0;          // the candidate that is render's defaults
};

struct Verdict {
  double geomean_ms = 0;             // geometric mean of the scenes' median_ms
  double worst_max_abs_lsb = 0;      // over the scenes
  double worst_pct_over_1lsb = 0;    // over the scenes
  std::string rejected_because;      // "" if within the budget on every scene
};

struct TuneDecision {
  std::vector<Verdict> verdicts;           // one per candidate, in the table's order
  std::vector<std::size_t> fastest_first;  // candidate indices by geomean_ms, then error
  std::optional<std::size_t> fastest;      // the first of fastest_first within the budget
  std::optional<std::size_t> chosen;       // `fastest`, or the baseline if within min_gain_pct
  double fastest_gain_pct = 0;             // how much faster `fastest` is than the baseline
};

// Scenes are weighed alike: the geometric mean makes a candidate 10 % faster on every scene
// 10 % faster overall however large or small each scene's frame is (a sum would let the
// slowest scene decide alone). A candidate is within the budget iff on every scene its max
// error is <= budget.max_abs_lsb and its share of pixels over 1 LSB <= max_pct_over_1lsb; a
// time or error that is not a number rejects it. Equal times go to the smaller worst error,
// then to the earlier candidate. The fastest within the budget is chosen unless the baseline is
// within the budget too and no more than min_gain_pct slower. `table[c][s]`: candidate c on
// scene s (every row as long as `scene_names`).
TuneDecision decide_tuning(std::span<const std::vector<SceneFigures>> table,
                           std::span<const std::string> scene_names, const TuneCriteria& criteria);

}  // namespace fastshade
