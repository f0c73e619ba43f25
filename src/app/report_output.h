// The files `fastshade report` writes: results.csv and results.json (one row per scene x
// configuration, the same columns in both) and summary.md (tables for people).
#pragma once
#include <span>
#include <string>
#include <vector>

#include "app/report_metrics.h"

namespace fastshade {

struct RunInfo {  // the same for every row of one run
  std::string machine, isa, commit, date_utc;  // isa: the run's ISAs, comma-separated
  int threads = 0, frames = 0;
  double load_start = -1, load_end = -1;  // 1-minute load average before and after the run
};

struct ReportRow {
  std::string scene, isa, config, method;
  int width = 0, height = 0;
  long long triangles = 0, covered_px = 0;
  double median_ms = 0, raster_shade_ms = 0;  // medians over the timed frames
  double speedup_vs_phong = 0;                // phong's median_ms / this median_ms
  ErrorMetrics error;                         // against `reference` on the same scene
  bool pareto_rmse = false, pareto_max = false;  // on the front of time vs RMSE, vs max error
  std::string heat_map, plot;                 // paths relative to the output directory, or ""
};

struct SkippedConfig {
  std::string config, reason;
};

// The column names, in order: the one definition of a row for both files.
std::vector<std::string> report_columns();

std::string results_csv(const RunInfo& run, std::span<const ReportRow> rows);
std::string results_json(const RunInfo& run, std::span<const ReportRow> rows,
                         std::span<const SkippedConfig> skipped);
// `plots_note`: why there are no plots, or "" when they were drawn.
std::string summary_markdown(const RunInfo& run, std::span<const ReportRow> rows,
                             std::span<const SkippedConfig> skipped, const std::string& plots_note);

}  // namespace fastshade
