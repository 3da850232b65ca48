set -u
export LD_LIBRARY_PATH=$PWD/build-dev/lib
b=build-dev/bin; w=/tmp/w; mkdir -p $w
$b/gencase build-dev/shared-cases/Spheric2Dam_01M.xml $w/s1m -dp:0.01 > /dev/null
$b/gencase build-dev/shared-cases/Spheric2Dam_01M.xml $w/s4m -dp:0.006 > /dev/null
for c in s1m s4m; do SEASPRING_TIMERS=1 $b/seaspring -gpu -symplectic -ddt:3 -tmax:0.02 -sv:none -progress:0 $w/$c $w/o_$c | grep -E "phase|Finished|Particles"; done
ncu --clock-control none --kernel-name regex:fluidForcesKernel --launch-skip 4 --launch-count 1 --section SpeedOfLight --section Occupancy --section LaunchStats --section MemoryWorkloadAnalysis $b/seaspring -gpu -symplectic -ddt:3 -nsteps:4 -sv:none -progress:0 $w/s1m $w/o_p 2>&1 | grep -v "^==PROF==" | grep -E "Throughput|Duration|Registers|Occupancy|Block Size|L1|L2|DRAM|Warp|Compute|Memory" | head -40
