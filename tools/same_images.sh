#!/usr/bin/env bash
# Whether two fastshade binaries draw the same pixels: every scene of scenes/ and bench/scenes
# (those whose meshes are here) with every configuration of report's table
# (src/app/report_configs.h), each also with --srgb, and the shading methods on every ISA this
# CPU runs. A change meant to leave images alone (a refactor, a build-time change) must print
# "0 differ".
#   bash tools/same_images.sh BIN_A BIN_B [SCENE.json...]
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: bash tools/same_images.sh BIN_A BIN_B [SCENE.json...]" >&2; exit 2; }
a=$1 b=$2
shift 2
cd "$(dirname "$0")/.."
scenes=("$@")
if [ ${#scenes[@]} -eq 0 ]; then
  scenes=(scenes/*.json)
  [ -d ../shared/models ] && scenes+=(bench/scenes/*.json)
fi
mapfile -t configs < <(sed -n '/kReportConfigs\[\] = {/,/^};/s/^ *"\([^"]*\)".*/\1/p' src/app/report_configs.h)
[ ${#configs[@]} -gt 10 ] || { echo "could not read report's table" >&2; exit 2; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
mapfile -t cpu_isas < <(for i in scalar sse4 avx2 avx512; do
  "$a" render -o "$dir/probe.png" --isa "$i" >/dev/null 2>&1 && echo "$i"; done)
runs=()
for c in "${configs[@]}"; do runs+=("$c" "$c --srgb"); done
for i in "${cpu_isas[@]}"; do
  for c in "phong" "phong --brdf schlick" "phong --normals adaptive" "hybrid" "gouraud" "auto"; do
    runs+=("$c --isa $i" "$c --isa $i --srgb")
  done
done
same=0 differ=0 refused=0
for scene in "${scenes[@]}"; do
  for run in "${runs[@]}"; do
    read -r -a words <<<"$run"
    ra=0 rb=0
    "$a" render "$scene" -o "$dir/a.png" --method "${words[@]}" >/dev/null 2>"$dir/a.err" || ra=$?
    "$b" render "$scene" -o "$dir/b.png" --method "${words[@]}" >/dev/null 2>"$dir/b.err" || rb=$?
    if [ "$ra" -ne 0 ] || [ "$rb" -ne 0 ]; then
      if [ "$ra" -eq "$rb" ] && cmp -s "$dir/a.err" "$dir/b.err"; then
        refused=$((refused + 1))
      else
        differ=$((differ + 1))
        echo "DIFFER (exit $ra vs $rb): $scene --method $run"
      fi
    elif cmp -s "$dir/a.png" "$dir/b.png"; then
      same=$((same + 1))
    else
      differ=$((differ + 1))
      echo "DIFFER: $scene --method $run"
    fi
    rm -f "$dir/a.png" "$dir/b.png"
  done
done
echo "$same identical, $refused refused alike, $differ differ (${#scenes[@]} scenes, ${#runs[@]} runs each; ISAs: ${cpu_isas[*]})"
[ "$differ" -eq 0 ]
