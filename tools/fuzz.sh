#!/usr/bin/env bash
# Coverage-guided fuzzing of every input reader (docs/FUZZING.md). Builds the libFuzzer
# targets and the parser tests (clang, ASan + UBSan, no recovery) in build-fuzz/, runs the
# tests (every fuzz seed and regression among them), then runs each fuzz target for SECONDS
# (default 60), JOBS at a time (default 1), from its seeds: fuzz/corpus/TARGET, the shared models
# of its format (../shared/models) and, for scenes, scenes/. Prints per target the executions,
# libFuzzer's coverage (cov: edges, ft: features) and any finding; a finding's input is kept in
# build-fuzz/findings/TARGET/: once fixed, move it to fuzz/regressions/TARGET/, where the test
# suite replays it. Exit 1 if anything was found.
#   bash tools/fuzz.sh [SECONDS] [TARGET...]      (FUZZ_JOBS=2 runs two targets at once)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(mesh_obj mesh_ply mesh_off mesh_stl scene_json render_config)
jobs=${FUZZ_JOBS:-1}

bash tools/ensure_packages.sh clang libfuzzer-14-dev libclang-rt-14-dev
if [ ! -f build-fuzz/build.ninja ]; then
  CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=Release -DFASTSHADE_FUZZ=ON \
    -DFASTSHADE_BENCH=OFF >&2
fi
cmake --build build-fuzz -j "$(nproc)" --target fuzzers fastshade_parser_tests >&2
# The input parsers' tests and every seed and regression, under the same sanitizers.
build-fuzz/fastshade_parser_tests --gtest_brief=1

# A target's seeds: the repository's, then the shared models of its format (a fuzzer reads
# only the first max_len bytes of each).
seed_dirs() {
  local target=$1 work=build-fuzz/seeds/$1
  rm -rf "$work" && mkdir -p "$work"
  local ext=
  case $target in mesh_obj) ext=obj ;; mesh_ply) ext=ply ;; mesh_off) ext=off ;; mesh_stl) ext=stl ;; esac
  if [ -n "$ext" ] && [ -d ../shared/models ]; then
    find ../shared/models -maxdepth 1 -name "*.$ext" -size -1024k -exec cp {} "$work" \;
  fi
  [ "$target" = scene_json ] && cp scenes/*.json "$work"
  echo "fuzz/corpus/$target" "$work"
}

run_one() {  # TARGET: fuzzes it; prints one summary line
  local target=$1 max_len=16384
  case $target in scene_json|render_config) max_len=4096 ;; esac
  local corpus=build-fuzz/corpus/$target findings=build-fuzz/findings/$target log=build-fuzz/fuzz_$target.log
  mkdir -p "$corpus" "$findings"
  local status=0
  # shellcheck disable=SC2046
  build-fuzz/fuzz_"$target" "$corpus" $(seed_dirs "$target") -max_total_time="$seconds" -max_len="$max_len" \
    -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$findings/" >"$log" 2>&1 || status=$?
  local execs cov
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  cov=$(grep -o 'cov: [0-9]* ft: [0-9]*' "$log" | tail -1)
  if [ "$status" -eq 0 ]; then
    echo "$target: ${execs:-?} executions in ${seconds} s, $cov, corpus $(ls "$corpus" | wc -l) inputs, nothing found"
  else
    echo "$target: FINDING after ${execs:-?} executions ($cov): $(grep -m1 -E 'fastshade finding|ERROR: |SUMMARY' "$log") (log: $log, input in $findings/)"
    return 1
  fi
}

failed=0
running=0
for target in "${targets[@]}"; do
  run_one "$target" &
  running=$((running + 1))
  if [ "$running" -ge "$jobs" ]; then
    wait -n || failed=1
    running=$((running - 1))
  fi
done
while [ "$running" -gt 0 ]; do
  wait -n || failed=1
  running=$((running - 1))
done
exit "$failed"
