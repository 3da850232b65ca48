#!/usr/bin/env bash
# Quick start 2/2: installs what is missing, builds, and runs the whole test suite.
# CUDA tests skip (visibly) when no GPU is present.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/tools/setup-deps.sh"
"$root/tools/build.sh"
cd "$root/build"
ctest --output-on-failure -j "${SEASPRING_JOBS:-$(nproc)}"
