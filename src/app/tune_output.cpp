#include "app/tune_output.h"

#include "app/format.h"

namespace fastshade {

namespace {

using Json = nlohmann::ordered_json;

constexpr const char* kRule =
    "the fastest candidate by the geometric mean over the scenes of its median frame time, among "
    "those whose max error against reference (and share of covered pixels off by more than 1 LSB) "
    "stays within the budget on every scene; render's defaults (at this budget) instead if they are "
    "within the budget and the fastest is no more than min_gain_pct faster (docs/TUNING.md)";

// "1 frame", "3 frames"
std::string count(int n, const std::string& noun) { return std::to_string(n) + " " + noun + (n == 1 ? "" : "s"); }

// "| a | b |\n"
std::string table_row(const std::vector<std::string>& cells) {
  std::string row = "|";
  for (const std::string& cell : cells) row.append(" ").append(cell).append(" |");
  return row + "\n";
}

}  // namespace

std::string verdict_text(const TuneTable& t, std::size_t candidate) {
  if (t.decision.chosen == candidate) return "chosen";
  if (t.decision.fastest == candidate)
    return "within budget, but only " + format_double("%.1f", t.decision.fastest_gain_pct) +
           " % faster than the default (--min-gain " + format_double("%g", t.criteria.min_gain_pct) + " %)";
  const std::string& why = t.decision.verdicts[candidate].rejected_because;
  return why.empty() ? "within budget" : "over budget: " + why;
}

double speedup_vs_default(const TuneTable& t, std::size_t candidate) {
  return t.decision.verdicts[t.criteria.baseline].geomean_ms / t.decision.verdicts[candidate].geomean_ms;
}

std::string tune_table_markdown(const TuneTable& t) {
  const RunInfo& run = t.run;
  std::string md = run.date_utc + ", commit `" + run.commit + "`, " + run.machine + ", ISA " + run.isa + ", " +
                   count(run.threads, "thread") + ", median of " + count(run.frames, "frame") +
                   "; load average " + format_double("%.1f", run.load_start) + " at the start, " +
                   format_double("%.1f", run.load_end) + " at the end. Budget: max error " +
                   format_double("%g", t.criteria.max_abs_lsb) + " LSB";
  if (t.criteria.max_pct_over_1lsb < 100)
    md.append(", ").append(format_double("%g", t.criteria.max_pct_over_1lsb)).append(" % of pixels > 1 LSB");
  md += " on every scene.\n\n";

  std::vector<std::string> header = {"#", "configuration"}, align = {"---:", "---"};
  for (const std::string& scene : t.scene_names) header.push_back(scene + " ms"), align.push_back("---:");
  for (const char* column : {"geo. mean ms", "× default", "max LSB", "% px > 1 LSB"})
    header.push_back(column), align.push_back("---:");
  header.push_back("verdict"), align.push_back("---");
  md += table_row(header) + table_row(align);
  int rank = 0;
  for (std::size_t c : t.decision.fastest_first) {
    const Verdict& v = t.decision.verdicts[c];
    std::vector<std::string> cells = {std::to_string(++rank),
                                      t.labels[c] + (c == t.criteria.baseline ? " (default)" : "")};
    for (const SceneFigures& f : t.figures[c]) cells.push_back(format_double("%.2f", f.median_ms));
    cells.insert(cells.end(), {format_double("%.2f", v.geomean_ms), format_double("%.2f", speedup_vs_default(t, c)),
                               format_double("%g", v.worst_max_abs_lsb), format_double("%.3f", v.worst_pct_over_1lsb),
                               t.decision.chosen == c ? "**chosen**" : verdict_text(t, c)});
    md += table_row(cells);
  }
  return md;
}

Json tune_provenance(const TuneTable& t) {
  Json table = Json::array();
  for (std::size_t c : t.decision.fastest_first) {
    const Verdict& v = t.decision.verdicts[c];
    Json ms = Json::array();
    for (const SceneFigures& f : t.figures[c]) ms.push_back(f.median_ms);
    table.push_back({{"config", t.labels[c]},
                     {"scene_ms", ms},
                     {"geomean_ms", v.geomean_ms},
                     {"speedup_vs_default", speedup_vs_default(t, c)},
                     {"max_abs_lsb", v.worst_max_abs_lsb},
                     {"pct_covered_over_1lsb", v.worst_pct_over_1lsb},
                     {"verdict", verdict_text(t, c)}});
  }
  const std::size_t chosen = t.decision.chosen.value();
  return {{"written_by", "fastshade tune"},
          {"date_utc", t.run.date_utc},
          {"machine", t.run.machine},
          {"isa", t.run.isa},
          {"threads", t.run.threads},
          {"commit", t.run.commit},
          {"frames", t.run.frames},
          {"load_average_start", t.run.load_start},
          {"load_average_end", t.run.load_end},
          {"scenes", t.scene_paths},
          {"criteria",
           {{"max_error_lsb", t.criteria.max_abs_lsb},
            {"max_pct_over_1lsb", t.criteria.max_pct_over_1lsb},
            {"min_gain_pct", t.criteria.min_gain_pct}}},
          {"rule", kRule},
          {"chosen", t.labels[chosen]},
          {"speedup_vs_default", speedup_vs_default(t, chosen)},
          {"table", table}};
}

}  // namespace fastshade
