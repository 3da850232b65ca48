#!/usr/bin/env bash
# Runs ON the GPU machine (device tool) with build-dev carried: phase timers at 1.1 M and
# 4.4 M particles (SPHERIC Test 2) and an Nsight Compute profile of one fluid-force launch.
set -u
export LD_LIBRARY_PATH=$PWD/build-dev/lib
b=build-dev/bin; w=/tmp/w; mkdir -p $w
$b/gencase build-dev/shared-cases/Spheric2Dam_01M.xml $w/s1m -dp:0.01 > /dev/null
for c in s1m; do SEASPRING_TIMERS=1 $b/seaspring -gpu -symplectic -ddt:3 -tmax:0.005 -sv:none -progress:0 $w/$c $w/o_$c | grep -E "phase|Finished"; done
ncu --clock-control none --kernel-name regex:fluidForcesKernel --launch-skip 4 --launch-count 1 \
  --section SpeedOfLight --section Occupancy --section LaunchStats --section WarpStateStats \
  --section InstructionStats --section SchedulerStats --section SourceCounters \
  $b/seaspring -gpu -symplectic -ddt:3 -nsteps:4 -sv:none -progress:0 $w/s1m $w/o_p 2>&1 | grep -v "^==PROF==" |
  grep -E "Throughput|Duration|Registers|Occupancy|Block Size|Warp Cycles|Issued|Eligible|Active Warps|Branch|Divergen|Stall|Executed Ipc|Instructions|Efficiency|thread" | head -60
