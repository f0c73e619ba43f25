// What `fastshade tune` shows and keeps: the table it decided from (Markdown, for a terminal
// and for docs) and the provenance its config file carries.
#pragma once
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/report_output.h"
#include "app/tune_rule.h"

namespace fastshade {

struct TuneTable {
  RunInfo run;
  TuneCriteria criteria;  // its baseline: `render`'s defaults at this budget
  std::vector<std::string> scene_names, scene_paths;
  std::vector<std::string> labels;                 // per candidate
  std::vector<std::vector<SceneFigures>> figures;  // [candidate][scene]
  TuneDecision decision;
};

// "chosen", "within budget", "within budget, but only 2.7 % faster than the default (--min-gain
// 3 %)" or "over budget: " and why.
std::string verdict_text(const TuneTable& table, std::size_t candidate);

// The baseline's geometric-mean time over `candidate`'s (above 1: faster).
double speedup_vs_default(const TuneTable& table, std::size_t candidate);

// One line on the run, then a Markdown table, fastest first: per-scene and geometric-mean
// times, speed-up over the default candidate, worst errors, and a verdict (the chosen row, or
// why a row is over the budget).
std::string tune_table_markdown(const TuneTable& table);

// The run, the budget, the rule, the choice and the table in short; only for a table with a
// chosen candidate.
nlohmann::ordered_json tune_provenance(const TuneTable& table);

}  // namespace fastshade
