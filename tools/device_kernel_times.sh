#!/usr/bin/env bash
# Runs ON the GPU machine (device tool) with build-dev carried: time per step by phase
# (SEASPRING_TIMERS=1) and by kernel (Nsight Compute, gpu__time_duration over 10 whole
# steps) on SPHERIC Test 2 at 4.4 M particles (dp 0.006).
# Env: SS_BIN (folder with seaspring and gencase; default build-dev/bin), SS_ARGS (extra
# solver options, e.g. -cellmode:third).
set -u
export LD_LIBRARY_PATH=$PWD/build-dev/lib
b=${SS_BIN:-build-dev/bin}; w=/tmp/w; mkdir -p $w
args=(-gpu -symplectic -wendland -ddt:3 -sv:none -progress:0 ${SS_ARGS:-})
nvidia-smi --query-gpu=name --format=csv,noheader
[[ -f $w/s4m.h5 ]] || $b/gencase build-dev/shared-cases/Spheric2Dam_01M.xml $w/s4m -dp:0.006 > /dev/null
SEASPRING_TIMERS=1 $b/seaspring -overwrite "${args[@]}" -nsteps:100 $w/s4m $w/o_t | grep -E "phase|Finished"
# Steps 11-20: launches of 10 steps after 10 warm-up steps (launches per step counted first).
ncu --clock-control none --metrics gpu__time_duration.sum --csv \
  $b/seaspring -overwrite "${args[@]}" -nsteps:20 $w/s4m $w/o_p 2>/dev/null | grep -v '^==' >$w/ncu.csv
awk -F'","' 'NR > 1 { k = $5; gsub(/<unnamed>::|seaspring::|cuda::/, "", k); sub(/^void /, "", k); sub(/[<(].*/, "", k);
    v = $NF; gsub(/[",]/, "", v); n[k]++; t[k] += v; u = $(NF-1) }
  END { for (k in n) printf "%-36s %5d launches %12.1f %s\n", k, n[k], t[k], u }' $w/ncu.csv | sort -k4 -n -r
echo "(all 20 steps and the set-up; divide by 20 for a per-step figure)"
