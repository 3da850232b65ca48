#!/usr/bin/env bash
# Configures and builds SeaSpring into build/ (CUDA backend when nvcc is present).
# Extra arguments go to CMake's configure step, e.g. -DSEASPRING_CUDA=OFF.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${SEASPRING_BUILD_DIR:-$root/build}"
jobs="${SEASPRING_JOBS:-$(nproc)}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$build" -j "$jobs"
