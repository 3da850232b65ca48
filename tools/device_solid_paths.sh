#!/usr/bin/env bash
# Runs ON the GPU machine (device tool): times the two GPU paths of the VCPM sub-cycle (one
# single-block kernel per sub-cycle vs one kernel per pass) on solids of 400 to 48,000
# particles, by moving SEASPRING_SOLID_BLOCK_MAX; both must give the same state hash.
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export LD_LIBRARY_PATH="$root/build-dev/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
bin="$root/build-dev/bin"
out="${OUT:-/tmp/seaspring_out}"
work=/tmp/seaspring_paths
mkdir -p "$out" "$work"
"$bin/gencase" "$root/cases/antoci_gate2d/AntociGate2D_Def.xml" "$work/antoci" >/dev/null
"$bin/gencase" "$root/cases/cantilever3d_tipload/CantileverTipLoad3D_Def.xml" "$work/tip2" -dp:0.002 >/dev/null
"$bin/gencase" "$root/cases/cantilever3d_tipload/CantileverTipLoad3D_Def.xml" "$work/tip1" >/dev/null
"$bin/gencase" "$root/cases/hanging_beam/HangingBeam_Def.xml" "$work/beam5" -dp:0.005 >/dev/null
run() {  # label case nsteps blockmax
  SEASPRING_SOLID_BLOCK_MAX=$4 "$bin/seaspring" -overwrite -gpu -nsteps:"$3" -sv:none -progress:0 "$work/$2" "$work/o" >"$work/$1.log" 2>&1
  printf '%-34s %s  %s  %s\n' "$1" "$(grep -o 'Solids: [0-9]* particles' "$work/$1.log")" \
    "$(grep -o 'in [0-9.]* s wall (loop [0-9.]* s)' "$work/$1.log")" "$(grep -o 'State hash: [0-9a-f]*' "$work/$1.log")" |
    tee -a "$out/paths.txt"
}
nvidia-smi --query-gpu=name --format=csv,noheader | tee "$out/paths.txt"
run antoci2d_3000steps_block antoci 3000 1000000000
run antoci2d_3000steps_perpass antoci 3000 0
run tip_dp2mm_20000sub_block tip2 20000 1000000000
run tip_dp2mm_20000sub_perpass tip2 20000 0
run tip_dp1mm_20000sub_block tip1 20000 1000000000
run tip_dp1mm_20000sub_perpass tip1 20000 0
run beam_dp5mm_2000sub_block beam5 2000 1000000000
run beam_dp5mm_2000sub_perpass beam5 2000 0
