// The load-balance model: per-item costs measured on one thread, replayed as a schedule on P
// simulated workers. Pure functions of numbers; docs/SCALING.md states what they assume.
#pragma once
#include <span>
#include <string>
#include <vector>

namespace fastshade {

// One step of a frame: its items may run on any worker, in the order given, and the next phase
// starts only when all of them are done (a tbb::parallel_for ends in a barrier). A serial step
// is a phase of one item.
struct SchedulePhase {
  std::string stage;            // which reported stage it belongs to ("front_end", ...)
  std::string name;             // what its items are ("setup chunks", ...)
  std::vector<double> item_ms;  // in hand-out order
  bool timed_whole = false;     // timed as a whole (wall time) and split evenly into its items
};

// Greedy list schedule: each item, in order, goes to the worker that becomes free first.
// This is what dynamic hand-out of single items (TBB's simple_partitioner with work stealing)
// approaches when items are many; it is within one largest item of the optimum (Graham).
// workers >= 1; an empty list takes 0 ms.
double list_schedule_ms(std::span<const double> item_ms, int workers);

struct StagePrediction {
  std::string stage;
  double ms = 0;
};

struct SchedulePrediction {
  int workers = 0;
  double total_ms = 0;
  std::vector<StagePrediction> stages;  // in the order stages first appear in the phases
};

// The frame's time on `workers` workers: the sum over phases of their list schedules.
SchedulePrediction predict_schedule(std::span<const SchedulePhase> phases, int workers);

// The frame's time on unboundedly many workers: every phase takes its largest item.
double critical_path_ms(std::span<const SchedulePhase> phases);

}  // namespace fastshade
