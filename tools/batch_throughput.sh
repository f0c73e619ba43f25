#!/usr/bin/env bash
# Batch throughput on 1 and 2 threads, alternated: every run renders every mesh of a folder
# into a fresh directory and reports the batch's own images/s (mesh loading included, process
# start-up not; MODELS_DIR may also be a list file).
#   bash tools/batch_throughput.sh [MODELS_DIR] [PAIRS] [SIZE] [MAX_ATTEMPTS] [VIEWS]
#
# The machine is shared, and Linux gives each session a fair share of the CPU (autogroup): while
# anyone else keeps a core busy, a 2-thread run gets no more CPU than a 1-thread run and the
# ratio says nothing. So each run starts only once the CPUs have been idle for half a second
# (/proc/stat), measures how much CPU everything else used meanwhile
# (busy time in /proc/stat minus the run's own), and a pair counts only if, in both runs, the
# others used under 10 % of one core. Prints every run, then medians over the clean pairs.
set -euo pipefail
cd "$(dirname "$0")/.."
models=${1:-../shared/models}
pairs=${2:-7}
size=${3:-256x256}
attempts=${4:-200}
views=${5:-1}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
hz=$(getconf CLK_TCK)
source tools/timing_helpers.sh

# One run: prints "RATE WALL_S OTHERS_CPU_FRACTION".
run() {
  wait_for_idle
  rm -rf "$out/r"
  local before after start end line rate own
  before=$(busy_jiffies)
  start=$(date +%s.%N)
  line=$(/usr/bin/time -f "%U %S" -o "$out/time" build/fastshade batch "$models" -o "$out/r" \
         --size "$size" --views "$views" --threads "$1" 2>/dev/null | head -1)
  end=$(date +%s.%N)
  after=$(busy_jiffies)
  rate=$(echo "$line" | sed -n 's/.*(\([0-9.]*\) images\/s.*/\1/p')
  own=$(awk '{print $1 + $2}' "$out/time")
  echo "$rate $(echo "$end - $start" | bc) $(echo "(($after - $before) / $hz - $own) / ($end - $start)" | bc -l)"
}

clean=0
for attempt in $(seq "$attempts"); do
  [ "$clean" -lt "$pairs" ] || break
  read -r rate1 wall1 other1 < <(run 1)
  read -r rate2 wall2 other2 < <(run 2)
  ok=$(echo "$other1 < 0.1 && $other2 < 0.1" | bc)
  printf '1 thread %6.2f img/s (others %4.2f core)  2 threads %6.2f img/s (others %4.2f core)  ratio %.2f %s\n' \
    "$rate1" "$other1" "$rate2" "$other2" "$(echo "$rate2 / $rate1" | bc -l)" "$([ "$ok" = 1 ] && echo clean || echo -)"
  if [ "$ok" = 1 ]; then
    echo "$rate1 $rate2 $wall1 $wall2" >> "$out/clean"
    clean=$((clean + 1))
  fi
done
[ "$clean" -gt 0 ] || { echo "no clean pair in $attempts attempts: the machine was never idle" >&2; exit 1; }
one=$(awk '{print $1}' "$out/clean" | median)
two=$(awk '{print $2}' "$out/clean" | median)
ratios=$(awk '{print $2 / $1}' "$out/clean" | median)
wall1=$(awk '{print $3}' "$out/clean" | median)
wall2=$(awk '{print $4}' "$out/clean" | median)
printf 'clean pairs: %d; median images/s: 1 thread %.2f, 2 threads %.2f; ratio of medians %.2f, median of ratios %.2f\n' \
  "$clean" "$one" "$two" "$(echo "$two / $one" | bc -l)" "$ratios"
printf 'whole process, start-up included: median wall 1 thread %.3f s, 2 threads %.3f s, ratio %.2f\n' \
  "$wall1" "$wall2" "$(echo "$wall1 / $wall2" | bc -l)"
