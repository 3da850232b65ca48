#!/usr/bin/env bash
# Runs ON the GPU machine (device tool) with build-dev carried: the neighbour-cell skin
# (-skin:F) against speed. PARTS (default "spheric small"):
#   spheric  SPHERIC Test 2 at 4.4 M (symplectic, Wendland, DDT 3, artificial viscosity), from its
#            lattice (sorts are rare there: the skin's cost without its gain);
#   small    the small 2D cases (Antoci gate, FlexStruc Liao), first 0.05 s;
#   sluice   the 3D sluice gate (laminar+SPS) at SLUICE_DP (0.004) from t = 0 to SLUICE_T (1.0 s),
#            through its impacts, where a late divide sorts at most divides (the skin's gain);
#   fsi3d    FlexStruc Liao 3D (2.63 M, Verlet, SPS, mDBC, VCPM plate), first 0.02 s (needs
#            build-dev/shared carried).
# Each skin in turn, ROUNDS rounds (default 2); with BASE_BIN, a baseline build's run at its
# default skin first in each part. A different skin is a different neighbour order (sorts at
# other steps), so each skin has its own state hash.
# Env: SS_BIN (default build-dev/bin), BASE_BIN, SKINS (default "0 0.05 0.1 0.2"), SPHERIC_STEPS (200).
set -u
export LD_LIBRARY_PATH=$PWD/build-dev/lib
b=${SS_BIN:-build-dev/bin}; w=/tmp/w; mkdir -p $w
skins=${SKINS:-0 0.05 0.1 0.2}
parts=" ${PARTS:-spheric small} "
nvidia-smi --query-gpu=name --format=csv,noheader
want() { [[ $parts == *" $1 "* ]]; }
if want spheric; then
  [[ -f $w/s4m.h5 ]] || $b/gencase build-dev/shared-cases/Spheric2Dam_01M.xml $w/s4m -dp:0.006 > /dev/null
fi
if want small; then
  [[ -f $w/ant.h5 ]] || $b/gencase cases/antoci_gate2d/AntociGate2D_Def.xml $w/ant >/dev/null
  [[ -f $w/liao.h5 ]] || $b/gencase build-dev/shared-cases/flexstruc/CaseDambreak2D_FSI_Def.xml $w/liao >/dev/null 2>&1
fi
sdp=${SLUICE_DP:-0.004}
if want fsi3d; then
  [[ -f $w/liao3d.h5 ]] || $b/gencase build-dev/shared/dualsphysics-cases/flexstruc/CaseDambreak3D_FSI_Def.xml $w/liao3d >/dev/null 2>&1
fi
if want sluice; then
  [[ -f $w/sluice.h5 ]] || $b/gencase cases/sluice_gate/SluiceGate3D_Def.xml $w/sluice -dp:$sdp >/dev/null
fi
base=${BASE_BIN:-}
row() {  # label case args... (BIN=path: another build)
  local label=$1 c=$2; shift 2
  ${BIN:-$b}/seaspring -overwrite -gpu -sv:none -progress:0 "$@" $w/$c $w/o_$c > $w/log.txt 2>&1 || { tail -3 $w/log.txt; return; }
  python3 - "$w/o_$c/run.json" "$label" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
print(f"{sys.argv[2]:<28} np={r['particles']['total']:>8} steps={r['steps']:>6} sorts={r['sorts']:>5}/{r['divides']:<6} "
      f"loop={r['loop_time_s']:8.3f}s  {1e3*r['loop_time_s']/max(r['steps'],1):8.4f} ms/step  {r['ns_per_particle_step']:8.3f} ns/p/s  hash={r['state_hash']}")
PY
}
for ((round = 1; round <= ${ROUNDS:-2}; ++round)); do
  if want sluice; then
    [[ -n $base ]] && BIN=$base row "BASE sluice dp $sdp" sluice -tmax:${SLUICE_T:-1.0}
    for s in $skins; do row "sluice dp $sdp skin $s" sluice -tmax:${SLUICE_T:-1.0} -skin:$s; done
  fi
  if want fsi3d; then
    [[ -n $base ]] && BIN=$base row "BASE liao3d" liao3d -tmax:0.02
    for s in $skins; do row "liao3d skin $s" liao3d -tmax:0.02 -skin:$s; done
  fi
  if want spheric; then
    [[ -n $base ]] && BIN=$base row "BASE spheric4m" s4m -symplectic -wendland -ddt:3 -nsteps:${SPHERIC_STEPS:-200}
    for s in $skins; do row "spheric4m skin $s" s4m -symplectic -wendland -ddt:3 -nsteps:${SPHERIC_STEPS:-200} -skin:$s; done
  fi
  if want small; then
    [[ -n $base ]] && BIN=$base row "BASE antoci2d" ant -tmax:0.05
    for s in $skins; do row "antoci2d skin $s" ant -tmax:0.05 -skin:$s; done
    [[ -n $base ]] && BIN=$base row "BASE liao2d" liao -tmax:0.05
    for s in $skins; do row "liao2d skin $s" liao -tmax:0.05 -skin:$s; done
  fi
done
