#!/usr/bin/env bash
# One entry point for a fresh Debian 12 machine: installs what is missing, builds (Release),
# then either renders the embedded default scene or runs the whole test suite.
#   bash tools/dev.sh render   -> out/default.png and a one-line summary
#   bash tools/dev.sh test     -> every test through ctest: GoogleTest, and pytest of the Python
#                                 module in build/venv (made here: pip install of nanobind,
#                                 numpy, pytest and ray from PyPI)
#   bash tools/dev.sh sanitize -> every test, built with ASan + UBSan (no recovery) in build-asan/
# Idempotent: nothing is installed or rebuilt that is already there.
set -euo pipefail
cd "$(dirname "$0")/.."

mode=${1:-}
case "$mode" in render|test|sanitize) ;; *) echo "usage: bash tools/dev.sh render|test|sanitize" >&2; exit 2 ;; esac

packages=(build-essential cmake ninja-build pkg-config libtbb-dev libglm-dev libopenmesh-dev
          libopenimageio-dev libpng-dev libhwy-dev libgtest-dev libbenchmark-dev nlohmann-json3-dev
          libcli11-dev)
[ "$mode" = render ] || packages+=(python3-dev python3-venv)
# Optional, not installed here: python3-matplotlib draws the plots of `fastshade report` and
# `fastshade bench scaling`; without it both write their tables and say so.
bash tools/ensure_packages.sh "${packages[@]}"

jobs=$(nproc)
# The Python module's venv: what building it (nanobind) and testing it (pytest, numpy, Ray) need.
# Debian's python3 refuses system-wide pip. The marker says the install finished.
venv=build/venv
if [ "$mode" != render ] && [ ! -f "$venv/.installed" ]; then
  python3 -m venv "$venv"
  "$venv/bin/pip" install -q --disable-pip-version-check "nanobind>=2.0" numpy pytest ray >&2
  touch "$venv/.installed"
fi
# Turns the module (and its pytest) on in a build directory that lacks it.
with_python() {
  if [ "$(sed -n 's/^FASTSHADE_PYTHON:BOOL=//p' "$1/CMakeCache.txt")" != ON ]; then
    cmake -S . -B "$1" -DFASTSHADE_PYTHON=ON -DPython_EXECUTABLE="$PWD/$venv/bin/python" >&2
  fi
}
if [ "$mode" = sanitize ]; then
  # Sanitizers slow the suite about 3x; leaks are reported too (docs/FUZZING.md).
  if [ ! -f build-asan/build.ninja ]; then
    cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Release -DFASTSHADE_SANITIZE=ON -DFASTSHADE_BENCH=OFF >&2
  fi
  with_python build-asan
  cmake --build build-asan -j "$jobs" >&2
  exec ctest --test-dir build-asan --output-on-failure -j "$jobs"
fi
if [ ! -f build/build.ninja ]; then
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >&2
fi

if [ "$mode" = render ]; then
  # Only what rendering needs: the library and the program, not the tests or benchmarks.
  cmake --build build -j "$jobs" --target fastshade >&2
  mkdir -p out
  exec build/fastshade render -o out/default.png
fi
with_python build
cmake --build build -j "$jobs" >&2
# ctest lists skipped tests by name only: say once why the shared-model ones skipped.
models=${FASTSHADE_SHARED_MODELS:-../shared/models}
if [ ! -d "$models" ]; then
  echo "note: $models is missing: the tests that render the shared models skip (clone ../shared" \
       "beside this checkout, or set FASTSHADE_SHARED_MODELS=DIR)" >&2
fi
exec ctest --test-dir build --output-on-failure -j "$jobs"
