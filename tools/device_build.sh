#!/usr/bin/env bash
# Builds SeaSpring with the CUDA backend (sm_90) into build-dev/ for the lent GPU machines and
# copies the shared libraries the binaries need (HDF5, pugixml, their dependencies; glibc
# excluded) into build-dev/lib, so that build-dev can be carried to the device machine and run
# there with LD_LIBRARY_PATH=build-dev/lib (tools/device_check.sh does this).
# SEASPRING_DEVICE_TESTS=1: also builds the whole test suite and packs it, with everything ctest
# needs there, into build-dev/tests.tar.xz for tools/device_test.sh (carry build-dev/tests.tar.xz).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build-dev"
tests=OFF
[[ -n "${SEASPRING_DEVICE_TESTS:-}" ]] && tests=ON
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DSEASPRING_CUDA=ON \
  -DCMAKE_CUDA_ARCHITECTURES=90 -DSEASPRING_TESTS=$tests >/dev/null
if [[ $tests == ON ]]; then
  cmake --build "$build" -j "${SEASPRING_JOBS:-$(nproc)}"
else
  cmake --build "$build" -j "${SEASPRING_JOBS:-$(nproc)}" --target seaspring gencase
fi
mkdir -p "$build/lib"
ldd "$build"/bin/* | awk '/=> \//{print $3}' | sort -u |
  grep -v -E '/(libc|libm|libresolv|libpthread|libdl|librt)\.so' |
  while read -r lib; do cp -L -u "$lib" "$build/lib/"; done
du -sh "$build/bin" "$build/lib"
# The shared DualSPHysics inputs live outside the repository and do not travel: copy them.
mkdir -p "$build/shared-cases"
cp "$root/../shared/dualsphysics-cases/Spheric2Dam_01M.xml" \
   "$root/../shared/dualsphysics-cases/CaseDambreakVal2D_Def.xml" \
   "$root/../shared/validation-data/antoci2007-elastic-gate/exp_tip_dx_antoci2007_digitized_A.csv" \
   "$root/../shared/validation-data/antoci2007-elastic-gate/exp_tip_dy_antoci2007_digitized_A.csv" "$build/shared-cases/"
mkdir -p "$build/shared-cases/flexstruc"
cp "$root/../shared/dualsphysics-cases/flexstruc/CaseDambreak2D_FSI_Def.xml" \
   "$root/../shared/dualsphysics-cases/flexstruc/DambreakGateTimeSeries.csv" "$build/shared-cases/flexstruc/"
# The reference data and DualSPHysics cases for tools/validate.py (SEASPRING_SHARED=build-dev/shared).
mkdir -p "$build/shared"
cp -r "$root/../shared/validation-data" "$root/../shared/dualsphysics-cases" "$build/shared/"
if [[ $tests == ON ]]; then
  # ctest's files hold absolute paths of this machine: device_test.sh recreates them there.
  tmp="$(mktemp -d)"
  (cd "$build" && tar --exclude='*.o' --exclude='*.a' --exclude='./tests.tar.xz' --exclude='./validation' \
    --exclude='./base' -cJf "$tmp/tests.tar.xz" .)
  mv "$tmp/tests.tar.xz" "$build/tests.tar.xz" && rmdir "$tmp"
  echo "$root" >"$build/tests.root"
  du -sh "$build/tests.tar.xz"
fi
