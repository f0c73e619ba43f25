#include "app/report_output.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <map>

#include <nlohmann/json.hpp>

#include "app/report_configs.h"

namespace fastshade {

namespace {

using Json = nlohmann::ordered_json;

// Every column of a row, in order; CSV and JSON are both written from this.
Json row_fields(const RunInfo& run, const ReportRow& r) {
  return Json{{"scene", r.scene},
              {"config", r.config},
              {"method", r.method},
              {"width", r.width},
              {"height", r.height},
              {"triangles", r.triangles},
              {"covered_px", r.covered_px},
              {"frames", run.frames},
              {"median_ms", r.median_ms},
              {"raster_shade_ms", r.raster_shade_ms},
              {"speedup_vs_phong", r.speedup_vs_phong},
              {"max_abs_lsb", r.error.max_abs_lsb},
              {"rmse_lsb", r.error.rmse_lsb},
              {"psnr_db", r.error.psnr_db},  // +inf (JSON null) for the reference itself
              {"pct_covered_over_1lsb", r.error.pct_covered_over_1lsb},
              {"nan_suspect_channels", r.error.nan_suspect_channels},
              {"pareto_rmse", r.pareto_rmse},
              {"pareto_max", r.pareto_max},
              {"heat_map", r.heat_map},
              {"plot", r.plot},
              {"machine", run.machine},
              {"isa", r.isa},
              {"threads", run.threads},
              {"commit", run.commit}};
}

std::string csv_cell(const Json& v) {
  if (v.is_boolean()) return v.get<bool>() ? "1" : "0";
  if (v.is_number_float()) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v.get<double>());  // "inf" for the reference's PSNR
    return buf;
  }
  if (!v.is_string()) return v.dump();
  const std::string s = v.get<std::string>();
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string quoted = "\"";
  for (char c : s) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string fmt_psnr(double db) { return std::isinf(db) ? "∞" : fmt("%.1f", db); }

std::string pareto_mark(const ReportRow& r) {
  if (r.pareto_rmse && r.pareto_max) return "RMSE, max";
  return r.pareto_rmse ? "RMSE" : r.pareto_max ? "max" : "";
}

// Configurations in the order first met, with their rows over all scenes.
std::vector<std::pair<std::string, std::vector<const ReportRow*>>> by_config(
    std::span<const ReportRow> rows) {
  std::vector<std::pair<std::string, std::vector<const ReportRow*>>> out;
  for (const ReportRow& r : rows) {
    auto it = std::find_if(out.begin(), out.end(), [&](const auto& e) { return e.first == r.config; });
    if (it == out.end()) it = out.insert(out.end(), {r.config, {}});
    it->second.push_back(&r);
  }
  return out;
}

// The ISAs of the rows, in the order first met.
std::vector<std::string> isas_of(std::span<const ReportRow> rows) {
  std::vector<std::string> out;
  for (const ReportRow& r : rows)
    if (std::find(out.begin(), out.end(), r.isa) == out.end()) out.push_back(r.isa);
  return out;
}

std::vector<ReportRow> rows_on(std::span<const ReportRow> rows, const std::string& isa) {
  std::vector<ReportRow> out;
  std::copy_if(rows.begin(), rows.end(), std::back_inserter(out), [&](const ReportRow& r) { return r.isa == isa; });
  return out;
}

double geo_mean_speedup(const std::vector<const ReportRow*>& rs) {
  double log_sum = 0;
  for (const ReportRow* r : rs) log_sum += std::log(r->speedup_vs_phong);
  return std::exp(log_sum / static_cast<double>(rs.size()));
}

// `heading_tail`: ", ISA avx2" where a run measured several.
void overview(std::string& md, std::span<const ReportRow> rows, int scenes, const std::string& heading_tail) {
  md += "## Overview over " + std::to_string(scenes) + " scenes" + heading_tail +
        "\n\n"
        "| configuration | speed-up over phong: geo. mean (range) | max LSB: worst | RMSE LSB: mean | "
        "% px > 1 LSB: worst | NaN suspects | on the time-RMSE front |\n"
        "|---|---:|---:|---:|---:|---:|---:|\n";
  for (const auto& [config, rs] : by_config(rows)) {
    double lo = INFINITY, hi = 0, worst_max = 0, rmse_sum = 0, worst_pct = 0;
    long long nan = 0;
    int front = 0;
    for (const ReportRow* r : rs) {
      lo = std::min(lo, r->speedup_vs_phong);
      hi = std::max(hi, r->speedup_vs_phong);
      worst_max = std::max(worst_max, r->error.max_abs_lsb);
      rmse_sum += r->error.rmse_lsb;
      worst_pct = std::max(worst_pct, r->error.pct_covered_over_1lsb);
      nan += r->error.nan_suspect_channels;
      front += r->pareto_rmse;
    }
    const double n = static_cast<double>(rs.size());
    md += "| " + config + " | " + fmt("%.2f", geo_mean_speedup(rs)) + " (" + fmt("%.2f", lo) + "–" +
          fmt("%.2f", hi) + ") | " + fmt("%.0f", worst_max) + " | " + fmt("%.3f", rmse_sum / n) +
          " | " + fmt("%.3f", worst_pct) + " | " + std::to_string(nan) + " | " +
          std::to_string(front) + "/" + std::to_string(rs.size()) + " |\n";
  }
  md += "\n";
}

// Where the paper's methods pay: each configuration's speed-up over phong on the same ISA, and
// phong's own time on each ISA against the first's.
void isa_table(std::string& md, std::span<const ReportRow> rows, const std::vector<std::string>& isas) {
  md += "## Speed-up over phong by ISA\n\nGeometric mean over the scenes of each configuration's "
        "speed-up over `phong` on the same ISA (above 1: it beats phong there). The last row is "
        "phong's own speed on each ISA against " + isas.front() + "'s.\n\n| configuration |";
  std::string rule = "|---|";
  for (const std::string& isa : isas) md += " " + isa + " |", rule += "---:|";
  md += "\n" + rule + "\n";
  std::vector<std::vector<ReportRow>> per_isa;
  for (const std::string& isa : isas) per_isa.push_back(rows_on(rows, isa));
  for (const auto& [config, ignored] : by_config(per_isa.front())) {
    md += "| " + config + " |";
    for (const std::vector<ReportRow>& on : per_isa) {
      std::vector<const ReportRow*> rs;
      for (const ReportRow& r : on)
        if (r.config == config) rs.push_back(&r);
      md += rs.empty() ? " – |" : " " + fmt("%.2f", geo_mean_speedup(rs)) + " |";
    }
    md += "\n";
  }
  // phong's rows of the first ISA and of each, scene by scene (the same scenes, in order).
  auto phong_ms = [](const std::vector<ReportRow>& on) {
    std::vector<double> ms;
    for (const ReportRow& r : on)
      if (r.config == kBaselineConfig) ms.push_back(r.median_ms);
    return ms;
  };
  const std::vector<double> first = phong_ms(per_isa.front());
  md += "| phong's speed against " + isas.front() + " |";
  for (const std::vector<ReportRow>& on : per_isa) {
    const std::vector<double> ms = phong_ms(on);
    double log_sum = 0;
    for (std::size_t i = 0; i < ms.size() && i < first.size(); ++i) log_sum += std::log(first[i] / ms[i]);
    md += ms.empty() ? " – |" : " " + fmt("%.2f", std::exp(log_sum / static_cast<double>(ms.size()))) + " |";
  }
  md += "\n\n";
}

void scene_table(std::string& md, const std::vector<const ReportRow*>& rs, bool several_isas) {
  const ReportRow& first = *rs.front();
  md += "### " + first.scene + (several_isas ? ", ISA " + first.isa : "") + "\n\n" + std::to_string(first.width) + "×" +
        std::to_string(first.height) + ", " + std::to_string(first.triangles) + " triangles, " +
        std::to_string(first.covered_px) + " covered pixels.\n\n";
  if (!first.plot.empty()) md += "![" + first.scene + ": error against time](" + first.plot + ")\n\n";
  md += "| configuration | ms | × phong | max LSB | RMSE LSB | PSNR dB | % px > 1 LSB | NaN suspects | "
        "Pareto front |\n|---|---:|---:|---:|---:|---:|---:|---:|---|\n";
  std::string maps;
  for (const ReportRow* r : rs) {
    md += "| " + r->config + " | " + fmt("%.2f", r->median_ms) + " | " + fmt("%.2f", r->speedup_vs_phong) +
          " | " + fmt("%.0f", r->error.max_abs_lsb) + " | " + fmt("%.4f", r->error.rmse_lsb) + " | " +
          fmt_psnr(r->error.psnr_db) + " | " + fmt("%.4f", r->error.pct_covered_over_1lsb) + " | " +
          std::to_string(r->error.nan_suspect_channels) + " | " + pareto_mark(*r) + " |\n";
    if (!r->heat_map.empty()) maps += (maps.empty() ? "" : ", ") + ("[" + r->config + "](" + r->heat_map + ")");
  }
  if (!maps.empty()) md += "\nError heat maps: " + maps + ".\n";
  md += "\n";
}

}  // namespace

