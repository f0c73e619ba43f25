#!/usr/bin/env bash
# The per-method error and frame-time table of docs/KERNELS.md: every method and BRDF on the
# bunny (1920x1080) and an icosphere (1920x1080), at n = 10, 100, 1000, against `reference`.
#   bash tools/kernel_table.sh [BUILD_DIR] > table.md
# Needs ../shared/models/bunny.ply. Times: median of 10 frames, 2 threads, this machine.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${1:-build}/fastshade
models=$(cd .. && pwd)/shared/models
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

scene() {  # name object shininess
  cat > "$work/$1.json" <<JSON
{"image": {"width": 1920, "height": 1080, "background": [0, 0, 0]},
 "camera": {"fit": true, "distance": 2.5, "fovy_deg": 45},
 "lights": [{"type": "directional", "direction": [1, 1, 1], "color": [1, 1, 1], "space": "view"}],
 "ambient": [0.1, 0.1, 0.1],
 "materials": {"m": {"diffuse": 0.7, "specular": 0.5, "shininess": $3}},
 "objects": [$2]}
JSON
}

configs=("gouraud" "phong" "phong --normals adaptive" "phong --normals equal-angle" "hybrid --max-error 0.5" "hybrid --max-error 1" "hybrid --max-error 2"
         "hybrid --max-error 4")
for b in cosk:1 cosk:3 schlick schlick-pow2 quadratic quadratic-fit poly2 poly3; do
  configs+=("phong --brdf $b")
done

echo "| scene | n | method | ms | max LSB | RMSE LSB | PSNR dB | % px > 1 LSB |"
echo "|---|---:|---|---:|---:|---:|---:|---:|"
for n in 10 100 1000; do
  scene "bunny-$n" "{\"mesh\": \"$models/bunny.ply\", \"material\": \"m\", \"normals\": \"recompute\"}" "$n"
  scene "icosphere-$n" '{"primitive": "icosphere", "subdivisions": 4, "material": "m"}' "$n"
  for s in bunny icosphere; do
    f="$work/$s-$n.json"
    "$bin" render "$f" -o "$work/ref.png" --method reference > /dev/null
    for c in "${configs[@]}"; do
      # shellcheck disable=SC2086
      ms=$("$bin" render "$f" -o "$work/out.png" --method $c --threads 2 --frames 10 |
           sed -E 's/.*: ([0-9.]+) ms \(front.*/\1/')
      read -r max rmse psnr pct < <("$bin" compare "$work/out.png" "$work/ref.png" --json |
        python3 -c 'import json,sys; j=json.load(sys.stdin); print("%.0f" % j["max_abs_lsb"], "%.4f" % j["rmse_lsb"], "inf" if j["psnr_db"] is None else "%.1f" % j["psnr_db"], "%.4f" % j["pct_over_1lsb"])')
      echo "| $s | $n | $c | $ms | $max | $rmse | $psnr | $pct |"
    done
  done
done
