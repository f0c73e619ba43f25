#!/usr/bin/env bash
# fastshade side by side with Mesa's llvmpipe (bench/peers/): installs the EGL/OpenGL packages
# if missing, builds the llvmpipe_peer target in build/ (Release) and runs it on the peer frames
# of the shared meshes (bench/peers/*.json) with 2 threads and llvmpipe culling back faces (as
# pyrender does) and not, then bunny and dragon_871k with 1 thread. Extra arguments go to
# llvmpipe_peer (e.g. --frames 41, --images DIR, --method phong). Separate from tools/dev.sh: the main build and tests need no GL.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri)
bash tools/ensure_packages.sh "${packages[@]}"

# Re-configuring finds EGL even in a build/ configured before it was installed.
if [ -f build/build.ninja ]; then cmake -S . -B build >&2; else cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >&2; fi
cmake --build build -j "$(nproc)" --target llvmpipe_peer >&2

for cull in back none; do
  build/llvmpipe_peer --threads 2 --cull "$cull" "$@" bench/peers/*.json
  echo
done
build/llvmpipe_peer --threads 1 --cull back "$@" bench/peers/bunny.json bench/peers/dragon_871k.json
