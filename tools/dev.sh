#!/usr/bin/env bash
# One entry point for a fresh Debian 12 machine: installs what is missing, builds (Release),
# then either renders the embedded default scene or runs the whole test suite.
#   bash tools/dev.sh render   -> out/default.png and a one-line summary
#   bash tools/dev.sh test     -> every test through ctest
# Idempotent: nothing is installed or rebuilt that is already there.
set -euo pipefail
cd "$(dirname "$0")/.."

mode=${1:-}
case "$mode" in render|test) ;; *) echo "usage: bash tools/dev.sh render|test" >&2; exit 2 ;; esac

# python3-matplotlib draws `fastshade bench scaling`'s plot; without it the command still
# writes its CSV and JSON.
packages=(build-essential cmake ninja-build pkg-config libtbb-dev libglm-dev libopenmesh-dev
          libopenimageio-dev libhwy-dev libgtest-dev libbenchmark-dev nlohmann-json3-dev
          libcli11-dev python3-matplotlib)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "installing: ${missing[*]}" >&2
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq "${missing[@]}" >&2
fi

jobs=$(nproc)
if [ ! -f build/build.ninja ]; then
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >&2
fi
cmake --build build -j "$jobs" >&2

if [ "$mode" = render ]; then
  mkdir -p out
  exec build/fastshade render -o out/default.png
else
  exec ctest --test-dir build --output-on-failure -j "$jobs"
fi
