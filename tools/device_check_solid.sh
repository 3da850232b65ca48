#!/usr/bin/env bash
# Runs ON the GPU machine (device tool), from the repository root, with build-dev carried
# (tools/device_build.sh makes it). VCPM solids: CPU/GPU bit-identity on a solid-only 3D case,
# a coupled 2D case and a coupled 3D case with breakage; a fluid-only regression hash; then the
# solid benchmark. Writes logs and a table under $OUT.
# Usage: tools/device_check_solid.sh [bench DPs...]
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export LD_LIBRARY_PATH="$root/build-dev/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
bin="$root/build-dev/bin"
out="${OUT:-/tmp/seaspring_out}"
work=/tmp/seaspring_dev_solid
mkdir -p "$out" "$work"
nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader | tee "$out/gpu.txt"

table="$out/parity_solid.txt"
: >"$table"
parity() {  # name case_path nsteps extra-args...
  local name=$1 kase=$2 n=$3; shift 3
  local h=() extra=""
  for b in "-cpu -threads:1" "-cpu -threads:16" "-gpu"; do
    # shellcheck disable=SC2086
    "$bin/seaspring" $b -nsteps:"$n" -sv:none -progress:0 "$@" "$kase" "$work/o_$name" >"$work/$name.${b//[ :]/_}.log" 2>&1 ||
      { echo "FAILED $name $b"; tail -5 "$work/$name.${b//[ :]/_}.log"; }
    h+=("$(grep -o 'State hash: [0-9a-f]*' "$work/$name.${b//[ :]/_}.log" | cut -d' ' -f3)")
    extra="$(grep -o '[0-9]* broken' "$work/$name.${b//[ :]/_}.log" | head -1)"
  done
  local same=yes
  for x in "${h[@]}"; do [[ "$x" == "${h[0]}" ]] || same=NO; done
  printf '%-26s cpu1=%s cpu16=%s gpu=%s identical=%s (%s)\n' "$name" "${h[@]}" "$same" "$extra" | tee -a "$table"
}
"$bin/gencase" "$root/cases/dambreak3d/DamBreak3D_Def.xml" "$work/db3d" >/dev/null
"$bin/gencase" "$root/cases/hanging_beam/HangingBeam_Def.xml" "$work/beam" -dp:0.01 >/dev/null
"$bin/gencase" "$root/cases/hydrostatic_plate/HydrostaticPlate_Def.xml" "$work/plate" -dp:0.025 >/dev/null
"$bin/gencase" "$root/cases/dambreak_plate3d/DamBreakPlate3D_Def.xml" "$work/dbplate" >/dev/null
"$bin/gencase" "$root/cases/breaking_bar/"*_Def.xml "$work/bar" >/dev/null 2>&1 || echo "no breaking_bar case"
parity db3d_fluid_regression "$work/db3d" 40 -symplectic -wendland -viscoart:0.1 -ddt:3
parity beam3d_solid_only "$work/beam" 3000
parity plate2d_coupled "$work/plate" 400
[[ -f "$work/bar.xml" ]] && parity bar_breaking "$work/bar" 4000
parity dbplate3d_breaking "$work/dbplate" 1800
(cd "$work" && tar czf "$out/logs.tgz" ./*.log) 2>/dev/null
echo "== parity (db3d fluid-only hash of the previous release: c831d1020e07417e) =="; cat "$table"
# Antoci 2007 gate (2D, dp 1 mm) to 0.4 s on the GPU; free-end marker vs the experiment
# (needs h5py: carry .whl with an h5py wheel for Python 3.12).
"$bin/gencase" "$root/cases/antoci_gate2d/AntociGate2D_Def.xml" "$work/antoci" >/dev/null
/usr/bin/time -f "antoci wall %e s" "$bin/seaspring" -gpu -progress:0 "$work/antoci" "$work/o_antoci" >"$work/antoci.log" 2>&1
grep -E "Finished|Solids|hash|antoci wall" "$work/antoci.log" | tee "$out/antoci.txt"
cp "$work/o_antoci/ledger.csv" "$out/antoci_ledger.csv" 2>/dev/null
if ls "$root"/.whl/h5py-*.whl >/dev/null 2>&1; then
  python3 -m pip install -q --no-index --no-deps --no-compile --no-cache-dir --target /tmp/site "$root"/.whl/*.whl &&
    PYTHONPATH=/tmp/site python3 "$root/tools/solid_marker.py" "$work/o_antoci" --point 0.102,0,0.003 \
      --csv "$out/antoci_tip.csv" --window 0.36 \
      --ref-x "$root/build-dev/shared-cases/exp_tip_dx_antoci2007_digitized_A.csv" \
      --ref-z "$root/build-dev/shared-cases/exp_tip_dy_antoci2007_digitized_A.csv" 2>&1 | tee -a "$out/antoci.txt"
fi
SEASPRING_BIN="$bin" BENCH_DIR="$work/bench" "$root/tools/bench_solid.sh" -gpu "$@" 2>&1 | tee "$out/bench_solid.txt"
cp "$work/bench/bench_solid.csv" "$out/" 2>/dev/null
