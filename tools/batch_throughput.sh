#!/usr/bin/env bash
# Batch throughput on 1 and 2 threads, alternated (the machine is shared: ratios within one
# run are what counts). Every round renders every mesh of a folder into a fresh directory.
#   bash tools/batch_throughput.sh [MODELS_DIR] [ROUNDS] [SIZE]
# Prints per round the batch's own images/s (loading included, process start-up not) and the
# wall time of the whole process, then the medians and their 2-thread / 1-thread ratios.
set -euo pipefail
cd "$(dirname "$0")/.."
models=${1:-../shared/models}
rounds=${2:-7}
size=${3:-256x256}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

median() { sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }

for round in $(seq "$rounds"); do
  for threads in 1 2; do
    rm -rf "$out/r"
    start=$(date +%s.%N)
    line=$(build/fastshade batch "$models" -o "$out/r" --size "$size" --threads "$threads" 2>/dev/null | head -1)
    wall=$(echo "$(date +%s.%N) - $start" | bc)
    rate=$(echo "$line" | sed -n 's/.*(\([0-9.]*\) images\/s.*/\1/p')
    images=$(echo "$line" | sed -n 's/^batch: \([0-9]*\) images.*/\1/p')
    echo "$threads $rate $(echo "$images / $wall" | bc -l)" >> "$out/runs"
    printf 'round %d, %d thread(s): %s images/s in the batch, %.3f s wall\n' "$round" "$threads" "$rate" "$wall"
  done
done
for col in 2 3; do
  one=$(awk -v c=$col '$1 == 1 {print $c}' "$out/runs" | median)
  two=$(awk -v c=$col '$1 == 2 {print $c}' "$out/runs" | median)
  what=$([ $col = 2 ] && echo "batch images/s" || echo "wall images/s  ")
  printf '%s: 1 thread %.2f, 2 threads %.2f, ratio %.2f\n' "$what" "$one" "$two" "$(echo "$two / $one" | bc -l)"
done
