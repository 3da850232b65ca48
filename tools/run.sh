#!/usr/bin/env bash
# Quick start 1/2: installs what is missing, builds, generates the default case (a small 3D
# dam break, cases/dambreak3d) and runs it with seaspring (GPU when one exists, else all CPU
# cores). Prints where the output is. SEASPRING_RUN_ARGS adds solver options (e.g. -tmax:0.2).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/tools/setup-deps.sh"
"$root/tools/build.sh"
bin="${SEASPRING_BUILD_DIR:-$root/build}/bin"
case_def="$root/cases/dambreak3d/DamBreak3D_Def.xml"
out="${SEASPRING_OUT:-$root/out/dambreak3d}"
"$bin/gencase" "$case_def" "$out/DamBreak3D" -save:vtk
# shellcheck disable=SC2086
"$bin/seaspring" -overwrite ${SEASPRING_RUN_ARGS:-} "$out/DamBreak3D" "$out/run"
echo
echo "Output: $out"
echo "  $out/DamBreak3D.xml    resolved case (constants, parameters, particle blocks)"
echo "  $out/DamBreak3D.h5     initial particles (HDF5); DamBreak3D.vtu: preview"
echo "  $out/run/parts.xdmf    the simulation as one time series: open it in ParaView"
echo "  $out/run/data/         part_NNNN.h5 at every TimeOut"
echo "  $out/run/run.json      run summary (backend, counts, steps, timing, state hash)"
