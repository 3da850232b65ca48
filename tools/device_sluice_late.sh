#!/usr/bin/env bash
# SeaSpring — MIT licence.
# Runs ON the GPU machine (device tool) with the builds carried: where the 3D sluice gate's
# steps go after the impact, where the benchmark's pre-impact window does not look
# (docs/performance-large.md, fifteenth session). One run of the new build from t = 0 to
# T_CK with a restart file there; then, from that file, the window T_CK..T_END of each build
# (alternated, ROUNDS rounds) with the phase timers; then the GPU time of every pass over
# NCU_STEPS steps from t = 0 and after the restart, and the force launch's instructions, active
# lanes and occupancy in both (Nsight Compute, when `ncu` is there).
# Env: SS_BIN (new build, default build-dev/bin), BASE_BIN (optional baseline), DP (0.002),
#      T_CK (0.38), T_END (0.44), ROUNDS (2), NCU_STEPS (10; 0: none), BACKEND (-gpu),
#      OUT (where sluice_late.txt goes).
# The restart file is the new build's: a baseline that cannot read it fails visibly.
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
[[ -d $root/build-dev/lib ]] && export LD_LIBRARY_PATH="$root/build-dev/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
new=${SS_BIN:-$root/build-dev/bin}; base=${BASE_BIN:-}
dp=${DP:-0.002}; tck=${T_CK:-0.38}; tend=${T_END:-0.44}; rounds=${ROUNDS:-2}; ncu_steps=${NCU_STEPS:-10}
backend=(${BACKEND:--gpu})
out=${OUT:-/tmp/seaspring_out}; work=/tmp/seaspring_sluice_late
mkdir -p "$out" "$work"
table=$out/sluice_late.txt
: >"$table"
say() { echo "$*" | tee -a "$table"; }
command -v nvidia-smi >/dev/null && nvidia-smi --query-gpu=name --format=csv,noheader | tee -a "$table"
kase=$work/sluice_dp$dp
"$new/gencase" "$root/cases/sluice_gate/SluiceGate3D_Def.xml" "$kase" -dp:"$dp" >"$work/gencase.log" 2>&1 ||
  { tail -3 "$work/gencase.log"; exit 1; }
args=("${backend[@]}" -sv:none -progress:0)

say "== the new build from t = 0 to $tck s (restart file there): $new"
"$new/seaspring" -overwrite "${args[@]}" -tmax:"$tck" -checkpoint:"$tck" "$kase" "$work/ck" >"$work/ck.log" 2>&1 ||
  { tail -5 "$work/ck.log"; exit 1; }
grep -E "^(Finished|Particles)" "$work/ck.log" | tee -a "$table"
cp "$work/ck/restart.h5" "$work/restart.h5"
ck=$(grep -o "checkpoint t=[0-9.e+-]* s, step [0-9]*" "$work/ck.log" | tail -n 1 | grep -o "[0-9]*$")
[[ -n $ck ]] || { say "no restart file was written"; exit 1; }
say "restart file at step $ck"

window() {  # label bin
  local label=$1 b=$2 log="$work/w_$1.log"
  if ! SEASPRING_TIMERS=1 "$b/seaspring" -overwrite "${args[@]}" -tmax:"$tend" -restart:"$work/restart.h5" "$kase" \
      "$work/w" >"$log" 2>&1; then
    say "$label: FAILED ($(grep -v '^\s*$' "$log" | tail -n 1))"
    return
  fi
  /usr/bin/python3 - "$work/w/run.json" "$label" "$ck" "$(grep -o 'phase times per step.*' "$log")" <<'PY' | tee -a "$table"
import json, sys
j = json.load(open(sys.argv[1]))
steps = j["steps"] - int(sys.argv[3])  # older builds have no steps_this_run
print(f"{sys.argv[2]:<6} {steps} steps, loop {j['loop_time_s']:.2f} s, {1e3 * j['loop_time_s'] / steps:.3f} ms per step; "
      f"sorts {j['sorts']} (boundary block {j.get('boundary_sorts', '-')}) of {j['divides']} divides since t = 0; "
      f"hash {j['state_hash']}")
print(f"       {sys.argv[4]}")
PY
}
say "== the window $tck..$tend s from the restart file (phase timers synchronise: per-phase figures)"
for ((r = 1; r <= rounds; ++r)); do
  [[ -n $base ]] && window base "$base"
  window new "$new"
