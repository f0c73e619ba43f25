// `fastshade tune`'s decision on hand-made tables: no timing, only the rule.
#include "app/tune_rule.h"

#include <gtest/gtest.h>

#include <cmath>

namespace fastshade {
namespace {

const std::vector<std::string> kScenes = {"a.json", "b.json"};

// {ms, max LSB, % > 1 LSB} on a.json, then on b.json.
std::vector<SceneFigures> row(SceneFigures a, SceneFigures b) { return {a, b}; }

TEST(TuneRule, FastestWithinBudgetOnEverySceneWins) {
  const std::vector<std::vector<SceneFigures>> table = {
      row({10, 1, 0}, {20, 1, 0}),  // 0: the baseline, geo. mean 14.1
      row({4, 1, 0}, {30, 3, 2}),   // 1: fastest (11.0), but 3 LSB on b.json
      row({8, 0, 0}, {18, 1, 0}),   // 2: 12.0, within: the choice
      row({9, 1, 0}, {19, 0, 0}),   // 3: 13.1, within
  };
  const TuneDecision d = decide_tuning(table, kScenes, {.max_abs_lsb = 1, .baseline = 0});
  ASSERT_TRUE(d.chosen.has_value());
  EXPECT_EQ(*d.chosen, 2u);
  EXPECT_EQ(d.fastest, d.chosen);
  EXPECT_EQ(d.fastest_first, (std::vector<std::size_t>{1, 2, 3, 0}));
  EXPECT_NEAR(d.verdicts[1].geomean_ms, std::sqrt(4.0 * 30.0), 1e-9);
  EXPECT_EQ(d.verdicts[1].worst_max_abs_lsb, 3);
  EXPECT_EQ(d.verdicts[1].worst_pct_over_1lsb, 2);
  EXPECT_EQ(d.verdicts[1].rejected_because, "max error 3 LSB > 1 on b.json");
  EXPECT_EQ(d.verdicts[2].rejected_because, "");
  EXPECT_NEAR(d.fastest_gain_pct, 100 * (std::sqrt(200.0) / std::sqrt(144.0) - 1), 1e-9);
}

TEST(TuneRule, GeometricMeanWeighsScenesAlike) {
  // 0 is 20 % faster on the small scene, 1 is 10 % faster on the large one: a sum would pick 1
  // (100 < 108), the geometric mean picks 0 (sqrt(8 * 100) < sqrt(10 * 90)).
  const std::vector<std::vector<SceneFigures>> table = {row({8, 0, 0}, {100, 0, 0}),
                                                        row({10, 0, 0}, {90, 0, 0})};
  const TuneDecision d = decide_tuning(table, kScenes, {.min_gain_pct = 0, .baseline = 1});
  EXPECT_EQ(d.chosen, 0u);
}

TEST(TuneRule, ShareOfPixelsOverOneStepIsASecondLimit) {
  const std::vector<std::vector<SceneFigures>> table = {row({10, 2, 0.5}, {10, 2, 0.5}),
                                                        row({5, 2, 0.1}, {5, 2, 3.0})};
  const TuneCriteria no_share_limit{.max_abs_lsb = 2, .min_gain_pct = 0};
  EXPECT_EQ(decide_tuning(table, kScenes, no_share_limit).chosen, 1u);
  TuneCriteria with_limit = no_share_limit;
  with_limit.max_pct_over_1lsb = 1;
  const TuneDecision d = decide_tuning(table, kScenes, with_limit);
  EXPECT_EQ(d.chosen, 0u);
  EXPECT_EQ(d.verdicts[1].rejected_because, "3 % of pixels > 1 LSB (limit 1 %) on b.json");
}

TEST(TuneRule, TheBaselineStaysUnlessBeatenByMoreThanTheMinimumGain) {
  const std::vector<std::vector<SceneFigures>> table = {row({10, 1, 0}, {10, 1, 0}),  // baseline
                                                        row({9.8, 1, 0}, {9.8, 1, 0})};
  TuneCriteria c{.min_gain_pct = 3, .baseline = 0};
  TuneDecision d = decide_tuning(table, kScenes, c);
  EXPECT_EQ(d.fastest, 1u);
  EXPECT_EQ(d.chosen, 0u);  // 2 % faster: noise on a shared machine
  c.min_gain_pct = 1;
  d = decide_tuning(table, kScenes, c);
  EXPECT_EQ(d.chosen, 1u);
  // A baseline over the budget is no fallback.
  const std::vector<std::vector<SceneFigures>> over = {row({10, 5, 0}, {10, 1, 0}), table[1]};
  c.min_gain_pct = 3;
  EXPECT_EQ(decide_tuning(over, kScenes, c).chosen, 1u);
}

TEST(TuneRule, NothingWithinBudgetChoosesNothing) {
  const std::vector<std::vector<SceneFigures>> table = {row({10, 2, 0}, {10, 1, 0}),
                                                        row({10, NAN, 0}, {10, 0, 0})};
  const TuneDecision d = decide_tuning(table, kScenes, {.max_abs_lsb = 1});
  EXPECT_FALSE(d.chosen.has_value());
  EXPECT_FALSE(d.fastest.has_value());
  EXPECT_EQ(d.verdicts[0].rejected_because, "max error 2 LSB > 1 on a.json");
  EXPECT_EQ(d.verdicts[1].rejected_because, "no figures on a.json");
}

TEST(TuneRule, EqualTimesGoToTheSmallerErrorThenTheEarlierCandidate) {
  const std::vector<std::vector<SceneFigures>> table = {
      row({10, 1, 0}, {10, 1, 0}), row({10, 0, 0}, {10, 0, 0}), row({10, 0, 0}, {10, 0, 0}),
      row({11, 0, 0}, {11, 0, 0})};
  const TuneDecision d = decide_tuning(table, kScenes, {.min_gain_pct = 0, .baseline = 3});
  EXPECT_EQ(d.fastest_first, (std::vector<std::size_t>{1, 2, 0, 3}));
  EXPECT_EQ(d.chosen, 1u);
}

}  // namespace
}  // namespace fastshade
