// What `fastshade bench scaling` writes and prints: scaling.csv (one row per tile size and
// thread count), scaling.json (the same plus the model), and the tables on stdout.
#include <algorithm>
#include <cstdio>
#include <sstream>

#include <nlohmann/json.hpp>

#include "app/scaling.h"

namespace fastshade {

namespace {

struct Stage {
  const char* name;
  double StageTimes::*field;
};
constexpr Stage kStages[] = {{"front_end", &StageTimes::front_end},
                             {"binning", &StageTimes::binning},
                             {"raster_shade", &StageTimes::raster_shade},
                             {"total", &StageTimes::total}};

// The front end in the sense (transform, clip, setup and binning) as a share of the frame.
double front_share(const StageTimes& t) {
  return t.total > 0 ? (t.front_end + t.binning) / t.total : 0.0;
}

const ScalingPoint* find_point(const ScalingRun& run, int tile_px, int threads) {
  for (const ScalingPoint& p : run.points)
    if (p.tile_px == tile_px && p.threads == threads) return &p;
  return nullptr;
}

double sum_ms(const SchedulePhase& phase) {
  double ms = 0;
  for (const double item : phase.item_ms) ms += item;
  return ms;
}

double max_ms(const SchedulePhase& phase) {
  double ms = 0;
  for (const double item : phase.item_ms) ms = std::max(ms, item);
  return ms;
}

double model_stage_ms(const SchedulePrediction& p, const std::string& stage) {
  if (stage == "total") return p.total_ms;
  for (const StagePrediction& s : p.stages)
    if (s.stage == stage) return s.ms;
  return 0.0;
}

// Per phase but "other" (meaningless once items overlap): the sum of item costs at p's thread
// count over the same at 1 thread. 1 = no contention. A phase timed as a whole was timed by
// wall clock, so its time is multiplied by the thread count: 1 = it scaled perfectly, and more
// mixes contention with imbalance and cores that were busy elsewhere.
std::vector<std::pair<std::string, double>> item_cost_ratios(const ScalingRun& run, const ScalingPoint& p) {
  std::vector<std::pair<std::string, double>> ratios;
  const ScalingPoint* one = find_point(run, p.tile_px, 1);
  if (!one) return ratios;
  for (std::size_t i = 0; i < p.phases.size() && i < one->phases.size(); ++i)
    if (p.phases[i].stage != "other") {
      const double base = sum_ms(one->phases[i]);
      const double cost = sum_ms(p.phases[i]) * (p.phases[i].timed_whole ? p.threads : 1);
      ratios.emplace_back(p.phases[i].name, base > 0 ? cost / base : 0.0);
    }
  return ratios;
}

}  // namespace

double item_cost_ratio(const ScalingRun& run, const ScalingPoint& p) {
  const ScalingPoint* one = find_point(run, p.tile_px, 1);
  double at_p = 0, at_one = 0;
  for (std::size_t i = 0; one && i < p.phases.size() && i < one->phases.size(); ++i)
    if (!p.phases[i].timed_whole && p.phases[i].stage != "other") {
      at_p += sum_ms(p.phases[i]);
      at_one += sum_ms(one->phases[i]);
    }
  return at_one > 0 ? at_p / at_one : 0.0;
}

bool untrustworthy(const ScalingRun& run, const ScalingPoint& p) {
  return p.cpus_used < kBusyCpuShare * std::min(p.threads, run.hardware_threads) ||
         (!p.oversubscribed && item_cost_ratio(run, p) > kSlowedItemRatio);
}

double speedup(const ScalingRun& run, const ScalingPoint& p, double StageTimes::*stage) {
  const ScalingPoint* one = find_point(run, p.tile_px, 1);
  return one && p.median.*stage > 0 ? one->median.*stage / (p.median.*stage) : 0.0;
}

double model_total_ms(const ScalingRun& run, int tile_px, int workers) {
  for (const ScalingModel& m : run.models)
    if (m.tile_px == tile_px)
      for (const SchedulePrediction& p : m.predictions)
        if (p.workers == workers) return p.total_ms;
  return 0.0;
}

std::string scaling_csv(const ScalingRun& run) {
  std::ostringstream csv;
  csv << "scene,method,width,height,tile,threads,oversubscribed,frames";
  for (const Stage& s : kStages) csv << ',' << s.name << "_ms";
  for (const Stage& s : kStages) csv << ',' << s.name << "_speedup";
  for (const Stage& s : kStages) csv << ',' << s.name << "_efficiency";
  csv << ",front_share,cpus_used,item_cost_ratio,untrustworthy,model_total_ms\n";
  for (const ScalingPoint& p : run.points) {
    csv << '"' << run.scene << "\"," << run.method << ',' << run.width << ',' << run.height << ','
        << p.tile_px << ',' << p.threads << ',' << (p.oversubscribed ? 1 : 0) << ',' << run.frames;
    for (const Stage& s : kStages) csv << ',' << p.median.*s.field;
    for (const Stage& s : kStages) csv << ',' << speedup(run, p, s.field);
    for (const Stage& s : kStages) csv << ',' << speedup(run, p, s.field) / p.threads;
    const double model = model_total_ms(run, p.tile_px, p.threads);
    csv << ',' << front_share(p.median) << ',' << p.cpus_used << ',' << item_cost_ratio(run, p)
        << ',' << (untrustworthy(run, p) ? 1 : 0) << ',';
    if (model > 0) csv << model;
    csv << '\n';
  }
  return csv.str();
}

std::string scaling_json(const ScalingRun& run) {
  nlohmann::json points = nlohmann::json::array();
  for (const ScalingPoint& p : run.points) {
    nlohmann::json ms, up, eff, ratios = nlohmann::json::object();
    for (const auto& [name, ratio] : item_cost_ratios(run, p)) ratios[name] = ratio;
    for (const Stage& s : kStages) {
      ms[s.name] = p.median.*s.field;
      up[s.name] = speedup(run, p, s.field);
      eff[s.name] = speedup(run, p, s.field) / p.threads;
    }
    points.push_back({{"tile", p.tile_px},
                      {"threads", p.threads},
                      {"oversubscribed", p.oversubscribed},
                      {"median_ms", ms},
                      {"speedup", up},
                      {"efficiency", eff},
                      {"front_share", front_share(p.median)},
                      {"cpus_used", p.cpus_used},
                      {"item_cost_ratio", item_cost_ratio(run, p)},
                      {"untrustworthy", untrustworthy(run, p)},
                      {"item_cost_vs_1_thread", ratios}});
  }
  nlohmann::json models = nlohmann::json::array();
  for (const ScalingModel& m : run.models) {
    nlohmann::json predictions = nlohmann::json::array();
    const double one = m.predictions.front().total_ms;
    for (const SchedulePrediction& p : m.predictions) {
      nlohmann::json stages;
      for (const StagePrediction& s : p.stages) stages[s.stage] = s.ms;
      predictions.push_back({{"workers", p.workers},
                             {"total_ms", p.total_ms},
                             {"speedup", p.total_ms > 0 ? one / p.total_ms : 0.0},
                             {"stage_ms", stages}});
    }
    nlohmann::json phases = nlohmann::json::array();
    for (const SchedulePhase& phase : m.phases)
      phases.push_back({{"stage", phase.stage},
                        {"name", phase.name},
                        {"items", phase.item_ms.size()},
                        {"sum_ms", sum_ms(phase)},
                        {"max_ms", max_ms(phase)}});
    models.push_back({{"tile", m.tile_px},
                      {"tiles", m.tiles},
                      {"chunks", m.chunks},
                      {"serial_ms", m.serial_ms},
                      {"critical_path_ms", m.critical_path_ms},
                      {"max_speedup", m.critical_path_ms > 0 ? one / m.critical_path_ms : 0.0},
                      {"phases", phases},
                      {"predictions", predictions}});
  }
  const nlohmann::json j = {{"scene", run.scene},
                            {"method", run.method},
                            {"isa", run.isa},
                            {"width", run.width},
                            {"height", run.height},
                            {"triangles", run.triangles},
                            {"hardware_threads", run.hardware_threads},
                            {"frames", run.frames},
                            {"points", points},
                            {"model", models}};
  return j.dump(2) + "\n";
}

void print_scaling_tables(const ScalingRun& run) {
  std::printf("%s: %dx%d, %s, %lld triangles, isa %s, %d hardware threads; medians of %d frames\n\n",
              run.scene.c_str(), run.width, run.height, run.method.c_str(), run.triangles,
              run.isa.c_str(), run.hardware_threads, run.frames);
  std::printf("%4s %7s | %8s %8s %8s %8s | %-27s | %5s | %5s | %5s %5s\n", "", "", "median", "ms", "",
              "", "speed-up vs 1 thread", "eff.", "front", "CPUs", "items");
  std::printf("%4s %7s | %8s %8s %8s %8s | %6s %6s %6s %6s | %5s | %5s | %5s %5s\n", "tile", "threads",
              "front", "binning", "raster", "total", "front", "bin", "raster", "total", "total",
              "share", "used", "cost");
  bool any_oversubscribed = false, any_untrustworthy = false;
  for (const ScalingPoint& p : run.points) {
    any_oversubscribed |= p.oversubscribed;
    const bool flagged = untrustworthy(run, p);
    any_untrustworthy |= flagged;
    std::printf("%4d %6d%s | %8.2f %8.2f %8.2f %8.2f | %6.2f %6.2f %6.2f %6.2f | %4.0f%% | %4.0f%% | %5.2f %5.2f%s\n",
                p.tile_px, p.threads, p.oversubscribed ? "*" : " ", p.median.front_end,
                p.median.binning, p.median.raster_shade, p.median.total,
                speedup(run, p, &StageTimes::front_end), speedup(run, p, &StageTimes::binning),
                speedup(run, p, &StageTimes::raster_shade), speedup(run, p, &StageTimes::total),
                100 * speedup(run, p, &StageTimes::total) / p.threads, 100 * front_share(p.median),
                p.cpus_used, item_cost_ratio(run, p), flagged ? " !" : "");
  }
  if (any_oversubscribed) std::printf("* oversubscribed: more threads than the hardware has\n");
  if (any_untrustworthy)
    std::printf("! do not trust this point: CPUs used below %.0f%% of min(threads, hardware "
                "threads), or items cost %.0f%% more than on 1 thread (slowed cores)\n",
                100 * kBusyCpuShare, 100 * (kSlowedItemRatio - 1));
  std::printf("front share: (front end + binning) / total; CPUs used: process CPU time / wall "
              "time over the timed frames; items cost: the profiled items' summed time / the same "
              "on 1 thread (1.00: each item ran as fast as alone)\n\n");

  std::printf("load-balance model: per-item costs of 1-thread frames (item medians), replayed as a\n"
              "greedy list schedule on P workers; predicted speed-up vs the model's P = 1\n");
  std::printf("%4s %6s %6s |", "tile", "tiles", "chunks");
  for (const int w : kModelWorkers) std::printf(" %5s%-2d", "P=", w);
  std::printf("| %8s %8s %6s\n", "serial", "critical", "bound");
  for (const ScalingModel& m : run.models) {
    const double one = m.predictions.front().total_ms;
    std::printf("%4d %6zu %6zu |", m.tile_px, m.tiles, m.chunks);
    for (const SchedulePrediction& p : m.predictions) std::printf(" %7.2f", one / p.total_ms);
    std::printf("| %6.2fms %6.2fms %5.1fx\n", m.serial_ms, m.critical_path_ms, one / m.critical_path_ms);
  }
  std::printf("serial: phases of one item (between stages; the bin plan of a small grid); critical: "
              "largest item of every phase; bound: model P=1 / critical\n\n");

  std::printf("1-thread item costs per phase as the model takes them (hand-out overheads spread "
              "in), ms: sum (largest item)\n%4s |", "tile");
  for (const SchedulePhase& phase : run.models.front().phases) std::printf(" %17s", phase.name.c_str());
  std::printf("\n");
  for (const ScalingModel& m : run.models) {
    std::printf("%4d |", m.tile_px);
    for (const SchedulePhase& phase : m.phases) std::printf("  %6.2f (%6.3f)", sum_ms(phase), max_ms(phase));
    std::printf("\n");
  }
  std::printf("\n");

  std::printf("item costs at T threads / at 1 thread, per phase (1.00: items run as fast as "
              "alone; more: contention for memory, caches or the clock)\n%4s %7s |", "tile", "threads");
  for (const SchedulePhase& phase : run.models.front().phases)
    if (phase.stage != "other") std::printf(" %13s", (phase.name + (phase.timed_whole ? "+" : "")).c_str());
  std::printf("\n");
  for (const ScalingPoint& p : run.points) {
    if (p.threads == 1) continue;
    std::printf("%4d %6d%s |", p.tile_px, p.threads, p.oversubscribed ? "*" : " ");
    for (const auto& ratio : item_cost_ratios(run, p)) std::printf(" %13.2f", ratio.second);
    std::printf("\n");
  }
  std::printf("+ timed as a whole: wall time x T / 1-thread time, so imbalance and busy cores count "
              "too\n\n");

  std::printf("model against measurement (ms; model/measured in brackets)\n");
  std::printf("%4s %7s | %18s %18s %18s %18s\n", "tile", "threads", "front", "binning", "raster", "total");
  for (const ScalingModel& m : run.models)
    for (const SchedulePrediction& pred : m.predictions) {
      const ScalingPoint* p = find_point(run, m.tile_px, pred.workers);
      if (!p) continue;
      std::printf("%4d %7d |", m.tile_px, pred.workers);
      for (const Stage& s : kStages) {
        const double model = model_stage_ms(pred, s.name), measured = p->median.*s.field;
        std::printf(" %6.2f/%6.2f (%4.2f)", model, measured, measured > 0 ? model / measured : 0.0);
      }
      std::printf("\n");
    }
  std::printf("the stages' model times leave out \"between stages\", which only total holds\n");
}

}  // namespace fastshade
