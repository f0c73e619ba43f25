#!/usr/bin/env python3
"""The Python module against the command line, alternated, as docs/PYTHON.md reports them.

  PYTHONPATH=build/python build/venv/bin/python bench/python_bench.py [ROUNDS]

1. Frames: `Renderer.render()` wall time per frame (the call, the GIL released, the array
   handed over) against `fastshade render --frames 10`'s median frame, on the bunny 1920x1080
   scene (bench/scenes/bunny.json), 2 threads. The ratio is python / command line.
2. Batches: images per second over ../shared/models at 256x256, loading and writing included,
   `fastshade batch --threads 2` (a whole process) against `fastshade.batch(engine="ray",
   threads_per_task=1)` with Ray already running (its start-up reported apart) and against
   `engine="local"`.
"""
import os
import pathlib
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

import fastshade

REPO = pathlib.Path(__file__).resolve().parents[1]
BINARY = pathlib.Path(os.environ.get("FASTSHADE_BINARY", REPO / "build" / "fastshade"))
MODELS = pathlib.Path(os.environ.get("FASTSHADE_SHARED_MODELS", REPO.parent / "shared" / "models"))
SCENE = REPO / "bench" / "scenes" / "bunny.json"


def cli_frame_ms():
    out = subprocess.run([str(BINARY), "render", str(SCENE), "-o", "/tmp/python_bench.png", "--threads", "2",
                          "--frames", "10"], check=True, capture_output=True, text=True).stdout
    return float(re.search(r": ([0-9.]+) ms \(front end", out)[1])


def python_frame_ms(renderer):
    renderer.render()  # warm-up
    times = []
    for _ in range(10):
        t0 = time.perf_counter()
        renderer.render()
        times.append((time.perf_counter() - t0) * 1e3)
    return statistics.median(times)


def cli_batch_rate(out):
    shutil.rmtree(out, ignore_errors=True)
    t0 = time.perf_counter()
    subprocess.run([str(BINARY), "batch", str(MODELS), "-o", str(out), "--size", "256x256", "--threads", "2"],
                   check=True, capture_output=True)
    return count_ok(out) / (time.perf_counter() - t0)


def python_batch_rate(out, engine):
    shutil.rmtree(out, ignore_errors=True)
    t0 = time.perf_counter()
    results = fastshade.batch(MODELS, out, size=(256, 256), engine=engine, threads_per_task=1 if engine == "ray" else 2)
    return sum(r["status"] == "ok" for r in results) / (time.perf_counter() - t0)


def count_ok(out):
    return sum('"status":"ok"' in line for line in (out / "results.jsonl").read_text().splitlines())


def main():
    rounds = int(sys.argv[1]) if len(sys.argv) > 1 else 5
    renderer = fastshade.Renderer(fastshade.Scene.from_file(SCENE), threads=2)
    ratios = []
    for _ in range(rounds):
        cli, py = cli_frame_ms(), python_frame_ms(renderer)
        ratios.append(py / cli)
        print(f"frame: command line {cli:.2f} ms, python {py:.2f} ms, ratio {py / cli:.3f}")
    print(f"frame ratio python / command line, median of {rounds}: {statistics.median(ratios):.3f}")
    if not MODELS.is_dir():
        print(f"batch: skipped, no models at {MODELS}")
        return
    import ray
    t0 = time.perf_counter()
    ray.init(num_cpus=2, include_dashboard=False, log_to_driver=False)
    print(f"ray.init: {time.perf_counter() - t0:.1f} s (not in the rates below)")
    scratch = pathlib.Path(tempfile.mkdtemp())
    rates = {"cli": [], "ray": [], "local": []}
    for _ in range(rounds):
        rates["cli"].append(cli_batch_rate(scratch / "cli"))
        rates["ray"].append(python_batch_rate(scratch / "ray", "ray"))
        rates["local"].append(python_batch_rate(scratch / "local", "local"))
        print("batch images/s: " + ", ".join(f"{k} {v[-1]:.1f}" for k, v in rates.items()))
    cli = statistics.median(rates["cli"])
    for k in ("ray", "local"):
        print(f"batch {k} / command line, median images/s: {statistics.median(rates[k]) / cli:.3f}")
    shutil.rmtree(scratch)


if __name__ == "__main__":
    main()
