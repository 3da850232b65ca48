#!/usr/bin/env bash
# Runs ON the GPU machine with build-dev carried: FlexStruc Liao 2D (DualSPHysics' case as shipped),
# first 0.05 s, three rounds alternated: this build (corrected lattice, the default), this build with
# VcpmSurfaceCorrection 0, and an older build in build-dev/base_old/base (its own gencase).
export LD_LIBRARY_PATH=$PWD/build-dev/lib; w=/tmp/lc; mkdir -p $w; nvidia-smi --query-gpu=name --format=csv,noheader
src=build-dev/shared-cases/flexstruc; cp $src/DambreakGateTimeSeries.csv $w/
cp $src/CaseDambreak2D_FSI_Def.xml $w/new_Def.xml; cp $w/new_Def.xml $w/old_Def.xml
sed 's|<parameters>|<parameters><parameter key="VcpmSurfaceCorrection" value="0" />|' $w/new_Def.xml > $w/plain_Def.xml
runs="new:build-dev/bin plain:build-dev/bin old:build-dev/base_old/base"
for b in $runs; do n=${b%%:*}; d=${b#*:}; $d/gencase $w/${n}_Def.xml $w/liao_$n >/dev/null 2>&1 || echo "gencase $n failed"; done
for r in 1 2 3; do for b in $runs; do n=${b%%:*}; d=${b#*:}
$d/seaspring -gpu -overwrite -sv:none -progress:0 -tmax:0.05 $w/liao_$n $w/o_$n > $w/log_$n 2>&1 || tail -2 $w/log_$n
echo "$n: $(grep -o 'steps to t=[0-9.]* s' $w/log_$n) $(grep -o 'loop [0-9.]* s' $w/log_$n) $(grep -o 'VCPM sub-step [0-9.e-]* s' $w/log_$n) $(grep -o 'Solids: .*sub-steps' $w/log_$n)"; done; done
