#!/usr/bin/env bash
# Runs ON the GPU machine (device tool), from the repository root, with build-dev carried
# (tools/device_build.sh makes it). Checks CPU/GPU bit-identity on small cases of every
# physics family, then runs the fluid benchmark. Writes logs and a table under $OUT.
# Usage: tools/device_check.sh [bench DPs...]
# Env: BASE_BIN=folder with a baseline seaspring + gencase: the benchmark then runs the
#      baseline and this build alternately (BENCH_REPEAT rounds, default 2) and prints both;
#      PARITY_ONLY=1: the parity checks only.
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export LD_LIBRARY_PATH="$root/build-dev/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
bin="$root/build-dev/bin"
out="${OUT:-/tmp/seaspring_out}"
work=/tmp/seaspring_dev
mkdir -p "$out" "$work"
nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader | tee "$out/gpu.txt"
shared="$root/build-dev/shared-cases"

table="$out/parity.txt"
: >"$table"
parity() {  # name case_path nsteps extra-args...
  local name=$1 kase=$2 n=$3; shift 3
  local h=()
  for b in "-cpu -threads:1" "-cpu -threads:2" "-cpu -threads:16" "-gpu"; do
    rm -rf "$work/o_$name"/{Run.out,run.json,parts.xdmf,ledger.csv,data,vtk,gauges}  # an earlier run (seaspring refuses to mix)
    # shellcheck disable=SC2086
    "$bin/seaspring" $b -nsteps:"$n" -sv:none -progress:0 "$@" "$kase" "$work/o_$name" >"$work/$name.log" 2>&1 ||
      { echo "FAILED $name $b"; tail -5 "$work/$name.log"; }
    h+=("$(grep -o 'State hash: [0-9a-f]*' "$work/$name.log" | cut -d' ' -f3)")
  done
  local same=yes
  for x in "${h[@]}"; do [[ "$x" == "${h[0]}" ]] || same=NO; done
  printf '%-28s cpu1=%s cpu2=%s cpu16=%s gpu=%s identical=%s\n' "$name" "${h[@]}" "$same" | tee -a "$table"
}
"$bin/gencase" "$root/cases/dambreak3d/DamBreak3D_Def.xml" "$work/db3d" >/dev/null
"$bin/gencase" "$shared/CaseDambreakVal2D_Def.xml" "$work/val2d" -dp:0.02 >/dev/null
parity db3d_sym_wend_art_ddt3 "$work/db3d" 40 -symplectic -wendland -viscoart:0.1 -ddt:3
parity db3d_verlet_cubic_lam_ddt1 "$work/db3d" 40 -verlet -cubic -viscolam:1e-6 -ddt:1
parity db3d_sym_wend_sps_ddt2 "$work/db3d" 40 -symplectic -wendland -viscolamsps:1e-6 -ddt:2
parity db3d_cells2h "$work/db3d" 40 -cellmode:full
parity db3d_cells_h "$work/db3d" 40 -cellmode:h
parity db3d_cells_third "$work/db3d" 40 -cellmode:third
parity val2d_sym_wend_art_ddt3 "$work/val2d" 300 -symplectic -ddt:3
parity val2d_verlet_cubic_sps_ddt0 "$work/val2d" 300 -verlet -cubic -viscolamsps:1e-6 -ddt:0
cp "$work"/*.log "$out/" 2>/dev/null
echo "== parity =="; cat "$table"
[[ -n "${PARITY_ONLY:-}" ]] && exit 0
bench() {  # label bin-folder args...
  local label=$1 b=$2; shift 2
  SEASPRING_BIN="$b" BENCH_DIR="$work/bench" BENCH_CASE="$shared/Spheric2Dam_01M.xml" \
    "$root/tools/bench_fluid.sh" -gpu "$@" >"$work/bench_run.txt" 2>&1 || cat "$work/bench_run.txt"
  tail -n +2 "$work/bench/bench_fluid.csv" | sed "s/^/$label,/" >>"$out/bench_all.csv"
}
echo "build,dp,particles,steps,loop_s,steps_per_s,ns_per_particle_step,device,backend,threads,state_hash" >"$out/bench_all.csv"
for ((round = 0; round < ${BENCH_REPEAT:-2}; ++round)); do
  [[ -n "${BASE_BIN:-}" ]] && bench base "$BASE_BIN" "$@"
  bench new "$bin" "$@"
done
echo "== bench (ns per particle per step) =="
column -s, -t "$out/bench_all.csv" | cut -c1-150
