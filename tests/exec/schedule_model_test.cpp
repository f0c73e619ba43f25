// The load-balance model's schedule simulator on hand-made cost lists.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <stdexcept>

#include "fastshade/profile.h"

namespace fastshade {
namespace {

TEST(ListSchedule, OneWorkerTakesTheSum) {
  const std::vector<double> items = {3, 1, 4, 1, 5, 9, 2, 6};
  EXPECT_DOUBLE_EQ(list_schedule_ms(items, 1), 31.0);
}

TEST(ListSchedule, AsManyWorkersAsItemsTakeTheLargestItem) {
  const std::vector<double> items = {3, 1, 4, 1, 5, 9, 2, 6};
  for (const int workers : {8, 9, 64, 1000}) EXPECT_DOUBLE_EQ(list_schedule_ms(items, workers), 9.0) << workers;
}

TEST(ListSchedule, HandsOutInOrderNotLargestFirst) {
  // {3 | 1 1 1}: the 3 runs beside the three 1s.
  EXPECT_DOUBLE_EQ(list_schedule_ms(std::vector<double>{3, 1, 1, 1}, 2), 3.0);
  // {1 1 1 3}: the 3 comes last and starts when a worker frees at t = 1: worker A 1+1,
  // worker B 1+3. Largest-first would give 3.
  EXPECT_DOUBLE_EQ(list_schedule_ms(std::vector<double>{1, 1, 1, 3}, 2), 4.0);
  // Three workers, {2 2 2 1 1 1}: each takes a 2, then a 1.
  EXPECT_DOUBLE_EQ(list_schedule_ms(std::vector<double>{2, 2, 2, 1, 1, 1}, 3), 3.0);
}

TEST(ListSchedule, EmptyListTakesNothingAndZeroWorkersIsRefused) {
  EXPECT_DOUBLE_EQ(list_schedule_ms({}, 4), 0.0);
  EXPECT_THROW(list_schedule_ms(std::vector<double>{1}, 0), std::invalid_argument);
}

TEST(ListSchedule, StaysWithinGrahamsBounds) {
  // For any list: max(sum / P, largest) <= greedy <= sum / P + largest.
  std::mt19937 rng(7);
  std::exponential_distribution<double> cost(1.0);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<double> items(1 + rng() % 50);
    for (double& c : items) c = cost(rng);
    const double sum = std::accumulate(items.begin(), items.end(), 0.0);
    const double largest = *std::max_element(items.begin(), items.end());
    for (const int p : {1, 2, 3, 4, 8, 16, 64}) {
      const double t = list_schedule_ms(items, p);
      EXPECT_GE(t, std::max(sum / p, largest) - 1e-9) << "trial " << trial << " P " << p;
      EXPECT_LE(t, sum / p + largest + 1e-9) << "trial " << trial << " P " << p;
    }
  }
}

TEST(PredictSchedule, PhasesEndInBarriersAndStagesAddUp) {
  const std::vector<SchedulePhase> phases = {
      {"front_end", "a", {1, 1, 1}},  // 2 on two workers
      {"binning", "b", {5}},          // serial
      {"front_end", "c", {2, 2}},     // 2 on two workers
      {"raster_shade", "d", {4, 1, 1, 1, 1}},
  };
  const SchedulePrediction one = predict_schedule(phases, 1);
  EXPECT_DOUBLE_EQ(one.total_ms, 3 + 5 + 4 + 8);
  const SchedulePrediction two = predict_schedule(phases, 2);
  // Without the barrier the first and third phases would pack into 3.5, not 2 + 2.
  EXPECT_DOUBLE_EQ(two.total_ms, 2 + 5 + 2 + 4);
  ASSERT_EQ(two.stages.size(), 3u);
  EXPECT_EQ(two.stages[0].stage, "front_end");
  EXPECT_DOUBLE_EQ(two.stages[0].ms, 4.0);
  EXPECT_EQ(two.stages[1].stage, "binning");
  EXPECT_DOUBLE_EQ(two.stages[1].ms, 5.0);
  EXPECT_DOUBLE_EQ(two.stages[2].ms, 4.0);
  EXPECT_EQ(two.workers, 2);
  // Unboundedly many workers: every phase takes its largest item.
  EXPECT_DOUBLE_EQ(critical_path_ms(phases), 1 + 5 + 2 + 4);
  EXPECT_DOUBLE_EQ(predict_schedule(phases, 1000).total_ms, critical_path_ms(phases));
}

}  // namespace
}  // namespace fastshade
