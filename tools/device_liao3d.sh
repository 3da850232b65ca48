#!/usr/bin/env bash
# Runs ON the GPU machine with build-dev carried: where a step of FlexStruc Liao 3D (DualSPHysics'
# CaseDambreak3D_FSI_Def.xml as shipped, 2.63 M particles, Verlet, laminar+SPS, a 12,250-particle
# VCPM plate) goes: the phase timers (SEASPRING_TIMERS=1, the GPU synchronised after each phase)
# over NSTEPS steps (default 300) and the solids' line (sub-steps per fluid step), for this
# build, for this build with VcpmSurfaceCorrection 0 (the plain lattice) and, when
# build-dev/base/seaspring exists, for that baseline build.
export LD_LIBRARY_PATH=$PWD/build-dev/lib; w=/tmp/l3; mkdir -p $w
nvidia-smi --query-gpu=name --format=csv,noheader
src=build-dev/shared/dualsphysics-cases/flexstruc; cp $src/DambreakGateTimeSeries.csv $w/
cp $src/CaseDambreak3D_FSI_Def.xml $w/new_Def.xml
sed 's|<parameters>|<parameters><parameter key="VcpmSurfaceCorrection" value="0" />|' $w/new_Def.xml > $w/plain_Def.xml
build-dev/bin/gencase $w/new_Def.xml $w/l3_new >/dev/null 2>&1 || echo "gencase failed"
build-dev/bin/gencase $w/plain_Def.xml $w/l3_plain >/dev/null 2>&1 || echo "gencase plain failed"
runs="new:build-dev/bin:new plain:build-dev/bin:plain"
[[ -x build-dev/base/seaspring ]] && runs="$runs base:build-dev/base:new"
for b in $runs; do IFS=: read -r n d c <<<"$b"
  SEASPRING_TIMERS=1 $d/seaspring -gpu -overwrite -sv:none -progress:0 -nsteps:${NSTEPS:-300} $w/l3_$c $w/o_$n > $w/log_$n 2>&1 || tail -3 $w/log_$n
  echo "== $n"; grep -E 'phase times|Finished|Solids:|VCPM sub-step|sub-step factor|corrected' $w/log_$n | cut -c1-220
done
