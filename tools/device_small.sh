#!/usr/bin/env bash
# Runs ON the GPU machine (device tool) with build-dev carried: where a small case's step goes.
# Antoci gate 2D and FlexStruc Liao 2D: phase timers (SEASPRING_TIMERS=1, the GPU synchronised
# after each phase), and the GPU time and launches per kernel over 200 steps (Nsight Compute)
# against the wall time of the same steps without the profiler. Caches are not flushed between
# kernels (--cache-control none): ncu's default flush gives cold-cache times, which for these
# latency-bound kernels are up to 2x the real ones.
# Env: SS_BIN (default build-dev/bin), CASES (default "ant liao"), W (work folder, default /tmp/w;
# one per binary when their case formats differ).
set -u
export LD_LIBRARY_PATH=$PWD/build-dev/lib
b=${SS_BIN:-build-dev/bin}; w=${W:-/tmp/w}; mkdir -p $w
nvidia-smi --query-gpu=name --format=csv,noheader
[[ -f $w/ant.h5 ]] || $b/gencase cases/antoci_gate2d/AntociGate2D_Def.xml $w/ant >/dev/null
liao_xml=""
for d in build-dev/shared-cases build-dev/shared/dualsphysics-cases ../shared/dualsphysics-cases; do
  [[ -f $d/flexstruc/CaseDambreak2D_FSI_Def.xml ]] && { liao_xml=$d/flexstruc/CaseDambreak2D_FSI_Def.xml; break; }
done
[[ -n $liao_xml ]] || { echo "device_small.sh: CaseDambreak2D_FSI_Def.xml not found (build-dev/shared-cases, build-dev/shared/dualsphysics-cases, ../shared)" >&2; exit 1; }
[[ -f $w/liao.h5 ]] || $b/gencase $liao_xml $w/liao >/dev/null 2>&1
for c in ${CASES:-ant liao}; do
  echo "== $c"
  SEASPRING_TIMERS=1 $b/seaspring -overwrite -gpu -sv:none -progress:0 -nsteps:2000 $w/$c $w/o_$c | grep -E "phase|Finished"
  $b/seaspring -overwrite -gpu -sv:none -progress:0 -nsteps:2000 $w/$c $w/o_$c | grep -E "Finished"
  ncu --clock-control none --cache-control none --metrics gpu__time_duration.sum --csv $b/seaspring -overwrite -gpu -sv:none -progress:0 -nsteps:200 $w/$c $w/o_p 2>/dev/null | grep -v '^==' >$w/ncu_$c.csv
  awk -F'","' 'NR > 1 { k = $5; gsub(/<unnamed>::|seaspring::|cuda::|solver::|physics::/, "", k); sub(/^void /, "", k);
      if (k ~ /^forEachKernel/) { sub(/^forEachKernel<[0-9]+, /, "", k) } sub(/[<(].*/, "", k);
      v = $NF; gsub(/[",]/, "", v); n[k]++; t[k] += v; T += v; N++ }
    END { for (k in n) printf "  %-34s %6d launches %10.1f us\n", k, n[k], t[k] / 1000;
          printf "  %-34s %6d launches %10.1f us  (200 steps and the set-up)\n", "TOTAL", N, T / 1000 }' $w/ncu_$c.csv | sort -k4 -n -r | head -24
done
