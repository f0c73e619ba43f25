#!/usr/bin/env python3
"""Alternated timing of several render configurations on one frame.

The development guest's speed drifts within minutes (docs/PERFORMANCE.md), so a sequential
sweep compares the drift, not the configurations. Here the configurations take turns, ROUNDS
times; each turn is `BIN render SCENE -o /tmp/alt_LABEL.png --threads THREADS --frames 10
FLAGS` (one warm-up frame, the median of 10 timed ones, as the render line reports it). The
figure to read is the median over rounds of each configuration's ratio to the first one
measured in the same round; the plain medians and minima follow.

  python3 tools/alt.py ROUNDS SCENE.json THREADS "LABEL|[BIN=path] [ENV:K=V] flags..." ...

BIN= picks another fastshade binary (default: build/fastshade beside this script's
checkout); ENV:K=V sets an environment variable for that configuration only.
"""
import os
import re
import shlex
import statistics
import subprocess
import sys

FRAME_MS = re.compile(r": ([0-9.]+) ms \(front end")


def parse_config(text, default_bin):
    label, _, rest = text.partition("|")
    binary, env, flags = default_bin, {}, []
    for word in shlex.split(rest):
        if word.startswith("BIN="):
            binary = word[4:]
        elif word.startswith("ENV:") and "=" in word:
            key, _, value = word[4:].partition("=")
            env[key] = value
        else:
            flags.append(word)
    return label, binary, env, flags


def frame_ms(binary, env, flags, scene, threads, label):
    cmd = [binary, "render", scene, "-o", f"/tmp/alt_{label}.png", "--threads", str(threads),
           "--frames", "10", *flags]
    run = subprocess.run(cmd, capture_output=True, text=True, env={**os.environ, **env})
    match = FRAME_MS.search(run.stdout + run.stderr)
    if run.returncode != 0 or not match:
        sys.exit(f"alt.py: {' '.join(cmd)} failed: {(run.stderr or run.stdout).strip()}")
    return float(match.group(1))


def main():
    if len(sys.argv) < 5:
        sys.exit("usage: python3 tools/alt.py ROUNDS SCENE.json THREADS "
                 "\"LABEL|[BIN=path] [ENV:K=V] flags...\" ...")
    rounds, scene, threads = int(sys.argv[1]), sys.argv[2], int(sys.argv[3])
    default_bin = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "build",
                               "fastshade")
    configs = [parse_config(c, default_bin) for c in sys.argv[4:]]
    times = {label: [] for label, *_ in configs}
    for _ in range(rounds):
        for label, binary, env, flags in configs:
            times[label].append(frame_ms(binary, env, flags, scene, threads, label))
    first = configs[0][0]
    print(f"{scene}, {threads} threads, {rounds} rounds; ratio = median of per-round "
          f"ratios to '{first}'")
    for label, *_ in configs:
        ratios = [t / f for t, f in zip(times[label], times[first])]
        print(f"  {label:24s} ratio {statistics.median(ratios):.3f}  median "
              f"{statistics.median(times[label]):.2f} ms  min {min(times[label]):.2f} ms")


if __name__ == "__main__":
    main()
