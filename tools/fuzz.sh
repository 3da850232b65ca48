#!/usr/bin/env bash
# Fuzzing (issue 14): builds the libFuzzer targets of tests/fuzz with clang, AddressSanitizer and
# UBSan into build-fuzz/ and runs each on its corpus (tests/fuzz/corpus/TARGET, the seeds and
# every finding kept as a regression input; new inputs libFuzzer finds go to
# build-fuzz/corpus/TARGET, never into the repository by themselves).
#
#   tools/fuzz.sh                      1,000,000 executions of each target
#   tools/fuzz.sh --runs N [TARGET..]  N executions (targets: expression gencase_xml solver_case)
#   tools/fuzz.sh --time S [TARGET..]  S seconds each
#   tools/fuzz.sh --ci                 30 s each (tools/test.sh runs this when clang can build)
#   FUZZ_JOBS=J                        J parallel fuzzing processes per target (default 1); their
#                                      executions add up
#   FUZZ_NO_BUILD=1                    use build-fuzz/bin as it is (a machine without clang)
#
# A finding (crash, sanitizer report, timeout of 10 s, more than 2 GB of memory) stops the
# target with its input saved as build-fuzz/findings/TARGET/crash-* (or timeout-*, oom-*,
# leak-*); fix it, then copy the input into tests/fuzz/corpus/TARGET: the replay tests
# (ctest -R fuzz_replay) run it in every build. Prints one table line per target (executions,
# seconds, findings) and exits 1 when any target had a finding.
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${FUZZ_BUILD_DIR:-$root/build-fuzz}"
mode=runs value=1000000
targets=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --runs) mode=runs value="$2"; shift 2 ;;
    --time) mode=time value="$2"; shift 2 ;;
    --ci) mode=time value=30; shift ;;
    expression|gencase_xml|solver_case) targets+=("$1"); shift ;;
    *) echo "fuzz.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
[[ ${#targets[@]} -gt 0 ]] || targets=(expression gencase_xml solver_case)
jobs="${FUZZ_JOBS:-1}"

if [[ -n "${FUZZ_NO_BUILD:-}" ]]; then  # the GPU machines: build-fuzz/bin carried, no clang there
  mkdir -p "$build"
else
command -v clang++ >/dev/null || { echo "fuzz.sh: clang++ not found (Debian: apt-get install clang)" >&2; exit 2; }
CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSEASPRING_FUZZ=ON \
  -DSEASPRING_CUDA=OFF -DSEASPRING_TESTS=OFF -DSEASPRING_HOST_SIMD=OFF >/dev/null || exit 2
cmake --build "$build" -j "${SEASPRING_JOBS:-$(nproc)}" --target $(printf 'fuzz_%s ' "${targets[@]}") >"$build/build.log" 2>&1 ||
  { tail -30 "$build/build.log"; echo "fuzz.sh: build failed ($build/build.log)" >&2; exit 2; }
fi

status=0
summary=()
for t in "${targets[@]}"; do
  corpus="$build/corpus/$t" findings="$build/findings/$t"
  mkdir -p "$corpus" "$findings"
  args=(-timeout=10 -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 -artifact_prefix="$findings/")
  if [[ $mode == runs ]]; then
    per=$(( (value + jobs - 1) / jobs ))
    args+=(-runs="$per")
  else
    args+=(-max_total_time="$value")
  fi
  log="$build/fuzz_$t.log"
  start=$(date +%s)
  if [[ $jobs -gt 1 ]]; then
    # Independent processes, each with its own runs budget, on the shared corpus folder.
    pids=()
    for j in $(seq 1 "$jobs"); do
      (cd "$build" && TMPDIR="$build" "$build/bin/fuzz_$t" "${args[@]}" "$corpus" "$root/tests/fuzz/corpus/$t" \
        >"$log.$j" 2>&1) &
      pids+=($!)
    done
    rc=0
    for p in "${pids[@]}"; do wait "$p" || rc=1; done
    cat "$log".* >"$log"
  else
    (cd "$build" && TMPDIR="$build" "$build/bin/fuzz_$t" "${args[@]}" "$corpus" "$root/tests/fuzz/corpus/$t" >"$log" 2>&1)
    rc=$?
  fi
  secs=$(( $(date +%s) - start ))
  execs=$(grep -h 'stat::number_of_executed_units' "$log" | awk '{s += $2} END {print s + 0}')
  found=$(find "$findings" -type f | wc -l)
  [[ $rc -ne 0 || $found -gt 0 ]] && { status=1; tail -40 "$log"; }
  summary+=("$(printf '%-12s %12s executions %6s s  findings: %s  (exit %s)' "$t" "$execs" "$secs" "$found" "$rc")")
done
echo "== fuzz.sh ($mode $value, $jobs job(s) per target, $(nproc) cores, $(uname -n))"
printf '%s\n' "${summary[@]}"
exit $status
