#!/usr/bin/env bash
# Runs ON the GPU machine (device tool), from the repository root, with build-dev carried
# (tools/device_build.sh makes it; carry build-dev/{bin,lib,shared-cases} and .whl with an
# h5py wheel). VCPM solids: CPU (1 and 16 threads) / GPU bit-identity on solid-only, point-load,
# coupled (both coupling schemes) and breaking cases, and the GPU per-pass path; a fluid-only
# regression hash; long GPU runs (Antoci gate 2D and 3D, tip-loaded cantilever) with marker
# series; the solid benchmark. At most 8 files under $OUT (the device tool's limit).
# Usage: tools/device_check_solid.sh [bench DPs...]   (SEASPRING_PARITY_ONLY=1: parity checks only)
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export LD_LIBRARY_PATH="$root/build-dev/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
bin="$root/build-dev/bin"
out="${OUT:-/tmp/seaspring_out}"
work=/tmp/seaspring_dev_solid
mkdir -p "$out" "$work"
table="$out/parity_solid.txt"
nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader | tee "$table"
parity() {  # name case_path nsteps extra-args...
  local name=$1 kase=$2 n=$3; shift 3
  local h=() extra=""
  for b in "-cpu -threads:1" "-cpu -threads:2" "-cpu -threads:16" "-gpu"; do
    rm -rf "$work/o_$name"/{Run.out,run.json,parts.xdmf,ledger.csv,data,vtk,gauges}  # an earlier run (seaspring refuses to mix)
    # shellcheck disable=SC2086
    "$bin/seaspring" $b -nsteps:"$n" -sv:none -progress:0 "$@" "$kase" "$work/o_$name" >"$work/$name.${b//[ :]/_}.log" 2>&1 ||
      { echo "FAILED $name $b"; tail -5 "$work/$name.${b//[ :]/_}.log"; }
    h+=("$(grep -o 'State hash: [0-9a-f]*' "$work/$name.${b//[ :]/_}.log" | cut -d' ' -f3)")
    extra="$(grep -o '[0-9]* broken' "$work/$name.${b//[ :]/_}.log" | head -1)"
  done
  local same=yes
  for x in "${h[@]}"; do [[ "$x" == "${h[0]}" ]] || same=NO; done
  printf '%-26s cpu1=%s cpu2=%s cpu16=%s gpu=%s identical=%s (%s)\n' "$name" "${h[@]}" "$same" "$extra" | tee -a "$table"
}
"$bin/gencase" "$root/cases/dambreak3d/DamBreak3D_Def.xml" "$work/db3d" >/dev/null
"$bin/gencase" "$root/cases/hanging_beam/HangingBeam_Def.xml" "$work/beam" -dp:0.01 >/dev/null
"$bin/gencase" "$root/cases/hydrostatic_plate/HydrostaticPlate_Def.xml" "$work/plate" -dp:0.025 >/dev/null
"$bin/gencase" "$root/cases/dambreak_plate3d/DamBreakPlate3D_Def.xml" "$work/dbplate" >/dev/null
"$bin/gencase" "$root/cases/breaking_bar/BreakingBar_Def.xml" "$work/bar" >/dev/null
"$bin/gencase" "$root/cases/cantilever3d_tipload/CantileverTipLoad3D_Def.xml" "$work/tip2" -dp:0.002 >/dev/null
parity db3d_fluid_regression "$work/db3d" 40 -symplectic -wendland -viscoart:0.1 -ddt:3 -cellmode:h
parity beam3d_solid_only "$work/beam" 3000
parity tipload3d_pointloads "$work/tip2" 3000
parity plate2d_midpoint "$work/plate" 400
parity plate2d_seedscheme "$work/plate" 400 -vcpmcoupling:1
parity bar_breaking "$work/bar" 4000
parity dbplate3d_breaking "$work/dbplate" 1800
# DualSPHysics' own flexstruc example (Liao 2015 gate + plate; Verlet, laminar+SPS, Molteni DDT,
# DtAllParticles 1, a gate moved by a data file): the seed's coupling scheme under Verlet.
"$bin/gencase" "$root/build-dev/shared-cases/flexstruc/CaseDambreak2D_FSI_Def.xml" "$work/liao2d" >/dev/null
parity liao2d_dualsphysics_case "$work/liao2d" 600
# The per-pass GPU path on a small solid (the block path is the default there): same bits.
rm -rf "$work/o_pp"/{Run.out,run.json,parts.xdmf,ledger.csv,data,vtk,gauges}  # an earlier run (seaspring refuses to mix)
SEASPRING_SOLID_BLOCK_MAX=0 "$bin/seaspring" -gpu -nsteps:400 -sv:none -progress:0 "$work/plate" "$work/o_pp" >"$work/plate_perpass.log" 2>&1
echo "plate2d_midpoint gpu per-pass path: $(grep -o 'State hash: [0-9a-f]*' "$work/plate_perpass.log")" | tee -a "$table"
echo "== parity (db3d fluid-only, cells of h: c831d1020e07417e since 2026-11-22) =="; cat "$table"

if [[ -n "${SEASPRING_PARITY_ONLY:-}" ]]; then
  (cd "$work" && tar czf "$out/logs.tgz" ./*.log) 2>/dev/null
  exit 0
fi

# Long GPU runs: Antoci gate 2D and 3D (free-end marker against the experiment), and the
# tip-loaded cantilever of seed 000 §3.2 at dp 1 mm (point A). Markers need h5py (.whl).
have_h5py=0
if ls "$root"/.whl/h5py-*.whl >/dev/null 2>&1 &&
   python3 -m pip install -q --no-index --no-deps --no-compile --no-cache-dir --target /tmp/site "$root"/.whl/*.whl; then
  have_h5py=1
fi
marker() { [[ $have_h5py == 1 ]] && PYTHONPATH=/tmp/site python3 "$root/tools/solid_marker.py" "$@"; }
long_run() {  # name def-xml extra-args...
  local name=$1 def=$2; shift 2
  "$bin/gencase" "$def" "$work/$name" >/dev/null
  rm -rf "$work/o_$name"/{Run.out,run.json,parts.xdmf,ledger.csv,data,vtk,gauges}  # an earlier run (seaspring refuses to mix)
  /usr/bin/time -f "$name wall %e s" "$bin/seaspring" -gpu -progress:0 "$@" "$work/$name" "$work/o_$name" >"$work/$name.log" 2>&1
  { echo "== $name"; grep -E "Particles:|Finished|Solids|hash|wall" "$work/$name.log"; } | tee -a "$out/long_runs.txt"
}
: >"$out/long_runs.txt"
ref="$root/build-dev/shared-cases"
long_run antoci2d "$root/cases/antoci_gate2d/AntociGate2D_Def.xml"
marker "$work/o_antoci2d" --point 0.102,0,0.003 --csv "$out/antoci2d_tip.csv" --window 0.36 \
  --ref-x "$ref/exp_tip_dx_antoci2007_digitized_A.csv" --ref-z "$ref/exp_tip_dy_antoci2007_digitized_A.csv" 2>&1 | tee -a "$out/long_runs.txt"
long_run antoci3d "$root/cases/antoci_gate2d/AntociGate3D_Def.xml" -tout:0.01
marker "$work/o_antoci3d" --point 0.102,0.01,0.003 --k 4 --csv "$out/antoci3d_tip.csv" --window 0.36 \
  --ref-x "$ref/exp_tip_dx_antoci2007_digitized_A.csv" --ref-z "$ref/exp_tip_dy_antoci2007_digitized_A.csv" 2>&1 | tee -a "$out/long_runs.txt"
long_run tipload3d "$root/cases/cantilever3d_tipload/CantileverTipLoad3D_Def.xml"
marker "$work/o_tipload3d" --point 0.1,0.0045,0.0045 --k 4 --csv "$out/tipload3d_A.csv" 2>&1 | tee -a "$out/long_runs.txt"
(cd "$work" && tar czf "$out/logs.tgz" ./*.log) 2>/dev/null

SEASPRING_BIN="$bin" BENCH_DIR="$work/bench" "$root/tools/bench_solid.sh" -gpu "$@" 2>&1 | tee "$out/bench_solid.txt"
cp "$work/bench/bench_solid.csv" "$out/" 2>/dev/null
