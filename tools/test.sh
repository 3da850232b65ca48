#!/usr/bin/env bash
# Quick start 2/2: installs what is missing, builds, and runs the whole test suite, then a
# short fuzz run.
# CUDA tests skip (visibly) when no GPU is present.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/tools/setup-deps.sh"
"$root/tools/build.sh"
cd "$root/build"
ctest --output-on-failure -j "${SEASPRING_JOBS:-$(nproc)}"
# A short fuzz run (issue 14): each libFuzzer target of tests/fuzz for 20 s with clang,
# AddressSanitizer and UBSan (tools/fuzz.sh; its build goes to build-fuzz/).
if command -v clang++ >/dev/null 2>&1; then
  "$root/tools/fuzz.sh" --time 20
else
  echo "fuzz: SKIPPED (no clang++; tools/setup-deps.sh installs it)"
fi
