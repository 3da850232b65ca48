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
# The fluid rows of tools/hash_table.sh (every physics family, the cell modes) on each backend.
for b in "-cpu -threads:1" "-cpu -threads:2" "-cpu -threads:16" "-gpu"; do
  tag=${b//[^a-z0-9]/}
  SHARED_CASES="$shared" "$root/tools/hash_table.sh" "$bin" "$out/hashes_$tag.txt" "$b" '^(db3d|val2d_)' >/dev/null
done
names() { awk '{ print $1, $2 }' "$1"; }  # name and state hash (a gauge digest may follow)
paste -d' ' <(names "$out/hashes_cputhreads1.txt") <(names "$out/hashes_cputhreads2.txt") \
  <(names "$out/hashes_cputhreads16.txt") <(names "$out/hashes_gpu.txt") |
  awk '{ same = ($2 == $4 && $2 == $6 && $2 == $8) ? "yes" : "NO";
         printf "%-28s cpu1=%s cpu2=%s cpu16=%s gpu=%s identical=%s\n", $1, $2, $4, $6, $8, same }' >"$table"
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