done

passes() {  # title args...: the GPU time of every pass over ncu_steps steps (Nsight Compute)
  local title=$1; shift
  say "== GPU time per pass, $title (new build)"
  ncu --clock-control none --print-units base --metrics gpu__time_duration.sum --csv \
    "$new/seaspring" -overwrite "${args[@]}" "$@" "$kase" "$work/n" 2>/dev/null |
    grep '^"' >"$work/ncu.csv"  # the CSV rows only (the solver's own lines share stdout)
  /usr/bin/python3 - "$work/ncu.csv" "$ncu_steps" <<'PY' | tee -a "$table"
import collections, csv, re, sys
t, n = collections.Counter(), collections.Counter()
for r in csv.DictReader(open(sys.argv[1])):
    name = r.get("Kernel Name", "")
    m = re.findall(r"(?:solver|physics)::(\w+Pass)\b", name) or re.findall(r"::(\w+Kernel)\b", name)
    key = m[0] if m else name[:48]
    try:
        v = float(r["Metric Value"].replace(",", ""))
    except (KeyError, ValueError):
        continue
    v *= {"nsecond": 1.0, "ns": 1.0, "usecond": 1e3, "msecond": 1e6, "second": 1e9}.get(r.get("Metric Unit", "nsecond"), 1.0)
    t[key] += v
    n[key] += 1
steps = int(sys.argv[2])
for k, v in t.most_common(25):
    print(f"  {k:<40} {n[k]:6d} launches {v / 1e6 / steps:9.3f} ms per step")
print(f"  {'all':<40} {sum(n.values()):6d} launches {sum(t.values()) / 1e6 / steps:9.3f} ms per step")
PY
  # The force launch (fluid and boundary particles in one grid) in detail: per launch that ran
  # (a launch gated off by a sort takes a few microseconds and is left out).
  ncu --clock-control none --print-units base --kernel-name-base demangled -k regex:FluidLanes --csv --metrics \
    gpu__time_duration.sum,smsp__thread_inst_executed.sum,smsp__inst_executed.sum,sm__warps_active.avg.pct_of_peak_sustained_active,launch__registers_per_thread \
    "$new/seaspring" -overwrite "${args[@]}" "$@" "$kase" "$work/n" 2>/dev/null | grep '^"' >"$work/ncu_f.csv"
  /usr/bin/python3 - "$work/ncu_f.csv" "$nfluid" <<'PY' | tee -a "$table"
import collections, csv, sys
by = collections.defaultdict(dict)
for r in csv.DictReader(open(sys.argv[1])):
    try:
        by[r["ID"]][r["Metric Name"]] = float(r["Metric Value"].replace(",", ""))
    except (KeyError, ValueError):
        pass
runs = [m for m in by.values() if m.get("gpu__time_duration.sum", 0) > 50e3]
if not runs:
    print("  force launch: no metrics"); sys.exit()
avg = lambda k: sum(m.get(k, 0) for m in runs) / len(runs)
nf = float(sys.argv[2])
print(f"  force launch ({len(runs)} that ran): {avg('gpu__time_duration.sum') / 1e3:.1f} us; "
      f"{avg('smsp__thread_inst_executed.sum') / nf:.0f} thread instructions per fluid particle; "
      f"{avg('smsp__thread_inst_executed.sum') / max(avg('smsp__inst_executed.sum'), 1):.1f} of 32 lanes active; "
      f"occupancy {avg('sm__warps_active.avg.pct_of_peak_sustained_active'):.1f}%; "
      f"{avg('launch__registers_per_thread'):.0f} registers")
PY
}
if ((ncu_steps > 0)) && command -v ncu >/dev/null; then
  nfluid=$(grep -o "fluid [0-9]*" "$work/ck.log" | head -n 1 | grep -o "[0-9]*$")
  passes "the first $ncu_steps steps from t = 0" -nsteps:"$ncu_steps"
  passes "$ncu_steps steps after the restart at $tck s" -nsteps:$((ck + ncu_steps)) -restart:"$work/restart.h5"
fi
