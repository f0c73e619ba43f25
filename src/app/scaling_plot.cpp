// scaling.png: speed-up against threads, measured (left) and modelled (right), each with the
// ideal line. Drawn by a small matplotlib script fed to python3 on stdin; a machine without
// python3 + matplotlib gets the CSV and JSON and one line saying how to get the plot.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "app/scaling.h"
#include "fastshade/error.h"
#include "fastshade/atomic_file.h"

namespace fastshade {

namespace {

constexpr const char* kPlotScript = R"PY(
import json, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

run = json.load(open(sys.argv[1]))
def busy(p):  # measured on a busy machine or slowed cores (the table's "!")
    return p["untrustworthy"]
fig, (measured, model) = plt.subplots(1, 2, figsize=(12, 5))
tiles = sorted({p["tile"] for p in run["points"]})
colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
for i, tile in enumerate(tiles):
    pts = [p for p in run["points"] if p["tile"] == tile]
    c = colors[i % len(colors)]
    measured.plot([p["threads"] for p in pts], [p["speedup"]["total"] for p in pts], "o-",
                  color=c, label=f"tile {tile}: frame")
    measured.plot([p["threads"] for p in pts if busy(p)],
                  [p["speedup"]["total"] for p in pts if busy(p)], "o", color="white",
                  markeredgecolor=c)
    measured.plot([p["threads"] for p in pts],
                  [sum(pts[0]["median_ms"][s] for s in ("front_end", "binning")) /
                   sum(p["median_ms"][s] for s in ("front_end", "binning")) for p in pts],
                  "s--", color=c, alpha=0.6, label=f"tile {tile}: front end + binning")
top = max(p["threads"] for p in run["points"])
measured.plot([1, top], [1, top], "k:", label="ideal")
measured.axvline(run["hardware_threads"], color="grey", lw=0.8)
measured.set_xticks(sorted({p["threads"] for p in run["points"]}))
measured.set_xlabel("threads (grey: hardware threads; hollow: busy or slowed cores, not to trust)")
measured.set_ylabel("speed-up vs 1 thread")
measured.set_title(f"measured: {run['scene']}, {run['width']}x{run['height']}, {run['method']}")
measured.legend(fontsize=7)
measured.grid(alpha=0.3)
for i, m in enumerate(run["model"]):
    w = [p["workers"] for p in m["predictions"]]
    model.plot(w, [p["speedup"] for p in m["predictions"]], "o-", color=colors[i % len(colors)],
               label=f"tile {m['tile']} (bound {m['max_speedup']:.1f}x)")
ws = [p["workers"] for p in run["model"][0]["predictions"]]
model.plot(ws, ws, "k:", label="ideal")
model.set_xscale("log", base=2)
model.set_yscale("log", base=2)
model.set_xlabel("simulated workers P")
model.set_ylabel("predicted speed-up vs P = 1")
model.set_title("load-balance model (1-thread item costs, greedy schedule)")
model.legend(fontsize=7)
model.grid(alpha=0.3, which="both")
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=110)
)PY";

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (const char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// The first of PATH's python3 and Debian's (where python3-matplotlib installs: a pyenv or venv
// python3 earlier in PATH often lacks it) that can import matplotlib.
std::string find_python_with_matplotlib() {
  for (const char* python : {"python3", "/usr/bin/python3"}) {
    const std::string probe = std::string(python) + " -c 'import matplotlib' >/dev/null 2>&1";
    if (std::system(probe.c_str()) == 0) return python;
  }
  return {};
}

}  // namespace

bool plot_scaling(const std::filesystem::path& json, const std::filesystem::path& png) {
  const std::string python = find_python_with_matplotlib();
  if (python.empty()) {
    std::fprintf(stderr,
                 "fastshade: %s not drawn: no python3 with matplotlib found (Debian: apt-get "
                 "install python3-matplotlib); the CSV and JSON are complete\n",
                 png.string().c_str());
    return false;
  }
  TempFile temp(png);
  const std::string cmd = python + " - " + shell_quote(json.string()) + " " +
                          shell_quote(temp.path().string()) + " >&2";
  FILE* pipe = ::popen(cmd.c_str(), "w");
  if (!pipe) throw InputError(png.string(), "cannot start " + python);
  std::fputs(kPlotScript, pipe);
  const int status = ::pclose(pipe);
  if (status != 0) throw InputError(png.string(), "the plot script failed (" + python + ", status " +
                                                      std::to_string(status) + ")");
  temp.commit();
  return true;
}

}  // namespace fastshade
