#!/usr/bin/env bash
# Runs ON the GPU machine (device tool) with build-dev carried: where the time goes.
#  1. SPHERIC Test 2 at 4.4 M (dp 0.006): phase timers over 100 steps, GPU time per kernel
#     (Nsight Compute, 20 steps), and one fluid-force launch in detail (SIMT efficiency,
#     stall reasons, instruction mix).
#  2. Small cases (latency): Antoci 2D (17 k) and FlexStruc Liao 2D (DualSPHysics' input):
#     phase timers, launches per step and GPU busy time against wall time.
# Env: SS_BIN (folder with seaspring and gencase; default build-dev/bin), SS_ARGS (extra
#      solver options), PROFILE_PARTS (default "kernels detail small").
set -u
export LD_LIBRARY_PATH=$PWD/build-dev/lib
b=${SS_BIN:-build-dev/bin}; w=/tmp/w; mkdir -p $w; out=${OUT:-/tmp/out}
parts=${PROFILE_PARTS:-kernels detail small}
args=(-gpu -symplectic -wendland -ddt:3 -sv:none -progress:0 ${SS_ARGS:-})
nvidia-smi --query-gpu=name --format=csv,noheader
per_kernel() {  # csv -> table of GPU time per kernel name
  awk -F'","' 'NR > 1 { k = $5; gsub(/<unnamed>::|seaspring::|cuda::|solver::|physics::/, "", k); sub(/^void /, "", k); sub(/[<(].*/, "", k);
      v = $NF; gsub(/[",]/, "", v); n[k]++; t[k] += v; u = $(NF-1); T += v; N++ }
    END { for (k in n) printf "%-36s %6d launches %12.1f %s\n", k, n[k], t[k], u;
          printf "%-36s %6d launches %12.1f %s\n", "TOTAL", N, T, u }' "$1" | sort -k4 -n -r
}
[[ -f $w/s4m.h5 ]] || $b/gencase build-dev/shared-cases/Spheric2Dam_01M.xml $w/s4m -dp:0.006 > /dev/null
if [[ $parts == *kernels* ]]; then
  echo "== SPHERIC 4.4 M, ${args[*]}"
  SEASPRING_TIMERS=1 $b/seaspring -overwrite "${args[@]}" -nsteps:100 $w/s4m $w/o_t | grep -E "phase|Finished|ns/particle"
  ncu --clock-control none --metrics gpu__time_duration.sum --csv \
    $b/seaspring -overwrite "${args[@]}" -nsteps:20 $w/s4m $w/o_p 2>/dev/null | grep -v '^==' >$w/ncu.csv
  per_kernel $w/ncu.csv; echo "(20 steps and the set-up)"
fi
if [[ $parts == *detail* ]]; then
  ncu --clock-control none --kernel-name-base demangled --kernel-name regex:FluidForcesPass --launch-skip 4 --launch-count 1 \
    --section SpeedOfLight --section Occupancy --section LaunchStats --section WarpStateStats \
    --section InstructionStats --section SchedulerStats --section MemoryWorkloadAnalysis \
    --metrics smsp__thread_inst_executed_per_inst_executed.ratio,smsp__inst_executed.sum,smsp__thread_inst_executed.sum \
    $b/seaspring -overwrite "${args[@]}" -nsteps:5 $w/s4m $w/o_p >$out/ncu_detail.txt 2>&1
  grep -E "Kernel|forEach|Duration|Registers|Achieved Occupancy|Theoretical Occ|Block Size|Warp Cycles Per Issued|Issue Slots|Eligible Warps|Executed Ipc|thread_inst|inst_executed|L1/TEX Hit|L2 Hit|Memory Throughput|Compute \(SM\)|Stall" $out/ncu_detail.txt | head -60
fi
if [[ $parts == *small* ]]; then
  $b/gencase cases/antoci_gate2d/AntociGate2D_Def.xml $w/ant >/dev/null
  $b/gencase build-dev/shared-cases/flexstruc/CaseDambreak2D_FSI_Def.xml $w/liao >/dev/null 2>$w/liao.err || cat $w/liao.err
  for c in ant liao; do
    echo "== small case $c"
    SEASPRING_TIMERS=1 $b/seaspring -overwrite -gpu -sv:none -progress:0 -tmax:0.05 ${SS_ARGS:-} $w/$c $w/o_$c | grep -E "Particles|phase|Finished|ns/particle|steps|Physics|Solid"
    ncu --clock-control none --metrics gpu__time_duration.sum --csv $b/seaspring -overwrite -gpu -sv:none -progress:0 -nsteps:50 $w/$c $w/o_p2 2>/dev/null | grep -v '^==' >$w/ncu_$c.csv
    per_kernel $w/ncu_$c.csv | head -25; echo "(50 steps and the set-up)"
  done
fi
