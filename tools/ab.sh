#!/usr/bin/env bash
# Alternated A/B of two fastshade binaries on one frame, the way docs/PERFORMANCE.md judges a
# change: the VM's speed drifts within minutes, so the binaries take turns, ROUNDS times, and
# only the ratio of their medians is read. Each turn is `render SCENE --method METHOD --threads
# THREADS --frames 10` (one warm-up frame, the median of 10 timed ones); images go to /tmp.
#   bash tools/ab.sh BIN_A BIN_B ROUNDS SCENE.json METHOD [THREADS] [more render flags...]
set -euo pipefail
[ $# -ge 5 ] || { echo "usage: bash tools/ab.sh BIN_A BIN_B ROUNDS SCENE.json METHOD [THREADS] [flags...]" >&2; exit 2; }
a=$1 b=$2 rounds=$3 scene=$4 method=$5
threads=${6:-2}
shift $(( $# < 6 ? $# : 6 ))

frame_ms() {  # BIN TAG [flags...]: the median frame time the render line reports, in ms
  local bin=$1 tag=$2
  shift 2
  "$bin" render "$scene" -o "/tmp/ab_$tag.png" --method "$method" --threads "$threads" --frames 10 "$@" 2>&1 |
    sed -n 's/.*: \([0-9.]*\) ms (front end.*/\1/p'
}

times_a=() times_b=()
for _ in $(seq "$rounds"); do
  times_a+=("$(frame_ms "$a" a "$@")")
  times_b+=("$(frame_ms "$b" b "$@")")
done

summary() {  # name, then the rounds' times: prints them, the min and the median
  local name=$1
  shift
  printf '%s\n' "$@" | sort -n | awk -v name="$name" '
    { v[NR] = $1 }
    END { med = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2
          printf "%s: min %.2f median %.2f ms (rounds:", name, v[1], med
          for (i = 1; i <= NR; ++i) printf " %s", v[i]; print ")" }'
}
summary "A $a" "${times_a[@]}"
summary "B $b" "${times_b[@]}"
cmp -s /tmp/ab_a.png /tmp/ab_b.png && echo "images: identical" || echo "images: differ"
