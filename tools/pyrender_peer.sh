#!/usr/bin/env bash
# fastshade batch against pyrender + OSMesa (Mesa llvmpipe) on every mesh of ../shared/models,
# whole processes (start-up, loading and PNG writing included), alternated A, B, A, B, ...:
#   A = build/fastshade batch MODELS -o TMP --size WxH
#   B = build/pyrender-venv/bin/python bench/peers/pyrender_batch.py MODELS TMP --size WxH
# Prints each round's wall seconds and images/s, then per size the median images/s of each and
# the ratio fastshade / pyrender. Each run writes into a fresh directory (fastshade batch would
# skip images an earlier run wrote). One untimed warm-up pair per size fills the page cache.
# Each run waits for idle CPUs first and reports how many cores other processes used meanwhile
# ("others"): the machine is shared, and a round with others near 1 core says little.
#   bash tools/pyrender_peer.sh [ROUNDS (5)] [WxH ... (256x256 1920x1080)]
#
# Installs what is missing: Debian's libosmesa6, and a venv build/pyrender-venv with pyrender
# and then, in a second pip command, PyOpenGL >= 3.1.7. pyrender 0.1.45 pins PyOpenGL 3.1.0,
# whose OpenGL.osmesa lacks OSMesaCreateContextAttribs (ImportError when the renderer starts);
# pip installs the newer one over the pin, says the pin is broken (exit code 0), and pyrender
# then works. Both in one pip command would make pip fall back to pyrender 0.1.18 (no pin).
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=${1:-5}
sizes=("${@:2}")
((${#sizes[@]})) || sizes=(256x256 1920x1080)
models=../shared/models

[ -d ../shared ] || { echo "pyrender_peer: skipped: ../shared is missing (the meshes live in ../shared/models)"; exit 0; }
[ -d "$models" ] || { echo "pyrender_peer: $models is missing" >&2; exit 1; }
[ -x build/fastshade ] || { echo "pyrender_peer: build/fastshade is missing: build it first" >&2; exit 1; }

bash tools/ensure_packages.sh libosmesa6
venv=build/pyrender-venv
python=$venv/bin/python
[ -x "$python" ] || python3 -m venv "$venv"
if ! "$python" -c 'import pyrender, OpenGL, sys; sys.exit(tuple(map(int, OpenGL.__version__.split(".")[:3])) < (3, 1, 7))' 2>/dev/null; then
  "$python" -m pip install -q pyrender==0.1.45 >&2
  "$python" -m pip install -q 'PyOpenGL>=3.1.7' >&2  # pip's "ERROR: ... requires PyOpenGL==3.1.0" is expected
fi
export PYOPENGL_PLATFORM=osmesa

out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
hz=$(getconf CLK_TCK)
source tools/timing_helpers.sh

# One whole-process run into a fresh directory: prints "WALL_S IMAGES OTHERS", OTHERS being the
# cores that other processes kept busy meanwhile. A run that failed (exit code not 0) has its
# summary line printed to stderr.
run() {  # NAME SIZE
  local name=$1 size=$2 start end before after status=0 summary cmd
  if [ "$name" = fastshade ]; then
    cmd=(build/fastshade batch "$models" -o "$out/img" --size "$size")
  else
    cmd=("$python" bench/peers/pyrender_batch.py "$models" "$out/img" --size "$size")
  fi
  rm -rf "$out/img"
  wait_for_idle
  before=$(busy_jiffies)
  start=$(date +%s.%N)
  summary=$(/usr/bin/time -f "%U %S" -o "$out/time" "${cmd[@]}" 2>/dev/null) || status=$?
  end=$(date +%s.%N)
  after=$(busy_jiffies)
  [ "$status" = 0 ] || echo "pyrender_peer: $name exited $status: $summary" >&2
  echo "$(echo "$end - $start" | bc) $(find "$out/img" -name '*.png' | wc -l)" \
    "$(awk -v b="$before" -v a="$after" -v hz="$hz" -v w="$(echo "$end - $start" | bc)" \
         '{print ((a - b) / hz - $1 - $2) / w}' "$out/time")"
}

echo "meshes: $(find "$models" -type f \( -iname '*.obj' -o -iname '*.off' -o -iname '*.ply' -o -iname '*.stl' \) | wc -l) in $models; $(nproc) cores; $rounds rounds"
for size in "${sizes[@]}"; do
  run fastshade "$size" > /dev/null
  run pyrender "$size" > /dev/null
  : > "$out/rates"
  for round in $(seq "$rounds"); do
    read -r wall_a images_a others_a < <(run fastshade "$size")
    read -r wall_b images_b others_b < <(run pyrender "$size")
    rate_a=$(echo "$images_a / $wall_a" | bc -l)
    rate_b=$(echo "$images_b / $wall_b" | bc -l)
    echo "$rate_a $rate_b" >> "$out/rates"
    printf '%s round %d: fastshade %6.2f s %3d images %6.2f images/s (others %4.2f core) | pyrender %6.2f s %3d images %6.2f images/s (others %4.2f core)\n' \
      "$size" "$round" "$wall_a" "$images_a" "$rate_a" "$others_a" "$wall_b" "$images_b" "$rate_b" "$others_b"
  done
  med_a=$(awk '{print $1}' "$out/rates" | median)
  med_b=$(awk '{print $2}' "$out/rates" | median)
  printf '%s median images/s: fastshade %.2f, pyrender %.2f; ratio fastshade/pyrender %.2f\n\n' \
    "$size" "$med_a" "$med_b" "$(echo "$med_a / $med_b" | bc -l)"
done