std::vector<std::string> report_columns() {
  std::vector<std::string> names;
  const Json fields = row_fields(RunInfo{}, ReportRow{});
  for (const auto& field : fields.items()) names.push_back(field.key());
  return names;
}

std::string results_csv(const RunInfo& run, std::span<const ReportRow> rows) {
  std::string csv;
  for (const std::string& name : report_columns()) csv += (csv.empty() ? "" : ",") + name;
  csv += "\n";
  for (const ReportRow& r : rows) {
    std::string line;
    const Json fields = row_fields(run, r);
    for (const auto& field : fields.items())
      line += (line.empty() ? "" : ",") + csv_cell(field.value());
    csv += line + "\n";
  }
  return csv;
}

std::string results_json(const RunInfo& run, std::span<const ReportRow> rows,
                         std::span<const SkippedConfig> skipped) {
  Json out = {{"run",
               {{"date_utc", run.date_utc},
                {"machine", run.machine},
                {"isa", run.isa},
                {"threads", run.threads},
                {"frames", run.frames},
                {"commit", run.commit},
                {"load_average_start", run.load_start},
                {"load_average_end", run.load_end}}},
              {"rows", Json::array()},
              {"skipped", Json::array()}};
  for (const ReportRow& r : rows) out["rows"].push_back(row_fields(run, r));
  for (const SkippedConfig& s : skipped) out["skipped"].push_back({{"config", s.config}, {"reason", s.reason}});
  return out.dump(2) + "\n";
}

