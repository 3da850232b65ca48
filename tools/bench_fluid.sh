#!/usr/bin/env bash
# Fluid benchmark: SPHERIC Test 2 dam break with obstacle (DualSPHysics' own GPU benchmark case,
# ../shared/dualsphysics-cases/Spheric2Dam_01M.xml) re-generated with -dp for about 1 M, 4.4 M
# and 13 M particles; first 0.02 s; symplectic + Wendland + DDT 3 + artificial viscosity, DBC,
# no output. Prints ns per particle per step next to DualSPHysics 5.4's numbers (H200) and
# writes bench_fluid.csv in the work folder.
#
# Usage: tools/bench_fluid.sh [-gpu|-cpu -threads:N] [-cellmode:M] [DP ...]   (default DPs: 0.01 0.006 0.004)
# Env: SEASPRING_BIN (folder with seaspring and gencase; default build/bin),
#      BENCH_DIR (work folder; default /tmp/seaspring_bench), BENCH_CASE (case XML),
#      BENCH_TMAX (default 0.02).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bin="${SEASPRING_BIN:-$root/build/bin}"
work="${BENCH_DIR:-/tmp/seaspring_bench}"
case_xml="${BENCH_CASE:-$root/../shared/dualsphysics-cases/Spheric2Dam_01M.xml}"
tmax="${BENCH_TMAX:-0.02}"
backend=(-gpu)
dps=()
for a in "$@"; do
  case "$a" in
    -gpu|-gpu:*|-cpu|-threads:*|-cellmode:*) [[ "$a" == -cpu || "$a" == -gpu* ]] && backend=("$a") || backend+=("$a") ;;
    *) dps+=("$a") ;;
  esac
done
[[ ${#dps[@]} -eq 0 ]] && dps=(0.01 0.006 0.004)
mkdir -p "$work"
csv="$work/bench_fluid.csv"
echo "dp,particles,steps,loop_s,steps_per_s,ns_per_particle_step,device,backend,threads,state_hash" >"$csv"
for dp in "${dps[@]}"; do
  name="spheric_dp$dp"
  if [[ ! -f "$work/$name.h5" ]]; then
    "$bin/gencase" "$case_xml" "$work/$name" -dp:"$dp" >"$work/$name.gencase.log"
  fi
  "$bin/seaspring" -overwrite "${backend[@]}" -symplectic -wendland -ddt:3 -tmax:"$tmax" -sv:none -progress:0 \
    "$work/$name" "$work/out_$name" >"$work/$name.run.log" 2>&1 || { cat "$work/$name.run.log"; exit 1; }
  /usr/bin/env python3 - "$work/out_$name/run.json" "$dp" >>"$csv" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
print(f"{sys.argv[2]},{r['particles']['total']},{r['steps']},{r['loop_time_s']:.4f},"
      f"{r['steps']/r['loop_time_s']:.2f},{r['ns_per_particle_step']:.3f},\"{r['device']}\","
      f"{r['backend']},{r['threads']},{r['state_hash']}")
PY
done
echo "SeaSpring fluid benchmark (SPHERIC Test 2, first $tmax s; symplectic, Wendland, DDT 3, artificial viscosity, DBC):"
/usr/bin/env python3 - "$csv" <<'PY'
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
w = [max(len(r[i]) for r in rows) for i in range(len(rows[0]))]
for r in rows:
    print("  ".join(c.ljust(w[i]) for i, c in enumerate(r)))
PY
echo "DualSPHysics 5.4 on an H200 (same inputs): 1.12 M 4.58 ns, 4.36 M 4.48 ns, 13.29 M 4.74 ns per particle per step."
echo "DualSPHysics 5.4 CPU, 2 threads, Spheric2Dam_100K on the 2-core dev machine: 3.0 us per particle per step."
