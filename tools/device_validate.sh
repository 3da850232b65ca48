#!/usr/bin/env bash
# Runs ON the GPU machine (device tool), from the repository root, with build-dev carried
# (tools/device_build.sh makes it, and copies ../shared's reference data into
# build-dev/shared). Steps, each optional:
#   parity      gauge CSVs and state hashes of small gauge cases: cpu -threads:1, 2, 16, -gpu
#   validate    tools/validate.py, case by case, over VALIDATE_CASES (VALIDATE_ARGS, default
#               "--resolution all"), GPU; the report is tarred into $OUT/validation.tgz
#   stability   the hard cases of STABILITY ("name:xml:dp:tmax ..."), GPU, one table
# Usage: SEASPRING_COMMIT=<hash> tools/device_validate.sh parity validate stability
# (the commit of the tree: the copy's .git on the device may be stale; the report names it)
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export LD_LIBRARY_PATH="$root/build-dev/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export SEASPRING_SHARED="$root/build-dev/shared"
bin="$root/build-dev/bin"
out="${OUT:-/tmp/seaspring_out}"
work=/tmp/seaspring_val
mkdir -p "$out" "$work"
nvidia-smi --query-gpu=name,memory.total --format=csv,noheader | tee "$out/gpu.txt"

step_parity() {
  local table="$out/gauge_parity.txt"
  : >"$table"
  "$bin/gencase" "$SEASPRING_SHARED/dualsphysics-cases/CaseDambreakVal2D_Def.xml" "$work/val2d" -dp:0.02 >/dev/null
  "$bin/gencase" "$root/cases/antoci_gate2d/AntociGate2D_Def.xml" "$work/antoci" -dp:0.002 >/dev/null
  "$bin/gencase" "$root/tests/data/gauges/StillTank_Def.xml" "$work/tank" >/dev/null
  local specs=("val2d:600" "antoci:400" "tank:300")
  if [[ -f "$root/cases/dualsphysics_dambreak3d/CaseDambreak_Def.xml" ]]; then
    "$bin/gencase" "$root/cases/dualsphysics_dambreak3d/CaseDambreak_Def.xml" "$work/ds3d" -dp:0.017 >/dev/null && specs+=("ds3d:200")
  fi
  for spec in "${specs[@]}"; do
    local name=${spec%%:*} n=${spec##*:} ref="" same=yes hashes=""
    for b in "-cpu -threads:1" "-cpu -threads:2" "-cpu -threads:16" "-gpu"; do
      local o="$work/o_${name}_${b//[^a-z0-9]/}"
      rm -rf "$o"/{Run.out,run.json,parts.xdmf,ledger.csv,data,vtk,gauges}  # an earlier run (seaspring refuses to mix)
      # shellcheck disable=SC2086
      "$bin/seaspring" $b -nsteps:"$n" -sv:none -progress:0 "$work/$name" "$o" >"$o.log" 2>&1 || echo "FAILED $name $b"
      hashes+=" $(grep -o 'State hash: [0-9a-f]*' "$o.log" | cut -d' ' -f3)"
      local sum
      sum=$(cat "$o"/gauges/*.csv | md5sum | cut -c1-12)
      [[ -z "$ref" ]] && ref=$sum
      [[ "$sum" == "$ref" ]] || same=NO
      hashes+="/$sum($(ls "$o"/gauges | wc -l) files)"
    done
    printf '%-8s %s gauges-identical=%s\n' "$name" "$hashes" "$same" | tee -a "$table"
  done
}

step_validate() {  # case by case, the report tarred after each (a killed call keeps what ran)
  for c in ${VALIDATE_CASES:-}; do
    # shellcheck disable=SC2086
    python3 "$root/tools/validate.py" --cases "$c" ${VALIDATE_ARGS:---resolution all} --backend gpu --bin "$bin" \
      --out "$work/runs" --report "$work/report" >>"$out/validate.log" 2>&1
    tail -3 "$out/validate.log"
    tar czf "$out/validation.tgz" -C "$work" report
  done
}

step_stability() {
  local table="$out/stability.txt"
  printf '%-22s %10s %9s %8s %9s %8s %9s %s\n' case particles tmax reached steps wall_s broken note | tee "$table"
  for spec in ${STABILITY:-}; do
    IFS=: read -r name xml dp tmax <<<"$spec"
    local d="$work/stab_$name"
    mkdir -p "$d"
    "$bin/gencase" "$root/$xml" "$d/case" -dp:"$dp" >"$d/gencase.log" 2>&1 || { echo "$name: gencase failed"; tail -3 "$d/gencase.log"; continue; }
    rm -rf "$d"/{Run.out,run.json,parts.xdmf,ledger.csv,data,vtk,gauges}  # an earlier run (seaspring refuses to mix)
    timeout "${STAB_TIMEOUT:-400}" "$bin/seaspring" -gpu -tmax:"$tmax" -sv:h5 -progress:30 "$d/case" "$d" >"$d/run.log" 2>&1
    local rc=$?
    python3 - "$d" "$name" "$tmax" "$rc" <<'EOF' | tee -a "$table"
import glob, json, os, sys
import numpy as np
d, name, tmax, rc = sys.argv[1], sys.argv[2], float(sys.argv[3]), int(sys.argv[4])
try:
    r = json.load(open(os.path.join(d, "run.json")))
except Exception:
    print(f"{name:22s} run.json missing (exit {rc})"); sys.exit()
s = r.get("solids", {})
note = r.get("stop_reason", "") + (f"; exit {rc}" if rc else "")
ex = r.get("excluded", {})
note += f"; fluid excluded {sum(ex.values())}; {r.get('ns_per_particle_step', 0):.2f} ns/p/step"
try:  # the solid at the last output: every particle finite, largest displacement
    import h5py
    parts = sorted(glob.glob(os.path.join(d, "data", "part_*.h5")))
    first, last = h5py.File(parts[0], "r"), h5py.File(parts[-1], "r")
    sol = last["type"][:] == 2
    p1, p0 = last["pos"][:][sol], first["pos"][:][sol]
    fin = np.isfinite(p1).all(axis=1)
    note += f"; solid {sol.sum()} particles, {int((~fin).sum())} not finite, max |disp| {np.linalg.norm(p1[fin] - p0[fin], axis=1).max():.4g} m"
except Exception as e:
    note += f"; part files: {e}"
try:  # the energy ledger: largest solid energies over the run, work of the fluid force
    L = np.genfromtxt(os.path.join(d, "ledger.csv"), delimiter=";", names=True)
    allfin = all(np.isfinite(L[n]).all() for n in L.dtype.names)
    note += (f"; ledger rows {len(L)}, max KE {L['solid_kinetic'].max():.4g} J, max elastic {L['solid_elastic'].max():.4g} J, "
             f"final work {L['work'][-1]:.4g} J, all finite {allfin}")
except Exception as e:
    note += f"; ledger: {e}"
print(f"{name:22s} {r['particles']['total']:>10} {tmax:9.3f} {r.get('physical_time_s', 0):8.4f} "
      f"{r.get('steps', 0):9d} {r.get('wall_time_s', 0):8.1f} {s.get('broken_bonds', 0):>9} {note}")
EOF
    tail -4 "$d/run.log" >"$out/stab_$name.log"
    [[ -f "$d/ledger.csv" ]] && tail -3 "$d/ledger.csv" >>"$out/stab_$name.log"
  done
  # gauges, ledgers, summaries and logs of every run, plus the part file at STAB_PICTURE_PART
  # (e.g. "sluice3d:0008", for a picture made where ParaView is installed)
  (cd "$work" && tar czf "$out/stability.tgz" stab_*/gauges stab_*/run.json stab_*/ledger.csv stab_*/run.log \
     stab_*/case.xml $(for p in ${STAB_PICTURE_PART:-}; do echo "stab_${p%%:*}/data/part_${p##*:}.h5"; done) 2>/dev/null)
}

for s in "$@"; do "step_$s"; done
