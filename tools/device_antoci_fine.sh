#!/usr/bin/env bash
# Runs ON the GPU machine with build-dev carried: the Antoci gate 2D at the validation's fine dp
# (0.000625) to 0.4 s, as shipped and with one parameter changed per variant (VARIANTS, "name:key=value"
# items; default: the sub-step coefficient and the laminar lattice correction), one line each:
# how far it ran and why it stopped.
export LD_LIBRARY_PATH=$PWD/build-dev/lib; b=build-dev/bin; w=/tmp/af; mkdir -p $w
nvidia-smi --query-gpu=name --format=csv,noheader
vars=${VARIANTS:-"default: dtcoef0.6:VcpmDtCoef=0.6 lat0:LaminarLatticeCorrection=0"}
for v in $vars; do
  n=${v%%:*}; kv=${v#*:}; x=cases/antoci_gate2d/AntociGate2D_Def.xml
  if [[ -n "$kv" ]]; then
    sed "s|<parameters>|<parameters><parameter key=\"${kv%%=*}\" value=\"${kv#*=}\" />|" $x > $w/${n}_Def.xml
  else cp $x $w/${n}_Def.xml; fi
  $b/gencase $w/${n}_Def.xml $w/$n -dp:0.000625 > /dev/null 2>&1 || { echo "$n: gencase failed"; continue; }
  $b/seaspring -gpu -overwrite -sv:none -progress:0 -tmax:${TMAX:-0.4} $w/$n $w/o_$n > $w/log_$n 2>&1
  echo "$n (rc $?): $(grep -o -E 'Finished.*wall|Stopped.*wall' $w/log_$n | head -1) $(grep -o 'error: blow-up.*step [0-9]*' $w/log_$n | head -1) $(grep -o 'VCPM sub-step [0-9.e-]* s' $w/log_$n)"
done
