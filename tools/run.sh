#!/usr/bin/env bash
# Quick start 1/2: installs what is missing, builds, and generates the default case
# (a small 3D dam break, cases/dambreak3d). Prints where the output is.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/tools/setup-deps.sh"
"$root/tools/build.sh"
case_def="$root/cases/dambreak3d/DamBreak3D_Def.xml"
out="${SEASPRING_OUT:-$root/out/dambreak3d}"
"${SEASPRING_BUILD_DIR:-$root/build}/bin/gencase" "$case_def" "$out/DamBreak3D" -save:vtk
echo
echo "Output: $out"
echo "  $out/DamBreak3D.xml  resolved case (constants, parameters, particle blocks)"
echo "  $out/DamBreak3D.h5   particles (HDF5)"
echo "  $out/DamBreak3D.vtu  preview: open it in ParaView"
