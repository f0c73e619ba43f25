#!/usr/bin/env python3
"""Error-against-time plots for `fastshade report`: one PNG per scene, read from results.csv.

    python3 tools/report_plots.py OUT/results.csv OUT

Each figure has two panels, RMSE and max error (8-bit steps) against median frame time (log
axis); the Pareto front the report computed (columns pareto_rmse, pareto_max) is drawn as a
staircase with its points filled. The PNG goes where the row's `plot` column says. Exits 3,
printing nothing, when matplotlib is missing: the report then says so itself.
"""
import csv
import sys
from collections import OrderedDict

NO_MATPLOTLIB = 3  # report_command.cpp: kPlotsNoMatplotlib

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.lines
    import matplotlib.pyplot as plt
    import matplotlib.ticker
except ImportError:
    sys.exit(NO_MATPLOTLIB)

# One colour per method; configurations of a method share it.
METHOD_COLOURS = {
    "reference": "#000000",
    "phong": "#1f77b4",
    "gouraud": "#d62728",
    "hybrid": "#2ca02c",
    "auto": "#9467bd",
}
OTHER_COLOURS = ["#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"]

# Zero error cannot sit on a log axis: such points are drawn this far below the smallest
# non-zero error of the panel, on a line marked "0".
ZERO_BELOW_FACTOR = 4.0


def colour_of(method, extra):
    if method not in METHOD_COLOURS and method not in extra:
        extra[method] = OTHER_COLOURS[len(extra) % len(OTHER_COLOURS)]
    return METHOD_COLOURS.get(method) or extra[method]


def short_label(config, method):
    """'phong --brdf schlick' -> 'schlick'; 'hybrid --max-error 2' -> 'hybrid 2'."""
    flags = config[len(method):].split()
    values = [f for f in flags if not f.startswith("--")]
    return method if not values else (method + " " if method != "phong" else "") + " ".join(values)


class LabelPlacer:
    """Keeps point labels of one panel from overlapping: a label that would cover an earlier one
    moves up or down by whole lines, with a thin leader to its point."""

    LINE_PX = 9.0       # a 7-point label's height at the figure's dpi, with a little air
    CHAR_PX = 4.3       # its mean character width
    TRIES = 12

    def __init__(self, ax):
        self.ax = ax
        self.boxes = []

    def _free(self, box):
        x0, y0, x1, y1 = box
        return all(x1 <= a0 or x0 >= a1 or y1 <= b0 or y0 >= b1 for a0, b0, a1, b1 in self.boxes)

    def place(self, x, y, text, **style):
        px, py = self.ax.transData.transform((x, y))
        width = self.CHAR_PX * len(text)
        for k in range(self.TRIES):
            shift = (k + 1) // 2 * (1 if k % 2 else -1) * self.LINE_PX
            box = (px + 4, py + 2 + shift, px + 4 + width, py + 2 + shift + self.LINE_PX)
            if self._free(box):
                break
        self.boxes.append(box)
        moved = box[1] - (py + 2) != 0
        self.ax.annotate(text, (x, y), xytext=(4, 2 + box[1] - (py + 2)), textcoords="offset pixels",
                         fontsize=7, va="bottom",
                         arrowprops=dict(arrowstyle="-", linewidth=0.4, color=style["color"]) if moved else None,
                         **style)


def panel(ax, rows, error_key, front_key, title, extra_colours):
    errors = [float(r[error_key]) for r in rows]
    times = [float(r["median_ms"]) for r in rows]
    positive = [e for e in errors if e > 0]
    floor = (min(positive) if positive else 1.0) / ZERO_BELOW_FACTOR
    ys = [e if e > 0 else floor for e in errors]
    for r, x, y in zip(rows, times, ys):
        on_front = r[front_key] == "1"
        colour = colour_of(r["method"], extra_colours)
        ax.scatter(x, y, s=60 if on_front else 28, zorder=3, facecolors=colour if on_front else "white",
                   edgecolors=colour, linewidths=1.3)
    front = sorted((x, y) for r, x, y in zip(rows, times, ys) if r[front_key] == "1")
    if front:
        fx, fy = zip(*front)
        ax.step(fx, fy, where="post", color="#555555", linewidth=1, linestyle="--", zorder=2)
    ax.axhline(floor, color="#bbbbbb", linewidth=0.6, zorder=1)
    ax.set_xscale("log")
    ax.set_yscale("log")
    # Frame times span a factor of a few: label the minor ticks too, as plain numbers.
    plain = matplotlib.ticker.FuncFormatter(lambda v, _: f"{v:g}")
    ax.xaxis.set_major_formatter(plain)
    ax.xaxis.set_minor_formatter(plain)
    ax.tick_params(axis="x", which="minor", labelsize=7)
    ax.set_xlabel("median frame time, ms (log)")
    ax.set_ylabel(title + " vs reference, LSB (log; 0 on the grey line)")
    ax.grid(True, which="both", linewidth=0.3, alpha=0.5)
    ax.figure.canvas.draw()  # fixes the axes' limits, so that label positions hold
    placer = LabelPlacer(ax)
    # Front points first: their labels keep their places.
    for r, x, y in sorted(zip(rows, times, ys), key=lambda t: t[0][front_key] != "1"):
        on_front = r[front_key] == "1"
        placer.place(x, y, short_label(r["config"], r["method"]),
                     color=colour_of(r["method"], extra_colours),
                     fontweight="bold" if on_front else "normal")


def legend_handles(rows, extra_colours):
    handles = [matplotlib.lines.Line2D([], [], color="#555555", linestyle="--", linewidth=1,
                                       label="Pareto front (filled points)")]
    for method in OrderedDict((r["method"], None) for r in rows):
        handles.append(matplotlib.lines.Line2D([], [], marker="o", linestyle="", label=method,
                                               color=colour_of(method, extra_colours)))
    return handles


def main():
    if len(sys.argv) != 3:
        print("usage: report_plots.py RESULTS.csv OUT_DIR", file=sys.stderr)
        return 2
    csv_path, out_dir = sys.argv[1], sys.argv[2]
    with open(csv_path, newline="") as f:
        rows = list(csv.DictReader(f))
    # One plot per scene and ISA: the rows name their plot's file.
    plots = OrderedDict()
    for r in rows:
        plots.setdefault(r["plot"], []).append(r)
    extra_colours = {}
    for rs in plots.values():
        first = rs[0]
        scene = first["scene"]
        fig, axes = plt.subplots(1, 2, figsize=(12, 5))
        panel(axes[0], rs, "rmse_lsb", "pareto_rmse", "RMSE", extra_colours)
        panel(axes[1], rs, "max_abs_lsb", "pareto_max", "max error", extra_colours)
        # Below the panels: inside, it would hide points, and the fast accurate corner matters.
        handles = legend_handles(rs, extra_colours)
        fig.legend(handles=handles, loc="lower center", ncol=len(handles), fontsize=8, frameon=False)
        fig.suptitle(f"{scene}: {first['width']}x{first['height']}, {int(first['triangles']):,} "
                     f"triangles; {first['threads']} threads, {first['isa']}, median of "
                     f"{first['frames']} frames", fontsize=10)
        fig.tight_layout(rect=(0, 0.05, 1, 1))
        fig.savefig(f"{out_dir}/{first['plot']}", dpi=90)
        plt.close(fig)
    return 0


if __name__ == "__main__":
    sys.exit(main())
