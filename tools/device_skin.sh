#!/usr/bin/env bash
# Runs ON the GPU machine (device tool) with build-dev carried: the neighbour-cell skin
# (-skin:F) against speed. SPHERIC Test 2 at 4.4 M (symplectic, Wendland, DDT 3, artificial
# viscosity) and the small 2D cases (Antoci gate, FlexStruc Liao), each skin in turn.
# Env: SS_BIN (default build-dev/bin), SKINS (default "0 0.05 0.1 0.2"), SPHERIC_STEPS (200).
set -u
export LD_LIBRARY_PATH=$PWD/build-dev/lib
b=${SS_BIN:-build-dev/bin}; w=/tmp/w; mkdir -p $w
skins=${SKINS:-0 0.05 0.1 0.2}
nvidia-smi --query-gpu=name --format=csv,noheader
[[ -f $w/s4m.h5 ]] || $b/gencase build-dev/shared-cases/Spheric2Dam_01M.xml $w/s4m -dp:0.006 > /dev/null
[[ -f $w/ant.h5 ]] || $b/gencase cases/antoci_gate2d/AntociGate2D_Def.xml $w/ant >/dev/null
[[ -f $w/liao.h5 ]] || $b/gencase build-dev/shared-cases/flexstruc/CaseDambreak2D_FSI_Def.xml $w/liao >/dev/null 2>&1
row() {  # label case args...
  local label=$1 c=$2; shift 2
  $b/seaspring -overwrite -gpu -sv:none -progress:0 "$@" $w/$c $w/o_$c > $w/log.txt 2>&1 || { tail -3 $w/log.txt; return; }
  python3 - "$w/o_$c/run.json" "$label" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
print(f"{sys.argv[2]:<28} np={r['particles']['total']:>8} steps={r['steps']:>6} sorts={r['sorts']:>5}/{r['divides']:<6} "
      f"loop={r['loop_time_s']:8.3f}s  {1e3*r['loop_time_s']/max(r['steps'],1):8.4f} ms/step  {r['ns_per_particle_step']:8.3f} ns/p/s  hash={r['state_hash']}")
PY
}
for round in 1 2; do
  for s in $skins; do row "spheric4m skin $s" s4m -symplectic -wendland -ddt:3 -nsteps:${SPHERIC_STEPS:-200} -skin:$s; done
  for s in $skins 0.3; do row "antoci2d skin $s" ant -tmax:0.05 -skin:$s; done
  for s in $skins 0.3; do row "liao2d skin $s" liao -tmax:0.05 -skin:$s; done
done
