#!/usr/bin/env bash
# Runs ON the GPU machine (device tool) with the binaries and build-dev/lib carried: the SASS of
# one launch with its executed instruction counts (Nsight Compute's source page), for counting
# where a kernel's instructions go. Default: the fluid pair launch of SPHERIC Test 2 at
# DualSPHysics' Spheric2Dam_01M.xml (1.1 M particles; symplectic, Wendland, DDT 3, artificial
# viscosity). CASE=antoci KERNEL=sequenceBlockKernel: the solids' single-block sub-cycle of the
# Antoci gate 2D (cases/antoci_gate2d, its own options). CASE=liao3d: FlexStruc Liao 3D as shipped
# (Verlet, laminar+SPS; needs build-dev/shared).
# Env: SS_BIN (folder with seaspring and gencase, default build-dev/bin), W (work folder),
#      CASE (spheric, antoci or liao3d), KERNEL (Nsight Compute name regex, default FluidLanesPass),
#      ARGS (physics options), SKIP (launches skipped, default 4), OUT (sass.csv and the details).
set -u
export LD_LIBRARY_PATH=$PWD/build-dev/lib
b=${SS_BIN:-build-dev/bin}; w=${W:-/tmp/wfs}; out=${OUT:-$w}; mkdir -p "$w" "$out"
nvidia-smi --query-gpu=name --format=csv,noheader
if [[ ${CASE:-spheric} == liao3d ]]; then
  name=l3d; [[ -f $w/l3d.h5 ]] || $b/gencase build-dev/shared/dualsphysics-cases/flexstruc/CaseDambreak3D_FSI_Def.xml $w/l3d >/dev/null 2>&1
  args=${ARGS:-}; nsteps=8
elif [[ ${CASE:-spheric} == antoci ]]; then
  name=ant; [[ -f $w/ant.h5 ]] || $b/gencase cases/antoci_gate2d/AntociGate2D_Def.xml $w/ant >/dev/null
  args=${ARGS:-}; nsteps=300
else
  name=s1m; [[ -f $w/s1m.h5 ]] || $b/gencase build-dev/shared-cases/Spheric2Dam_01M.xml $w/s1m >/dev/null
  args=${ARGS:--symplectic -wendland -ddt:3}; nsteps=5
fi
rm -f $w/f.ncu-rep
ncu --clock-control none --kernel-name-base demangled --kernel-name regex:"${KERNEL:-FluidLanesPass}" \
  --launch-skip "${SKIP:-4}" --launch-count 1 --section SourceCounters --section LaunchStats \
  --section Occupancy --section SpeedOfLight --section InstructionStats --section WarpStateStats \
  --import-source no -o $w/f $b/seaspring -overwrite -gpu -sv:none -progress:0 $args -nsteps:$nsteps $w/$name $w/o >/dev/null 2>&1
ncu -i $w/f.ncu-rep --page details >$out/details.txt 2>&1
grep -E "Duration|Registers|Achieved Occ|Theoretical Occ|Executed Ipc|Issue Slots|Eligible|Warp Cycles Per Issued|Avg. Active Threads|Avg. Not Predicated" $out/details.txt | head -20
ncu -i $w/f.ncu-rep --page source --csv --print-source sass >$out/sass.csv 2>/dev/null
wc -c $out/sass.csv
