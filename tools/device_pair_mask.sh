#!/usr/bin/env bash
# SeaSpring — MIT licence.
# Runs ON the GPU machine (device tool) with a build carried: the fluid pair loop that tests a
# row's candidates into a bit mask first (SEASPRING_PAIR_MASK=1, physics/fluid_interaction.h,
# fluidPairsInRowMasked) against the direct loop, one build, runs alternated (ROUNDS rounds); every pair of runs must
# give the same state hash. Cases: SPHERIC Test 2 at 4.36 M (artificial viscosity, and
# laminar+SPS; SPHERIC_STEPS steps from the lattice), the 3D sluice gate at SLUICE_DP from
# t = 0 to T_CK (with a restart file there) and then T_CK..T_END from it (after the impacts:
# a disordered flow), FlexStruc Liao 3D's first 0.02 s, the Antoci gate 2D (0.05 s).
# Env: SS_BIN (default build-dev/bin), ROUNDS (2), SPHERIC_STEPS (200), SLUICE_DP (0.003),
#      T_CK (0.4), T_END (0.45), OUT (where pair_mask.txt goes).
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
[[ -d $root/build-dev/lib ]] && export LD_LIBRARY_PATH="$root/build-dev/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
b=${SS_BIN:-$root/build-dev/bin}; rounds=${ROUNDS:-2}; steps=${SPHERIC_STEPS:-200}
dp=${SLUICE_DP:-0.003}; tck=${T_CK:-0.4}; tend=${T_END:-0.45}
shared=${SHARED_CASES:-$root/build-dev/shared/dualsphysics-cases}
out=${OUT:-/tmp/seaspring_out}; w=/tmp/seaspring_pair_mask
mkdir -p "$out" "$w"
table=$out/pair_mask.txt
: >"$table"
say() { echo "$*" | tee -a "$table"; }
command -v nvidia-smi >/dev/null && nvidia-smi --query-gpu=name --format=csv,noheader | tee -a "$table"
gen() {  # name xml args...
  local n=$1 x=$2; shift 2
  [[ -f $w/$n.h5 ]] || "$b/gencase" "$x" "$w/$n" "$@" >"$w/gencase_$n.log" 2>&1 || { tail -3 "$w/gencase_$n.log"; return 1; }
}
row() {  # mask(0|1) label case outdir args...
  local q=$1 label=$2 c=$3 o=$4; shift 4
  if ! SEASPRING_PAIR_MASK=$q "$b/seaspring" -overwrite -gpu -sv:none -progress:0 "$@" "$w/$c" "$w/$o" >"$w/run.log" 2>&1; then
    say "$label mask=$q: FAILED ($(grep -v '^\s*$' "$w/run.log" | tail -n 1))"
    return
  fi
  /usr/bin/python3 - "$w/$o/run.json" "$label" "$q" <<'PY' | tee -a "$table"
import json, sys
r = json.load(open(sys.argv[1]))
n = r.get("steps_this_run", r["steps"])
print(f"{sys.argv[2]:<34} {'mask  ' if sys.argv[3] == '1' else 'direct'} np={r['particles']['total']:>8} steps={n:>6} "
      f"loop {r['loop_time_s']:8.3f} s  {1e3 * r['loop_time_s'] / max(n, 1):8.4f} ms/step  "
      f"{r['ns_per_particle_step']:7.3f} ns/p/step  hash {r['state_hash']}")
PY
}
pair() {  # label case args...: direct then mask, ROUNDS times
  local label=$1 c=$2; shift 2
  for ((r = 1; r <= rounds; ++r)); do
    row 0 "$label" "$c" "o_$c" "$@"
    row 1 "$label" "$c" "o_$c" "$@"
  done
}

if gen spheric "$shared/Spheric2Dam_01M.xml" -dp:0.006; then
  pair "SPHERIC 4.36 M, $steps steps" spheric -symplectic -wendland -ddt:3 -nsteps:"$steps"
  pair "SPHERIC 4.36 M laminar+SPS" spheric -symplectic -wendland -ddt:3 -nsteps:"$steps" -viscolamsps:1e-6
fi
if gen sluice "$root/cases/sluice_gate/SluiceGate3D_Def.xml" -dp:"$dp"; then
  row 0 "sluice dp $dp, 0..$tck s" sluice o_ck -tmax:"$tck" -checkpoint:"$tck"
  ck=$(grep -o "checkpoint t=[0-9.e+-]* s, step [0-9]*" "$w/run.log" | tail -n 1 | grep -o "[0-9]*$")
  cp "$w/o_ck/restart.h5" "$w/restart.h5" 2>/dev/null
  row 1 "sluice dp $dp, 0..$tck s" sluice o_sl -tmax:"$tck"
  [[ -n ${ck:-} ]] && pair "sluice dp $dp, $tck..$tend s (restart)" sluice -tmax:"$tend" -restart:"$w/restart.h5"
fi
if gen liao3d "$shared/flexstruc/CaseDambreak3D_FSI_Def.xml"; then
  pair "FlexStruc Liao 3D, 0.02 s" liao3d -tmax:0.02
fi
if gen antoci "$root/cases/antoci_gate2d/AntociGate2D_Def.xml"; then
  pair "Antoci gate 2D, 0.05 s" antoci -tmax:0.05
fi
say "== done"
