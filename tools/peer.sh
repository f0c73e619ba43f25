#!/usr/bin/env bash
# fastshade side by side with Mesa's llvmpipe (bench/peers/): installs the EGL/OpenGL packages
# if missing, builds the llvmpipe_peer target in build/ (Release) and runs it on the bunny and
# dragon_871k frames with 1 and 2 threads. Extra arguments go to llvmpipe_peer (e.g.
# --frames 41, --images DIR). Separate from tools/dev.sh: the main build and tests need no GL.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri)
bash tools/ensure_packages.sh "${packages[@]}"

# Re-configuring finds EGL even in a build/ configured before it was installed.
if [ -f build/build.ninja ]; then cmake -S . -B build >&2; else cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >&2; fi
cmake --build build -j "$(nproc)" --target llvmpipe_peer >&2

for threads in 1 2; do
  build/llvmpipe_peer --threads "$threads" "$@" bench/peers/bunny.json bench/peers/dragon_871k.json
  echo
done
