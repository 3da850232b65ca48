#!/usr/bin/env bash
# Runs ON the GPU machine (device tool) with the binaries and build-dev/lib carried: the SASS of
# one fluid pair launch with its executed instruction counts (Nsight Compute's source page), for
# counting where the fluid pair kernel's instructions go. SPHERIC Test 2 at DualSPHysics'
# Spheric2Dam_01M.xml (1.1 M particles; symplectic, Wendland, DDT 3, artificial viscosity) unless
# ARGS says otherwise.
# Env: SS_BIN (folder with seaspring and gencase, default build-dev/bin), W (work folder),
#      ARGS (physics options), SKIP (launches skipped, default 4), OUT (sass.csv and the details).
set -u
export LD_LIBRARY_PATH=$PWD/build-dev/lib
b=${SS_BIN:-build-dev/bin}; w=${W:-/tmp/wfs}; out=${OUT:-$w}; mkdir -p "$w" "$out"
nvidia-smi --query-gpu=name --format=csv,noheader
[[ -f $w/s1m.h5 ]] || $b/gencase build-dev/shared-cases/Spheric2Dam_01M.xml $w/s1m >/dev/null
args=${ARGS:--symplectic -wendland -ddt:3}
rm -f $w/f.ncu-rep
ncu --clock-control none --kernel-name-base demangled --kernel-name regex:FluidLanesPass \
  --launch-skip "${SKIP:-4}" --launch-count 1 --section SourceCounters --section LaunchStats \
  --section Occupancy --section SpeedOfLight --section InstructionStats --section WarpStateStats \
  --import-source no -o $w/f $b/seaspring -overwrite -gpu -sv:none -progress:0 $args -nsteps:5 $w/s1m $w/o >/dev/null 2>&1
ncu -i $w/f.ncu-rep --page details >$out/fluid_details.txt 2>&1
grep -E "Duration|Registers|Achieved Occ|Theoretical Occ|Executed Ipc|Issue Slots|Eligible|Warp Cycles Per Issued|Avg. Active Threads|Avg. Not Predicated" $out/fluid_details.txt | head -20
ncu -i $w/f.ncu-rep --page source --csv --print-source sass >$out/fluid_sass.csv 2>/dev/null
wc -c $out/fluid_sass.csv
