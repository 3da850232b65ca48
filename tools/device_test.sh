#!/usr/bin/env bash
# Runs ON the GPU machine (device tool), from the repository root: the whole ctest suite, the
# CUDA instances of the typed backend tests included, on the build that
# `SEASPRING_DEVICE_TESTS=1 tools/device_build.sh` packed (carry build-dev/tests.tar.xz and
# build-dev/tests.root). The build's absolute paths (source tree, ../shared) are recreated as
# links to this checkout. Writes the ctest log under $OUT. Extra arguments go to ctest (-R ...).
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${OUT:-/tmp/seaspring_out}"
mkdir -p "$out"
src_root="$(cat "$root/build-dev/tests.root")"
if [[ "$src_root" != "$root" ]]; then
  mkdir -p "$(dirname "$src_root")"
  [[ -e "$src_root" ]] || ln -s "$root" "$src_root"
fi
build="$src_root/build-dev"
mkdir -p "$build"
tar -xJf "$root/build-dev/tests.tar.xz" -C "$build"
# ../shared beside the source tree (the tests that read it skip visibly without it).
shared="$(dirname "$src_root")/shared"
[[ -e "$shared" ]] || ln -s "$build/shared" "$shared"
export LD_LIBRARY_PATH="$build/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
# The Python tests were configured with Debian's /usr/bin/python3; where that one lacks numpy,
# h5py or matplotlib (the GPU machines keep them in another Python), point them at one that has them.
if ! /usr/bin/python3 -c "import numpy, h5py, matplotlib" 2>/dev/null; then
  for py in "$(command -v python3)" /opt/torch/.venv/bin/python3; do
    if [[ -x "$py" ]] && "$py" -c "import numpy, h5py, matplotlib" 2>/dev/null; then
      find "$build" -name CTestTestfile.cmake -exec sed -i "s#/usr/bin/python3#$py#g" {} +
      echo "Python tests run with $py"
      break
    fi
  done
fi
nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader | tee "$out/gpu.txt"
ctest_bin="$(command -v ctest || true)"
[[ -z "$ctest_bin" && -x /opt/torch/.venv/bin/ctest ]] && ctest_bin=/opt/torch/.venv/bin/ctest
[[ -z "$ctest_bin" ]] && { echo "no ctest on this machine"; exit 2; }
cd "$build" && "$ctest_bin" --output-on-failure -j 8 "$@" 2>&1 | tee "$out/ctest.log"
rc=${PIPESTATUS[0]}
echo "== skipped tests =="; grep -E "Skipped|\*\*\*Skipped| skipped" "$out/ctest.log" | head -40
exit "$rc"
