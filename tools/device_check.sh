#!/usr/bin/env bash
# Runs ON the GPU machine (device tool), from the repository root, with build-dev carried
# (tools/device_build.sh makes it). Checks CPU/GPU bit-identity on small cases of every
# physics family, then runs the fluid benchmark. Writes logs and a table under $OUT.
# Usage: tools/device_check.sh [bench DPs...]
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
  for b in "-cpu -threads:1" "-cpu -threads:16" "-gpu"; do
    # shellcheck disable=SC2086
    "$bin/seaspring" $b -nsteps:"$n" -sv:none -progress:0 "$@" "$kase" "$work/o_$name" >"$work/$name.log" 2>&1 ||
      { echo "FAILED $name $b"; tail -5 "$work/$name.log"; }
    h+=("$(grep -o 'State hash: [0-9a-f]*' "$work/$name.log" | cut -d' ' -f3)")
  done
  local same=yes
  for x in "${h[@]}"; do [[ "$x" == "${h[0]}" ]] || same=NO; done
  printf '%-28s cpu1=%s cpu16=%s gpu=%s identical=%s\n' "$name" "${h[@]}" "$same" | tee -a "$table"
}
"$bin/gencase" "$root/cases/dambreak3d/DamBreak3D_Def.xml" "$work/db3d" >/dev/null
"$bin/gencase" "$shared/CaseDambreakVal2D_Def.xml" "$work/val2d" -dp:0.02 >/dev/null
parity db3d_sym_wend_art_ddt3 "$work/db3d" 40 -symplectic -wendland -viscoart:0.1 -ddt:3
parity db3d_verlet_cubic_lam_ddt1 "$work/db3d" 40 -verlet -cubic -viscolam:1e-6 -ddt:1
parity db3d_sym_wend_sps_ddt2 "$work/db3d" 40 -symplectic -wendland -viscolamsps:1e-6 -ddt:2
parity db3d_cells2h "$work/db3d" 40 -cellmode:full
parity val2d_sym_wend_art_ddt3 "$work/val2d" 300 -symplectic -ddt:3
parity val2d_verlet_cubic_sps_ddt0 "$work/val2d" 300 -verlet -cubic -viscolamsps:1e-6 -ddt:0
cp "$work"/*.log "$out/" 2>/dev/null
echo "== parity =="; cat "$table"
SEASPRING_BIN="$bin" BENCH_DIR="$work/bench" BENCH_CASE="$shared/Spheric2Dam_01M.xml" \
  "$root/tools/bench_fluid.sh" -gpu "$@" 2>&1 | tee "$out/bench.txt"
cp "$work/bench/bench_fluid.csv" "$out/" 2>/dev/null
