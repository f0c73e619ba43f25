#!/usr/bin/env bash
# The classifier's plan on every shared mesh at n = 10, 100, 1000 (docs/CLASSIFIER.md): share
# of triangles and of visible pixels on each path, and auto's error against `reference`.
#   bash tools/classifier_table.sh [BUILD_DIR [RENDER_FLAGS...]] > table.md
# The frame of the benchmarks (1920x1080, fit camera at 2.5 radii, light toward (1,1,1) in
# view space, kd 0.7, ks 0.5), default --spec-threshold and --max-error, `--classifier bound` (the
# classifier on every frame, whatever auto's cost model would choose); RENDER_FLAGS go to auto's
# render (e.g. --classify-min-px 0: the classifier's plan for every triangle).
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${1:-build}/fastshade
shift || true
models=$(cd .. && pwd)/shared/models
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

echo "| mesh | n | triangles G / D / S % | of which unclassified % | visible pixels G / D / S % | max LSB | % covered px > 1 LSB |"
echo "|---|---:|---|---:|---|---:|---:|"
for mesh in "$models"/*.{obj,ply,off,stl}; do
  [ -f "$mesh" ] || continue
  for n in 10 100 1000; do
    cat > "$work/s.json" <<JSON
{"image": {"width": 1920, "height": 1080, "background": [0, 0, 0]},
 "camera": {"fit": true, "distance": 2.5, "fovy_deg": 45},
 "lights": [{"type": "directional", "direction": [1, 1, 1], "color": [1, 1, 1], "space": "view"}],
 "ambient": [0.1, 0.1, 0.1],
 "materials": {"m": {"diffuse": 0.7, "specular": 0.5, "shininess": $n}},
 "objects": [{"mesh": "$mesh", "material": "m"}]}
JSON
    "$bin" render "$work/s.json" -o "$work/auto.png" --stats "$work/auto.json" --classifier bound "$@" > /dev/null
    "$bin" render "$work/s.json" -o "$work/ref.png" --method reference > /dev/null
    "$bin" compare "$work/auto.png" "$work/ref.png" --json > "$work/diff.json"
    python3 - "$work/auto.json" "$work/diff.json" "$(basename "$mesh")" "$n" <<'PY'
import json, sys
stats, diff = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
paths = stats["paths"]
names = ["gouraud_diffuse", "pixel_diffuse", "specular"]
tris = sum(paths[p]["triangles"] for p in names) or 1
pix = sum(paths[p]["pixels"] for p in names) or 1
share = lambda key, total: " / ".join(f"{100 * paths[p][key] / total:.1f}" for p in names)
covered = stats["covered_pixels"] / (1920 * 1080)
over = diff["pct_over_1lsb"] / covered if covered else 0
unclassified = 100 * stats["triangles_unclassified"] / tris
print(f"| {sys.argv[3]} | {sys.argv[4]} | {share('triangles', tris)} | {unclassified:.1f} | {share('pixels', pix)} | "
      f"{diff['max_abs_lsb']:.0f} | {over:.4f} |")
PY
  done
done