std::string summary_markdown(const RunInfo& run, std::span<const ReportRow> rows,
                             std::span<const SkippedConfig> skipped, const std::string& plots_note) {
  // Tables by scene and ISA: the rows come scene by scene, each scene's ISAs in turn.
  std::vector<std::vector<const ReportRow*>> tables;
  int scene_count = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (i == 0 || rows[i].scene != rows[i - 1].scene || rows[i].isa != rows[i - 1].isa) tables.emplace_back();
    if (i == 0 || rows[i].scene != rows[i - 1].scene) ++scene_count;
    tables.back().push_back(&rows[i]);
  }
  const std::vector<std::string> isas = isas_of(rows);
  std::string md = "# fastshade report\n\n" + run.date_utc + ", commit `" + run.commit + "`, " +
                   run.machine + ", ISA " + run.isa + ", " + std::to_string(run.threads) +
                   " threads, median of " + std::to_string(run.frames) +
                   " frames per configuration; load average " + fmt("%.1f", run.load_start) +
                   " at the start, " + fmt("%.1f", run.load_end) + " at the end.\n\n";
  md +=
      "Errors are in 8-bit steps (LSB) against `reference` on the same scene. Times are medians "
      "of frames taken in turn across the configurations of a scene (one frame of each, then "
      "the next round), so that a machine slowing down slows them all alike: compare times "
      "within a scene, as ratios.\n\n";
  if (!plots_note.empty()) md += "**No plots:** " + plots_note + "\n\n";
  if (isas.size() > 1) {
    isa_table(md, rows, isas);
    for (const std::string& isa : isas) overview(md, rows_on(rows, isa), scene_count, ", ISA " + isa);
  } else {
    overview(md, rows, scene_count, "");
  }
  if (!skipped.empty()) {
    md += "Not measured (not in this build):\n\n";
    for (const SkippedConfig& s : skipped) md += "- `" + s.config + "`: " + s.reason + "\n";
    md += "\n";
  }
  md += "## Per scene\n\n";
  for (const auto& table : tables) scene_table(md, table, isas.size() > 1);
  md +=
      "## Reading the columns\n\n"
      "- **ms**: median frame time (front end, binning, raster and shading; mesh loading "
      "excluded). **× phong**: phong's median divided by this one (above 1 is faster).\n"
      "- **max LSB**, **RMSE LSB** (over every channel of the image, background included, as "
      "`fastshade compare`), **PSNR**; **% px > 1 LSB**: share of covered pixels with a channel off "
      "by more than one step.\n"
      "- **NaN suspects**: the renderer writes 8 bits and its quantiser turns a NaN into 0, so "
      "NaNs cannot be counted in its output; this counts channels that are 0 where the reference "
      "has at least 2 LSB, an upper bound on NaN channels. 0 means no NaN changed a channel by "
      "more than 1 LSB.\n"
      "- **Pareto front**: no other configuration of the scene is both at least as fast and at "
      "least as accurate (by RMSE, or by max error) and better in one of them.\n"
      "- **Heat maps** (the worst configurations of each scene by RMSE): the largest channel "
      "error of each pixel, blue 1 LSB, cyan 2, green 4, yellow 8, orange 16, red 32, white 64 "
      "and more (log scale); grey: the object, exact; black: background.\n";
  return md;
}

}  // namespace fastshade
