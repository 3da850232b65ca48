#!/usr/bin/env bash
# VCPM solid benchmark: the hanging beam of seed paper 000 §3.1 (cases/hanging_beam, 3D,
# solid only, 18 bonds per interior particle, damping on) re-generated with -dp:
# 0.005 m = 48,000, 0.0025 m = 384,000 and 0.00125 m = 3,072,000 solid particles; a fixed
# number of solid sub-steps, no output. Prints ns per solid particle per sub-step (one
# sub-step = two bond-force evaluations, as in the seed's Tables 1-2) and writes
# bench_solid.csv in the work folder.
#
# Usage: tools/bench_solid.sh [-gpu|-cpu -threads:N] [DP ...]   (default DPs: 0.005 0.0025 0.00125)
# Env: SEASPRING_BIN (folder with seaspring and gencase; default build/bin),
#      BENCH_DIR (work folder; default /tmp/seaspring_bench_solid), BENCH_STEPS (default 2000).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bin="${SEASPRING_BIN:-$root/build/bin}"
work="${BENCH_DIR:-/tmp/seaspring_bench_solid}"
case_xml="$root/cases/hanging_beam/HangingBeam_Def.xml"
nsteps="${BENCH_STEPS:-2000}"
backend=(-gpu)
dps=()
for a in "$@"; do
  case "$a" in
    -gpu|-gpu:*|-cpu|-threads:*) [[ "$a" == -cpu || "$a" == -gpu* ]] && backend=("$a") || backend+=("$a") ;;
    *) dps+=("$a") ;;
  esac
done
[[ ${#dps[@]} -eq 0 ]] && dps=(0.005 0.0025 0.00125)
mkdir -p "$work"
csv="$work/bench_solid.csv"
echo "dp,solid_particles,substeps,loop_s,ns_per_solid_particle_substep,device,backend,threads,state_hash" >"$csv"
for dp in "${dps[@]}"; do
  name="beam_dp$dp"
  [[ -f "$work/$name.h5" ]] || "$bin/gencase" "$case_xml" "$work/$name" -dp:"$dp" >"$work/$name.gencase.log"
  "$bin/seaspring" -overwrite "${backend[@]}" -nsteps:"$nsteps" -sv:none -progress:0 \
    "$work/$name" "$work/out_$name" >"$work/$name.run.log" 2>&1 || { cat "$work/$name.run.log"; exit 1; }
  /usr/bin/env python3 - "$work/out_$name/run.json" "$dp" >>"$csv" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
s = r['solids']
print(f"{sys.argv[2]},{s['particles']},{s['substeps']},{r['loop_time_s']:.4f},"
      f"{r['ns_per_particle_step']:.3f},\"{r['device']}\",{r['backend']},{r['threads']},{r['state_hash']}")
PY
done
echo "SeaSpring VCPM benchmark (hanging beam, 3D simple cubic, $nsteps sub-steps, damping on):"
/usr/bin/env python3 - "$csv" <<'PY'
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
w = [max(len(r[i]) for r in rows) for i in range(len(rows[0]))]
for r in rows:
    print("  ".join(c.ljust(w[i]) for i, c in enumerate(r)))
PY
echo "Seed paper 000 (Quadro RTX 8000, same beam): 48,000 particles 16.9 ns, 384,000 particles 18.5 ns per particle per step."
echo "Bar of issue 4: <= 5 ns per solid particle per sub-step at >= 100,000 particles on an H200."
