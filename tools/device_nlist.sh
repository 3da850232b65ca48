#!/usr/bin/env bash
# Runs ON the GPU machine (device tool) with build-dev carried: the fluid neighbour lists
# (-nlist:F) against the row walk, back to back. SPHERIC Test 2 at 4.36 M and 13.29 M particles
# (Spheric2Dam_01M.xml at dp 0.006 and 0.004; symplectic, Wendland, DDT 3, the case's artificial
# viscosity, DBC; cells of h/2 with the default cell skin 0.05) and the small 2D cases (Antoci
# gate, FlexStruc Liao 2D). Every run prints its state hash: a list run must give the row walk's.
# Peak GPU memory per run from nvidia-smi sampled every 100 ms.
# Env: SS_BIN (default build-dev/bin), LISTS (default "0.2 0.4"), ROUNDS (2), SPHERIC_STEPS (200),
#      BIG (1: also 13.29 M), SMALL (1: also the 2D cases), OUT (table folder).
set -u
export LD_LIBRARY_PATH=$PWD/build-dev/lib
b=${SS_BIN:-build-dev/bin}; w=/tmp/wnl; mkdir -p $w
out=${OUT:-/tmp/seaspring_out}; mkdir -p "$out"; table=$out/nlist_table.txt
lists=${LISTS:-0.2 0.4}
nvidia-smi --query-gpu=name --format=csv,noheader | tee -a "$table"
[[ -f $w/s4m.h5 ]] || $b/gencase build-dev/shared-cases/Spheric2Dam_01M.xml $w/s4m -dp:0.006 > /dev/null
[[ ${BIG:-1} == 1 && ! -f $w/s13m.h5 ]] && $b/gencase build-dev/shared-cases/Spheric2Dam_01M.xml $w/s13m -dp:0.004 > /dev/null
if [[ ${SMALL:-1} == 1 ]]; then
  [[ -f $w/ant.h5 ]] || $b/gencase cases/antoci_gate2d/AntociGate2D_Def.xml $w/ant >/dev/null
  [[ -f $w/liao.h5 ]] || $b/gencase build-dev/shared-cases/flexstruc/CaseDambreak2D_FSI_Def.xml $w/liao >/dev/null 2>&1
fi
row() {  # label case args...
  local label=$1 c=$2; shift 2
  nvidia-smi --query-gpu=memory.used --format=csv,noheader,nounits -lms 100 > $w/mem.txt 2>/dev/null &
  local smi=$!
  $b/seaspring -overwrite -gpu -sv:none -progress:0 "$@" $w/$c $w/o_$c > $w/log.txt 2>&1 || { kill $smi; tail -3 $w/log.txt; return; }
  kill $smi; wait $smi 2>/dev/null
  python3 - "$w/o_$c/run.json" "$label" "$w/mem.txt" <<'PY' | tee -a "$TABLE"
import json, sys
r = json.load(open(sys.argv[1]))
mem = [int(x) for x in open(sys.argv[3]).read().split() if x.strip().isdigit()]
print(f"{sys.argv[2]:<24} np={r['particles']['total']:>8} steps={r['steps']:>6} sorts={r['sorts']:>5} lists={r.get('neighbour_list_builds',0):>5}/{r['divides']:<6} "
      f"{1e3*r['loop_time_s']/max(r['steps'],1):8.4f} ms/step {r['ns_per_particle_step']:7.3f} ns/p/s peak={max(mem) if mem else 0:>6} MiB hash={r['state_hash']}")
PY
}
export TABLE=$table
for round in $(seq 1 ${ROUNDS:-2}); do
  for l in 0 $lists; do row "spheric4m nlist $l" s4m -symplectic -wendland -ddt:3 -nsteps:${SPHERIC_STEPS:-200} -nlist:$l; done
  if [[ ${BIG:-1} == 1 ]]; then
    for l in 0 $lists; do row "spheric13m nlist $l" s13m -symplectic -wendland -ddt:3 -nsteps:${BIG_STEPS:-100} -nlist:$l; done
  fi
  if [[ ${SMALL:-1} == 1 ]]; then
    for l in 0 $lists; do row "antoci2d nlist $l" ant -tmax:0.05 -nlist:$l; done
    for l in 0 $lists; do row "liao2d nlist $l" liao -tmax:0.05 -nlist:$l; done
  fi
done
