#!/usr/bin/env bash
# Speed of this build against a baseline build, run back to back on the same machine in
# alternating rounds (tools/bench_fluid.sh underneath): the GPU on SPHERIC Test 2 at dp 0.006
# (4.36 M particles) and the CPU with 2 threads on Spheric2Dam_100K (116,658 particles, pinned
# to two cores with taskset where it exists); first 0.02 s, symplectic + Wendland + DDT 3 +
# artificial viscosity, DBC, no output. Prints ns per particle per step of every run and the
# ratio of the medians (new / base).
# Usage: BASE_BIN=dir [NEW_BIN=dir] [ROUNDS=3] [GPU=1] [CPU=1] tools/bench_compare.sh
# (on the GPU machine: with build-dev carried, LD_LIBRARY_PATH=build-dev/lib; CASES_DIR: the
#  folder holding Spheric2Dam_01M.xml and Spheric2Dam_100K.xml, default ../shared/dualsphysics-cases)
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
base="${BASE_BIN:?BASE_BIN: folder with the baseline seaspring and gencase}"
new="${NEW_BIN:-$root/build/bin}"
cases="${CASES_DIR:-$root/../shared/dualsphysics-cases}"
work="${BENCH_DIR:-/tmp/seaspring_bench_compare}"
rounds="${ROUNDS:-3}"
mkdir -p "$work"
results="$work/results.csv"
echo "set,build,round,particles,steps,ns_per_particle_step,state_hash" >"$results"
pin=()
command -v taskset >/dev/null && pin=(taskset -c 0,1)
one() {  # set build bin round backend-args...
  local set=$1 label=$2 bin=$3 round=$4; shift 4
  local d="$work/$set"
  mkdir -p "$d"
  if SEASPRING_BIN="$bin" BENCH_DIR="$d" "$@" >"$d/last_$label.txt" 2>&1; then
    tail -n +2 "$d/bench_fluid.csv" | awk -F, -v s="$set" -v l="$label" -v r="$round" \
      '{print s "," l "," r "," $2 "," $3 "," $6 "," $10}' >>"$results"
  else
    echo "FAILED $set $label round $round"; tail -5 "$d/last_$label.txt"
  fi
}
for ((r = 1; r <= rounds; ++r)); do
  if [[ "${GPU:-1}" == 1 ]]; then
    for b in base new; do
      bin=$base; [[ $b == new ]] && bin=$new
      one gpu_spheric_4.36M "$b" "$bin" "$r" env BENCH_CASE="$cases/Spheric2Dam_01M.xml" "$root/tools/bench_fluid.sh" -gpu 0.006
    done
  fi
  if [[ "${CPU:-1}" == 1 ]]; then
    for b in base new; do
      bin=$base; [[ $b == new ]] && bin=$new
      one cpu2_spheric_100K "$b" "$bin" "$r" env BENCH_CASE="$cases/Spheric2Dam_100K.xml" "${pin[@]}" \
        "$root/tools/bench_fluid.sh" -cpu -threads:2 0.025
    done
  fi
done
echo "== runs (ns per particle per step) =="
if command -v column >/dev/null; then column -s, -t "$results"; else tr , '\t' <"$results"; fi
echo "== median new / median base =="
python3 - "$results" <<'PY'
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1])))
for s in sorted({r["set"] for r in rows}):
    v = {b: [float(r["ns_per_particle_step"]) for r in rows if r["set"] == s and r["build"] == b] for b in ("base", "new")}
    h = {b: {r["state_hash"] for r in rows if r["set"] == s and r["build"] == b} for b in ("base", "new")}
    if v["base"] and v["new"]:
        mb, mn = statistics.median(v["base"]), statistics.median(v["new"])
        print(f"{s}: base {mb:.3f}  new {mn:.3f}  ratio {mn / mb:.3f}  hashes base {sorted(h['base'])} new {sorted(h['new'])}")
PY
