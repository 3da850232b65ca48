#!/usr/bin/env bash
# The speed benchmark set of issue 16 in one command: runs the selected parts and prints ONE
# table (last) with SeaSpring's figure, DualSPHysics' figure (or the other reference) and issue
# 16's target side by side; the same table goes to bench.csv. Runs ON the GPU machine from the
# repository root with build-dev carried (tools/device_build.sh made it):
#
#   tools/bench.sh [PART ...]                  no PART (or `default`): fluid sps memory small fsi3d
#   BASE_BIN=build-dev/base ROUNDS=2 tools/bench.sh fluid   this build against a baseline build
#
# Parts (they run in this order whatever the order given):
#   fluid1m  (optional) SPHERIC Test 2 at 1.12 M particles (Spheric2Dam_01M.xml, dp 0.01), first
#            0.02 s, symplectic + Wendland + DDT 3 + the case's artificial viscosity, DBC.
#   fluid    the same at 4.36 M (dp 0.006 -> 4,360,716 particles) and 13.29 M (dp 0.004 ->
#            13,292,664): ns per particle per step.
#   violent  (optional) SPHERIC Test 2 at 1.12 M in a disordered flow: the new build runs to
#            VIOLENT_T0 (default 0.6 s, after the front has hit the obstacle) and writes a
#            restart file there; then each build runs VIOLENT_STEPS (default 300) steps from it:
#            ns per particle per step. The lattice-start figures above show the pair loop at its
#            best; this one shows it where a dam break spends most of its time (at 1.12 M on an
#            H100 about 1.4x the lattice's; docs/performance-large.md, sixteenth session). A
#            baseline must read the new build's restart file (and BASE_ARGS must not change the
#            physics line, which -restart checks).
#   memory   GPU memory per particle: nvidia-smi memory.used sampled in the background (one query
#            about every 100 ms) during the 4.36 M and 13.29 M runs; the table shows the peak of
#            each run and the marginal bytes per particle (peak13 - peak4) / (n13 - n4), which
#            cancels the CUDA context and whatever else the GPU holds. With `fluid` the samples
#            come from the fluid runs; without it, short runs (-nsteps:MEM_NSTEPS) are made.
#   sps      SPHERIC 4.36 M with -viscolamsps:1e-6 (laminar + SPS): ns per particle per step.
#   small    latency-bound small cases on their own parameters: Antoci gate 2D
#            (cases/antoci_gate2d, about 17 k particles), ms per step over -tmax:0.05; FlexStruc
#            Liao 2D (DualSPHysics' CaseDambreak2D_FSI_Def.xml), loop seconds per simulated
#            second from -tmax:0.05.
#   fsi3d    FlexStruc Liao 3D (CaseDambreak3D_FSI_Def.xml), loop time of the first 0.02 s.
#   cpu      the CPU backend, -cpu -threads:2 (pinned to cores 0,1 with taskset where it exists)
#            on Spheric2Dam_100K.xml at its own dp (116,658 particles), first 0.02 s: µs per
#            particle per step. Only comparable with DualSPHysics' 2-thread figure (3.0 µs) when
#            run on the 2-core development machine, beside it; on the GPU machine it is a
#            base/new comparison only.
#   sluice   (optional, off by default, about 13.5 M particles: run it alone) the 3D sluice gate
#            (cases/sluice_gate/SluiceGate3D_Def.xml) at -dp:0.001, estimated time of its 2 s.
#            Method: one run with progress lines every SLUICE_PROGRESS s of wall time (the only
#            run not at -progress:0). Each progress line gives the simulated time t, the step
#            count and the loop time so far (its ns/particle/step x steps x particles). The
#            window opens at the first line with t >= SLUICE_T0 (default 0.005 s, to leave the
#            start-up behind) and closes at the first line SLUICE_STEPS steps later (default
#            600); the script then stops the run (it kills the solver it started; there is no
#            run.json and no state hash). In the window: ms per step = loop time / steps, steps
#            per simulated second = steps / simulated time, and the estimate for 2 s is
#            2 s x steps per simulated second x ms per step. It assumes the window's rates hold
#            for the whole run: the impacts shorten dt later and water leaves the domain (the
#            seed went from 13.5 M to 8.4 M particles), so take it as an estimate of the order.
#            Measured at dp 2 mm (docs/performance-large.md, fifteenth session): the first 0.71 s
#            cost 1.9x the default window's rate per simulated second, so the default estimate
#            is about half of the whole run. A larger SLUICE_T0 (e.g. 0.2, the first impact)
#            costs that much simulated time first (at dp 1 mm more than one device call; a
#            restart file written at that time, -checkpoint, and BENCH_ARGS=-restart:FILE avoid
#            it; with -restart the rates count only the continuation's steps).
#   sluicerun (optional; with sluice, after it) the same case at SLUICE_RUN_DP (default 0.003,
#            about 750 k particles) run to its end (or the deadline), progress lines every
#            SLUICE_RUN_PROGRESS (0.05) s of wall time: its loop time per simulated second over
#            the whole run divided by its rate over the dp 1 mm window's simulated interval
#            (interpolated between its progress lines) is the factor from the window's estimate
#            to the whole run's; the table adds "whole-run est." = the window's hours x factor.
#            It assumes the coarse run's later phases cost, relative to its start, what the fine
#            run's would (more steps per simulated second after the impacts, disordered flow,
#            more sorts, water leaving the domain).
#   capacity (optional, off by default, about 250 M particles at the default dp: run it alone)
#            SPHERIC Test 2 at CAPACITY_DP (default 0.0015) for CAPACITY_NSTEPS (10) steps, as the
#            fluid part's runs: how large a case this GPU and this machine hold. Rows: the GPU
#            arrays' bytes per particle (SeaSpring's own count of its allocations, run.json's
#            memory.gpu_arrays_peak_bytes / particles), the peak of nvidia-smi's memory.used, the
#            host's peak bytes per particle of the solver (run.json memory.host_peak_bytes) and of
#            gencase (its "host memory peak"), the case file's bytes per particle, and the largest
#            SPHERIC-like case: on this GPU the run's particles + (memory.total - the peak of
#            memory.used) / the arrays' bytes per particle; in this host's memory MemTotal / the
#            larger of the solver's and gencase's host bytes per particle (bench_table.py capacity).
#            Both assume the bytes per particle stay as measured (the cells grow with the domain,
#            not with the particles; a case with solids or SPS holds more per particle).
#
# Every run: -sv:none -progress:0 (sluice, sluicerun: progress lines); the figures are read from
# OUTDIR/run.json. Cases are generated once per dp with the new build's gencase and cached under
# the work folder (regenerated when the gencase binary or the definition changes); the baseline
# runs the same generated files.
#
# Env: SS_BIN       folder with seaspring and gencase (default build-dev/bin; build-dev/lib is put
#                   on LD_LIBRARY_PATH when it exists)
#      BASE_BIN     folder with the baseline seaspring: every timed run is repeated with it,
#                   alternating base then new (same machine, back to back); the table adds the
#                   base figure, new/base and whether the state hashes match
#      BASE_ENV     environment assignments for the baseline runs only, e.g. BASE_BIN=build-dev/bin
#                   BASE_ENV=SEASPRING_FORCES_AHEAD=0: one binary with and without a run-time switch
#      BASE_ARGS    extra solver options for the baseline runs only, e.g. BASE_BIN=build-dev/bin
#                   BASE_ARGS=-pairlanes:1: one binary with and without an option
#      ROUNDS       rounds of each run (default 1); the table shows medians
#      OUT          where bench.csv (the table) and bench.log (everything printed) go
#                   (default /tmp/seaspring_bench)
#      BENCH_WORK   work folder: generated cases, run outputs, the raw results runs.csv
#                   (default /tmp/seaspring_bench/work; never under OUT, the cases are large)
#      BENCH_DEADLINE  seconds after which no new run starts and the running one is stopped, so
#                   that the table is printed inside the 10-minute command limit (default 540)
#      BENCH_ARGS   extra solver options for every run (e.g. -skin:0, -cellmode:h)
#      BENCH_BACKEND backend options of the GPU parts (default -gpu; "-cpu -threads:2" tests the
#                   plumbing on a machine without a GPU, with small dp and times below)
#      BENCH_NSTEPS adds -nsteps:N to every run (plumbing tests)
#      SHARED_CASES folder with the DualSPHysics inputs (default: the first of build-dev/shared-cases,
#                   build-dev/shared/dualsphysics-cases, ../shared/dualsphysics-cases that has the file)
#      MEM_NSTEPS   steps of the memory-only runs (default 40); GPU_INDEX nvidia-smi's GPU (default 0)
#      SLUICE_T0, SLUICE_STEPS, SLUICE_PROGRESS (default 0.005 s, 600, 1 s), SLUICE_TEND (2),
#      SLUICE_RUN_DP (0.003), SLUICE_RUN_PROGRESS (0.05 s), SLUICE_RUN_SPAN (0.0065 s: the
#      window's length when sluicerun runs without sluice)
#      Testing sizes: SPHERIC_DP_1M/_A/_B (0.01, 0.006, 0.004), FLUID_TMAX (0.02), SMALL_TMAX
#      (0.05), FSI3D_TMAX (0.02), FSI3D_DP (the case's), CPU_TMAX (0.02), SLUICE_DP (0.001),
#      VIOLENT_T0 (0.6), VIOLENT_STEPS (300).
#
# Exit status: 0 when every run succeeded, 1 when any failed or was skipped (the table is printed
# either way; a failed run prints its log's tail and shows FAILED in the table), 2 bad usage.
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
abs() { if [[ -z "$1" || "$1" == /* ]]; then echo "$1"; else echo "$PWD/$1"; fi; }  # before the cd
new_bin=$(abs "${SS_BIN:-$root/build-dev/bin}")
base_bin=$(abs "${BASE_BIN:-}")
outdir=$(abs "${OUT:-/tmp/seaspring_bench}")
work=$(abs "${BENCH_WORK:-/tmp/seaspring_bench/work}")
[[ -n "${SHARED_CASES:-}" ]] && SHARED_CASES=$(abs "$SHARED_CASES")
cd "$root" || exit 2
[[ -d "$root/build-dev/lib" ]] && export LD_LIBRARY_PATH="$root/build-dev/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
rounds="${ROUNDS:-1}"
deadline="${BENCH_DEADLINE:-540}"
table_py="$root/tools/bench_table.py"
read -r -a backend <<<"${BENCH_BACKEND:--gpu}"
read -r -a extra <<<"${BENCH_ARGS:-}"
[[ -n "${BENCH_NSTEPS:-}" ]] && extra+=("-nsteps:$BENCH_NSTEPS")
all_parts=(fluid1m fluid violent memory sps small fsi3d cpu sluice sluicerun capacity)
default_parts=(fluid sps memory small fsi3d)

usage() { sed -n '2,/^set -uo/p' "${BASH_SOURCE[0]}" | sed '$d' | sed 's/^# \{0,1\}//'; }
want=()
for a in "$@"; do
  case "$a" in
    -h|--help) usage; exit 0 ;;
    default) want+=("${default_parts[@]}") ;;
    fluid1m|fluid|violent|memory|sps|small|fsi3d|cpu|sluice|sluicerun|capacity) want+=("$a") ;;
    *) echo "bench.sh: unknown part '$a' (parts: ${all_parts[*]}; default: ${default_parts[*]})" >&2; exit 2 ;;
  esac
done
[[ ${#want[@]} -eq 0 ]] && want=("${default_parts[@]}")
selected() { local p; for p in "${want[@]}"; do [[ $p == "$1" ]] && return 0; done; return 1; }
[[ "$rounds" =~ ^[1-9][0-9]*$ ]] || { echo "bench.sh: ROUNDS must be a positive integer" >&2; exit 2; }

# Binaries and tools, checked before anything starts.
missing=0
for f in "$new_bin/seaspring" "$new_bin/gencase" ${base_bin:+"$base_bin/seaspring"}; do
  [[ -x "$f" ]] || { echo "bench.sh: missing binary $f (SS_BIN / BASE_BIN)" >&2; missing=1; }
done
command -v python3 >/dev/null || { echo "bench.sh: python3 not found" >&2; missing=1; }
command -v timeout >/dev/null || { echo "bench.sh: timeout (coreutils) not found" >&2; missing=1; }
[[ $missing == 0 ]] || exit 2
builds=(new)
[[ -n "$base_bin" ]] && builds=(base new)
mkdir -p "$outdir" "$work/cases" "$work/runs" || exit 2
raw="$work/runs.csv"
rm -f "$raw"

start=$SECONDS
remaining() { echo $((deadline - (SECONDS - start))); }
stamp() { printf '%4ds' $((SECONDS - start)); }
any_failed=0

# A DualSPHysics input: SHARED_CASES, then the copies device_build.sh makes, then ../shared.
shared_case() {
  local d
  for d in ${SHARED_CASES:+"$SHARED_CASES"} "$root/build-dev/shared-cases" "$root/build-dev/shared/dualsphysics-cases" \
           "$root/../shared/dualsphysics-cases"; do
    [[ -f "$d/$1" ]] && { echo "$d/$1"; return 0; }
  done
  echo "bench.sh: $1 not found (SHARED_CASES, build-dev/shared-cases, build-dev/shared/dualsphysics-cases, ../shared/dualsphysics-cases)" >&2
  return 1
}

# Records a row with no run behind it (a case that could not be generated, the deadline).
record_status() {  # bench status note
  local b r
  for ((r = 1; r <= rounds; ++r)); do
    for b in "${builds[@]}"; do
      python3 "$table_py" record "$raw" "$1" "$b" "$r" ns - --status "$2" --note "$3"
    done
  done
  any_failed=1
}

# A benchmark whose case is missing or was not generated (SKIPPED when the deadline stopped it).
no_case() {  # bench
  if (($(remaining) < 10)); then record_status "$1" SKIPPED "deadline reached before its case was generated"
  else record_status "$1" FAILED "case not found or not generated (see the log above)"; fi
}

# gencase once per case and dp: WORK/cases/NAME.{xml,h5}, kept while the gencase binary and the
# definition are unchanged.
ensure_case() {  # name def.xml [dp]
  local name=$1 xml=$2 dp=${3:-} want have="" left
  want="$(cksum <"$new_bin/gencase" | cut -d' ' -f1) $(cksum <"$xml" | cut -d' ' -f1) ${dp:-own-dp}"
  [[ -f "$work/cases/$name.stamp" ]] && have=$(<"$work/cases/$name.stamp")
  if [[ -f "$work/cases/$name.h5" && -f "$work/cases/$name.xml" && "$have" == "$want" ]]; then
    echo "[$(stamp)] case $name: cached"
    return 0
  fi
  left=$(remaining)
  ((left > 10)) || { echo "[$(stamp)] case $name: not generated, deadline reached"; return 1; }
  rm -f "$work/cases/$name".*
  echo "[$(stamp)] gencase $xml -> $name ${dp:+(dp $dp)}"
  local t0=$SECONDS
  if ! timeout -k 5 "$left" "$new_bin/gencase" "$xml" "$work/cases/$name" ${dp:+"-dp:$dp"} >"$work/cases/$name.gencase.log" 2>&1; then
    echo "FAILED: gencase for $name; last lines of its log:"
    tail -n 15 "$work/cases/$name.gencase.log" | sed 's/^/  | /'
    return 1
  fi
  grep -E '^Particles:' "$work/cases/$name.gencase.log" | sed "s/^/  /; s/\$/ (gencase $((SECONDS - t0)) s)/"
  echo "$want" >"$work/cases/$name.stamp"
}

# GPU memory sampler: memory.used [MiB] about every 100 ms while a run lasts.
sampler_pid=""
mem_start() {  # samples-file
  local gpu=${GPU_INDEX:-0}
  ( while nvidia-smi --query-gpu=memory.used --format=csv,noheader,nounits -i "$gpu" 2>/dev/null; do sleep 0.1; done ) >"$1" &
  sampler_pid=$!
}
mem_stop() {
  [[ -n "$sampler_pid" ]] || return 0
  kill "$sampler_pid" 2>/dev/null
  wait "$sampler_pid" 2>/dev/null
  sampler_pid=""
}
gpu_name() { nvidia-smi --query-gpu=name --format=csv,noheader -i "${GPU_INDEX:-0}" 2>/dev/null | head -n 1; }

prefix=()  # put before the solver (the cpu part's taskset)

# One solver run: WORK/runs/BENCH_BUILD_rROUND{,.log}; records its figure (KIND) and, when MEMBENCH
# is given, the peak GPU memory under that name.
run_one() {  # bench kind build round case membench solver-args...
  local bench=$1 kind=$2 build=$3 round=$4 case=$5 membench=$6; shift 6
  local b=$new_bin; [[ $build == base ]] && b=$base_bin
  local out="$work/runs/${bench}_${build}_r$round" left rc status note=""
  local log="$out.log"
  left=$(remaining)
  if ((left < 10)); then
    echo "[$(stamp)] $bench $build round $round: SKIPPED (BENCH_DEADLINE $deadline s reached)"
    python3 "$table_py" record "$raw" "$bench" "$build" "$round" "$kind" - --status SKIPPED --note "deadline reached"
    [[ -n "$membench" ]] && python3 "$table_py" record "$raw" "$membench" "$build" "$round" ns - --status SKIPPED --note "deadline reached"
    any_failed=1
    return
  fi
  rm -rf "$out"
  local envs=() base_args=()
  [[ $build == base && -n "${BASE_ENV:-}" ]] && read -r -a envs <<<"env $BASE_ENV"
  [[ $build == base && -n "${BASE_ARGS:-}" ]] && read -r -a base_args <<<"$BASE_ARGS"
  local cmd=("${envs[@]}" "${prefix[@]}" "$b/seaspring" "$@" "${extra[@]}" "${base_args[@]}" -sv:none -progress:0 "$work/cases/$case" "$out")
  echo "[$(stamp)] $bench $build round $round: ${cmd[*]}"
  [[ -n "$membench" ]] && mem_start "$out.mem"
  timeout -k 5 "$left" "${cmd[@]}" >"$log" 2>&1
  rc=$?
  [[ -n "$membench" ]] && mem_stop
  if [[ $rc == 0 ]]; then
    grep -E '^(Finished|State hash)' "$log" | sed 's/^/  /'
    python3 "$table_py" record "$raw" "$bench" "$build" "$round" "$kind" "$out/run.json"
  else
    status=FAILED
    [[ $rc == 124 || $rc == 137 ]] && { status=TIMEOUT; note="stopped at the deadline"; }
    echo "$status: $bench $build round $round (exit $rc); last lines of $log:"
    tail -n 20 "$log" | sed 's/^/  | /'
    [[ -n "$note" ]] || note="exit $rc: $(grep -v '^\s*$' "$log" | tail -n 2 | tr '\n' ' ' | cut -c1-200)"
    python3 "$table_py" record "$raw" "$bench" "$build" "$round" "$kind" - --status "$status" --note "$note"
    any_failed=1
  fi
  if [[ -n "$membench" ]]; then
    local np=""
    [[ $rc == 0 ]] && np=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["particles"]["total"])' "$out/run.json" 2>/dev/null)
    if [[ -n "$np" ]]; then
      python3 "$table_py" memory "$raw" "$membench" "$build" "$round" "$out.mem" "$np" --device "$(gpu_name)" \
        --note "idle before: ${idle_mib:-?} MiB"
    else
      python3 "$table_py" record "$raw" "$membench" "$build" "$round" ns - --status FAILED --note "the run failed"
    fi
  fi
}

# Every round, every build (base first), one run each.
timed() {  # bench kind case membench solver-args...
  local r b
  for ((r = 1; r <= rounds; ++r)); do
    for b in "${builds[@]}"; do
      [[ -n "$4" ]] && idle_mib=$(nvidia-smi --query-gpu=memory.used --format=csv,noheader,nounits -i "${GPU_INDEX:-0}" 2>/dev/null | head -n 1)
      run_one "$1" "$2" "$b" "$r" "$3" "$4" "${@:5}"
    done
  done
}

# The violent part's restart file: the new build from t = 0 to T0 with a checkpoint there.
# Sets violent_step (the step of the restart file) and returns 0 when the file was written.
violent_restart() {  # case t0 solver-args...
  local case=$1 t0=$2; shift 2
  local out="$work/runs/violent_restart" left
  left=$(remaining)
  ((left < 10)) && { echo "[$(stamp)] violent: no time left for the restart file"; return 1; }
  rm -rf "$out"
  echo "[$(stamp)] violent: restart file at t = $t0 s (new build)"
  timeout -k 5 "$left" "$new_bin/seaspring" "$@" "${extra[@]}" -tmax:"$t0" -checkpoint:"$t0" -sv:none -progress:0 \
    "$work/cases/$case" "$out" >"$out.log" 2>&1 || { tail -n 5 "$out.log" | sed 's/^/  | /'; return 1; }
  violent_step=$(grep -o "checkpoint t=[0-9.e+-]* s, step [0-9]*" "$out.log" | tail -n 1 | grep -o "[0-9]*$")
  [[ -n "$violent_step" && -f "$out/restart.h5" ]] || { echo "  no restart file written"; return 1; }
  echo "  restart file at step $violent_step"
}

# The sluice run, stopped after its window (see the header).
sluice_one() {  # build round case
  local build=$1 round=$2 case=$3 b=$new_bin left pid rc stopped="" note=""
  [[ $build == base ]] && b=$base_bin
  local out="$work/runs/sluice3d_${build}_r$round" t0=${SLUICE_T0:-0.005} n=${SLUICE_STEPS:-600}
  local log="$out.log"
  left=$(remaining)
  if ((left < 30)); then
    python3 "$table_py" record "$raw" sluice3d "$build" "$round" ns - --status SKIPPED --note "deadline reached"
    any_failed=1
    return
  fi
  rm -rf "$out"
  local cmd=("$b/seaspring" "${backend[@]}" "${extra[@]}" -sv:none -progress:"${SLUICE_PROGRESS:-1}"
             -tmax:"${SLUICE_TEND:-2}" "$work/cases/$case" "$out")
  echo "[$(stamp)] sluice3d $build round $round (window of $n steps from t >= $t0 s): ${cmd[*]}"
  timeout -k 5 "$left" "${cmd[@]}" >"$log" 2>&1 &
  pid=$!
  while kill -0 "$pid" 2>/dev/null; do
    sleep 2
    if python3 "$table_py" sluice-done "$log" "$t0" "$n"; then
      stopped="window complete"
    elif (($(remaining) < 15)); then
      stopped="deadline"; note="stopped at the deadline"
    fi
    if [[ -n "$stopped" ]]; then
      kill "$pid" 2>/dev/null  # the timeout process; it passes the signal on to the solver
      break
    fi
  done
  wait "$pid"
  rc=$?
  grep -E '^t=' "$log" | tail -n 2 | sed 's/^/  /'
  if [[ -z "$stopped" && $rc != 0 ]]; then
    echo "FAILED: sluice3d $build round $round (exit $rc); last lines of $log:"
    tail -n 20 "$log" | sed 's/^/  | /'
    python3 "$table_py" record "$raw" sluice3d "$build" "$round" ns - --status FAILED \
      --note "exit $rc: $(grep -v '^\s*$' "$log" | tail -n 2 | tr '\n' ' ' | cut -c1-200)"
    any_failed=1
    return
  fi
  echo "  stopped: ${stopped:-the run ended (exit $rc)}"
  python3 "$table_py" sluice "$raw" "$build" "$round" "$log" "$t0" "$n" "${SLUICE_TEND:-2}" --note "$note" ||
    any_failed=1
  grep -q "^sluice3d,$build,$round,ok," "$raw" || any_failed=1
}

# The coarse sluice's whole run (see the header): recorded as sluice3d_run.
sluice_run_one() {  # build round case
  local build=$1 round=$2 b=$new_bin left rc status=ok note=""
  [[ $build == base ]] && b=$base_bin
  local out="$work/runs/sluice3d_run_${build}_r$round"
  left=$(remaining)
  ((left < 30)) && { python3 "$table_py" record "$raw" sluice3d_run "$build" "$round" ns - --status SKIPPED \
    --note "deadline reached"; any_failed=1; return; }
  rm -rf "$out"
  local cmd=("$b/seaspring" "${backend[@]}" "${extra[@]}" -sv:none -progress:"${SLUICE_RUN_PROGRESS:-0.05}"
             -tmax:"${SLUICE_TEND:-2}" "$work/cases/$3" "$out")
  echo "[$(stamp)] sluice3d_run $build round $round: ${cmd[*]}"
  timeout -k 5 "$((left - 5))" "${cmd[@]}" >"$out.log" 2>&1
  rc=$?
  grep -E '^(t=|Finished|State hash)' "$out.log" | tail -n 3 | sed 's/^/  /'
  [[ $rc == 124 || $rc == 137 ]] && note="stopped at the deadline"
  [[ $rc != 0 && -z $note ]] && { status=FAILED; note="exit $rc"; tail -n 10 "$out.log" | sed 's/^/  | /'; }
  python3 "$table_py" sluice-run "$raw" "$build" "$round" "$out.log" "$out/run.json" "${SLUICE_T0:-0.005}" \
    "${SLUICE_RUN_SPAN:-0.0065}" --status "$status" --note "$note" || any_failed=1
  grep -q "^sluice3d_run,$build,$round,ok," "$raw" || any_failed=1
}

# A sluice part: its case at dp, then fn for every round and build.
sluice_rounds() {  # fn dp bench
  local r b
  if ensure_case "sluice_dp$2" "$root/cases/sluice_gate/SluiceGate3D_Def.xml" "$2"; then
    for ((r = 1; r <= rounds; ++r)); do
      for b in "${builds[@]}"; do "$1" "$b" "$r" "sluice_dp$2"; done
    done
  else no_case "$3"; fi
}

main() {
  trap mem_stop EXIT
  echo "== SeaSpring speed benchmark (issue 16): parts ${want[*]}"
  echo "   $(date -u '+%Y-%m-%d %H:%M UTC'), commit $(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo '?'), host $(hostname 2>/dev/null || uname -n)"
  echo "   new: $new_bin${base_bin:+; base: $base_bin}${BASE_ENV:+ with $BASE_ENV}${BASE_ARGS:+ and $BASE_ARGS}; rounds $rounds; backend ${backend[*]}; extra options: ${extra[*]:-none}"
  echo "   work $work, results $outdir; deadline $deadline s"
  command -v nvidia-smi >/dev/null && nvidia-smi --query-gpu=index,name,driver_version,memory.total,memory.used --format=csv,noheader | sed 's/^/   GPU /'
  local spheric="" s100k="" gen_ok

  if selected fluid1m || selected fluid || selected violent || selected memory || selected sps || selected capacity; then
    spheric=$(shared_case Spheric2Dam_01M.xml) || spheric=""
  fi
  local fluid_args=("${backend[@]}" -symplectic -wendland -ddt:3 -tmax:"${FLUID_TMAX:-0.02}")
  local dp1=${SPHERIC_DP_1M:-0.01} dpa=${SPHERIC_DP_A:-0.006} dpb=${SPHERIC_DP_B:-0.004}
  local mem_ok=0
  if selected memory; then
    if [[ "${backend[*]}" == *-cpu* ]]; then
      record_status mem_peak_4.36M FAILED "memory needs the GPU (BENCH_BACKEND is ${backend[*]})"
    elif ! command -v nvidia-smi >/dev/null; then
      record_status mem_peak_4.36M FAILED "nvidia-smi not found"
    else
      mem_ok=1
    fi
  fi

  if selected fluid1m; then
    echo "== fluid1m: SPHERIC Test 2, dp $dp1 (1.12 M)"
    if [[ -n "$spheric" ]] && ensure_case "spheric_dp$dp1" "$spheric" "$dp1"; then
      timed spheric_1.12M ns "spheric_dp$dp1" "" "${fluid_args[@]}"
    else no_case spheric_1.12M; fi
  fi

  if selected violent; then
    local vt0=${VIOLENT_T0:-0.6} vsteps=${VIOLENT_STEPS:-300} vargs=("${backend[@]}" -symplectic -wendland -ddt:3)
    echo "== violent: SPHERIC Test 2, dp $dp1 (1.12 M), $vsteps steps from a restart file at t = $vt0 s"
    if [[ -n "$spheric" ]] && ensure_case "spheric_dp$dp1" "$spheric" "$dp1" &&
       violent_restart "spheric_dp$dp1" "$vt0" "${vargs[@]}"; then
      timed spheric_1.12M_late ns "spheric_dp$dp1" "" "${vargs[@]}" -restart:"$work/runs/violent_restart/restart.h5" \
        -nsteps:$((violent_step + vsteps))
    else no_case spheric_1.12M_late; fi
  fi

  if selected fluid || ((mem_ok)); then
    local key dp memb args
    for key in 4.36M 13.29M; do
      dp=$dpa; [[ $key == 13.29M ]] && dp=$dpb
      memb=""; ((mem_ok)) && memb="mem_peak_$key"
      echo "== $(selected fluid && echo fluid)${memb:+ memory}: SPHERIC Test 2, dp $dp ($key)"
      gen_ok=0
      [[ -n "$spheric" ]] && ensure_case "spheric_dp$dp" "$spheric" "$dp" && gen_ok=1
      if selected fluid; then
        if ((gen_ok)); then timed "spheric_$key" ns "spheric_dp$dp" "$memb" "${fluid_args[@]}"
        else no_case "spheric_$key"; fi
      elif ((gen_ok)); then
        args=("${fluid_args[@]}" -nsteps:"${MEM_NSTEPS:-40}")
        timed "memrun_$key" ns "spheric_dp$dp" "$memb" "${args[@]}"
      fi
      if [[ -n "$memb" ]] && ((!gen_ok)); then no_case "$memb"; fi
    done
  fi

  if selected sps; then
    echo "== sps: SPHERIC Test 2, dp $dpa (4.36 M), laminar + SPS 1e-6"
    if [[ -n "$spheric" ]] && ensure_case "spheric_dp$dpa" "$spheric" "$dpa"; then
      timed spheric_4.36M_sps ns "spheric_dp$dpa" "" "${fluid_args[@]}" -viscolamsps:1e-6
    else no_case spheric_4.36M_sps; fi
  fi

  if selected small; then
    local tsmall=${SMALL_TMAX:-0.05} liao2d
    echo "== small: Antoci gate 2D and FlexStruc Liao 2D, -tmax:$tsmall"
    if ensure_case antoci2d "$root/cases/antoci_gate2d/AntociGate2D_Def.xml"; then
      timed antoci2d ms_per_step antoci2d "" "${backend[@]}" -tmax:"$tsmall"
    else no_case antoci2d; fi
    if liao2d=$(shared_case flexstruc/CaseDambreak2D_FSI_Def.xml) && ensure_case liao2d "$liao2d"; then
      timed liao2d s_per_sim_s liao2d "" "${backend[@]}" -tmax:"$tsmall"
    else no_case liao2d; fi
  fi

  if selected fsi3d; then
    local liao3d
    echo "== fsi3d: FlexStruc Liao 3D, first ${FSI3D_TMAX:-0.02} s"
    if liao3d=$(shared_case flexstruc/CaseDambreak3D_FSI_Def.xml) &&
       ensure_case "liao3d${FSI3D_DP:+_dp$FSI3D_DP}" "$liao3d" "${FSI3D_DP:-}"; then
      timed liao3d loop_s "liao3d${FSI3D_DP:+_dp$FSI3D_DP}" "" "${backend[@]}" -tmax:"${FSI3D_TMAX:-0.02}"
    else no_case liao3d; fi
  fi

  if selected cpu; then
    echo "== cpu: Spheric2Dam_100K, -cpu -threads:2, first ${CPU_TMAX:-0.02} s (DualSPHysics' 3.0 us is from the 2-core dev machine)"
    if s100k=$(shared_case Spheric2Dam_100K.xml) && ensure_case spheric100k "$s100k"; then
      command -v taskset >/dev/null && (($(nproc) > 2)) && prefix=(taskset -c "0,1")
      timed cpu_100K us spheric100k "" -cpu -threads:2 -symplectic -wendland -ddt:3 -tmax:"${CPU_TMAX:-0.02}"
      prefix=()
    else no_case cpu_100K; fi
  fi

  if selected sluice; then
    echo "== sluice: SluiceGate3D at dp ${SLUICE_DP:-0.001} (about 13.5 M particles at 0.001), estimate of its ${SLUICE_TEND:-2} s"
    sluice_rounds sluice_one "${SLUICE_DP:-0.001}" sluice3d
  fi
  if selected sluicerun; then
    echo "== sluicerun: SluiceGate3D at dp ${SLUICE_RUN_DP:-0.003}, its whole ${SLUICE_TEND:-2} s (the window-to-whole-run factor)"
    sluice_rounds sluice_run_one "${SLUICE_RUN_DP:-0.003}" sluice3d_run
  fi

  if selected capacity; then
    local cdp=${CAPACITY_DP:-0.0015} r b host_bytes
    echo "== capacity: SPHERIC Test 2 at dp $cdp, ${CAPACITY_NSTEPS:-10} steps: the largest case this GPU and host hold"
    host_bytes=$(awk '/^MemTotal:/ {printf "%.0f", $2 * 1024}' /proc/meminfo)
    if [[ "${backend[*]}" == *-cpu* ]] || ! command -v nvidia-smi >/dev/null; then
      record_status capacity FAILED "capacity needs the GPU and nvidia-smi (BENCH_BACKEND is ${backend[*]})"
    elif [[ -n "$spheric" ]] && ensure_case "spheric_dp$cdp" "$spheric" "$cdp"; then
      for ((r = 1; r <= rounds; ++r)); do
        for b in "${builds[@]}"; do
          run_one capacity gpu_bpp "$b" "$r" "spheric_dp$cdp" capacity_smi_peak "${fluid_args[@]}" \
            -nsteps:"${CAPACITY_NSTEPS:-10}"
          python3 "$table_py" capacity "$raw" "$b" "$r" "$work/runs/capacity_${b}_r$r/run.json" \
            "$work/cases/spheric_dp$cdp.gencase.log" "$host_bytes" --device "$(gpu_name)"
        done
      done
    else no_case capacity; fi
  fi

  echo
  echo "== runs (raw, $raw)"
  python3 "$table_py" runs "$raw"
  echo
  echo "== SeaSpring against DualSPHysics and issue 16's targets ($((SECONDS - start)) s; table also in $outdir/bench.csv)"
  python3 "$table_py" table "$raw" "$outdir/bench.csv" || any_failed=1
  grep -q -E ',(FAILED|TIMEOUT|SKIPPED),' "$raw" && any_failed=1
  return $any_failed
}

main 2>&1 | tee "$outdir/bench.log"
exit "${PIPESTATUS[0]}"
