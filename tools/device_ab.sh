#!/usr/bin/env bash
# Runs ON the GPU machine (device tool), from the repository root: several builds timed against
# each other on one device, runs alternated build by build within each round (the twentieth
# session's method for variants that tools/bench.sh, one base against one new build, cannot
# compare in one call). Each build NAME comes as build-dev/v_NAME.tar.xz holding
# vb/NAME/{seaspring,gencase} (or already as vb/NAME/), with build-dev/lib carried; the first
# build generates the cases and writes the restart file. Prints the raw rows, then per case the
# medians, the ratios to the first build and the state hashes (a pair of exact variants must
# show one hash).
#   VARS="base new" CASES="s4 sps l3" LIAO=1 ROUNDS=2 OUT=$OUT tools/device_ab.sh
# Cases: s4   SPHERIC Test 2 at dp 0.006 (4,360,716 particles), S4STEPS (150) steps from the
#             start, symplectic + Wendland + DDT 3 + the case's artificial viscosity: ns/particle/step
#        s1   the same at dp 0.01 (1,116,258), S1STEPS (300) steps
#        s13  the same at dp 0.004 (13,292,664), S13STEPS (80) steps
#        late the 1.12 M case, 300 steps from a restart file at t = 0.6 s (needs LATE=1)
#        sps  s4 with -viscolamsps:1e-6
#        s4h5 s4's first 0.02 s writing part files (-sv:h5; three outputs): loop seconds
#        l3   FlexStruc Liao 3D as shipped, first 0.02 s: loop seconds (needs LIAO=1 and
#             build-dev/shared)
#        db3  DualSPHysics' 3D dam break CaseDambreak_Def.xml at dp 0.004 (about 1.6 M particles,
#             h = 1.73 dp, as shipped: Verlet, artificial viscosity), DB3STEPS (400) steps
#        db3l the same at its shipped dp 0.0085 (171 k), first 0.3 s: loop seconds
#        db3x the same, first 1.0 s (the front has hit the obstacle and the far wall): loop seconds
#        l2   FlexStruc Liao 2D as shipped (28 k), first 0.1 s: loop seconds (needs LIAO=1)
#        ant  the Antoci gate 2D (cases/antoci_gate2d, 17 k), first 0.1 s: loop seconds
#        v2d  DualSPHysics' CaseDambreakVal2D as shipped (dp 0.01), first 0.5 s: loop seconds
#        rtd  DualSPHysics' FlexStruc CaseRollingTankDeep as shipped, first 0.3 s: loop seconds
# Variants of one build: ARGS_NAME (extra solver options of variant NAME's runs) and BIN_NAME
# (the build it runs, default NAME) and ENV_NAME (environment settings of its runs, e.g.
# ENV_t64="SEASPRING_PAIR_THREADS=64"), e.g. VARS="third dp" BIN_third=new BIN_dp=new
# ARGS_third=-cellmode:third ARGS_dp=-cellmode:dp with build-dev/v_new.tar.xz.
# Env: VARS, CASES (default "s4 s1"), ROUNDS (2), DEADLINE (500 s: no run starts after it),
#      OUT (ab.csv: case,var,round,value,hash,output_s — run.json output_time_s).
set -u
export LD_LIBRARY_PATH=$PWD/build-dev/lib
binof() { local b="BIN_$1"; echo "${!b:-$1}"; }
argsof() { local a="ARGS_$1"; echo "${!a:-}"; }
envof() { local a="ENV_$1"; echo "${!a:-}"; }
for v in $VARS; do b=$(binof $v); [[ -f build-dev/v_$b.tar.xz && ! -d vb/$b ]] && tar -xJf build-dev/v_$b.tar.xz; done
first=$(binof ${VARS%% *})
W=/tmp/wab; mkdir -p $W
nvidia-smi --query-gpu=name --format=csv,noheader
G=vb/$first/gencase
[[ -f $W/s1m.h5 ]] || $G build-dev/shared-cases/Spheric2Dam_01M.xml $W/s1m >/dev/null
[[ -f $W/s4m.h5 ]] || $G build-dev/shared-cases/Spheric2Dam_01M.xml $W/s4m -dp:0.006 >/dev/null
[[ " ${CASES:-} " == *" s13 "* && ! -f $W/s13m.h5 ]] && $G build-dev/shared-cases/Spheric2Dam_01M.xml $W/s13m -dp:0.004 >/dev/null
A="-gpu -sv:none -progress:0 -symplectic -wendland -ddt:3"
if [[ -n "${LATE:-}" ]]; then
  [[ -f $W/late/restart.h5 ]] || vb/$first/seaspring $A -tmax:0.6 -checkpoint:0.6 $W/s1m $W/late > $W/late.log 2>&1
  LSTEP=$(grep -o "checkpoint t=[0-9.e+-]* s, step [0-9]*" $W/late.log | tail -n 1 | grep -o "[0-9]*$"); echo "late step $LSTEP"
fi
if [[ -n "${LIAO:-}" ]]; then [[ -f $W/l3d.h5 ]] || vb/$first/gencase build-dev/shared/dualsphysics-cases/flexstruc/CaseDambreak3D_FSI_Def.xml $W/l3d >/dev/null 2>&1; fi
if [[ -n "${LIAO:-}" && " ${CASES:-} " == *" l2 "* && ! -f $W/l2d.h5 ]]; then
  cp build-dev/shared/dualsphysics-cases/flexstruc/DambreakGateTimeSeries.csv $W/
  vb/$first/gencase build-dev/shared/dualsphysics-cases/flexstruc/CaseDambreak2D_FSI_Def.xml $W/l2d >/dev/null 2>&1
fi
[[ " ${CASES:-} " == *" ant "* && ! -f $W/ant.h5 ]] && vb/$first/gencase cases/antoci_gate2d/AntociGate2D_Def.xml $W/ant >/dev/null 2>&1
[[ " ${CASES:-} " == *" v2d "* && ! -f $W/v2d.h5 ]] && vb/$first/gencase build-dev/shared/dualsphysics-cases/CaseDambreakVal2D_Def.xml $W/v2d >/dev/null 2>&1
[[ " ${CASES:-} " == *" rtd "* && ! -f $W/rtd.h5 ]] && vb/$first/gencase build-dev/shared/dualsphysics-cases/flexstruc/CaseRollingTankDeep_Def.xml $W/rtd >/dev/null 2>&1
if [[ " ${CASES:-} " == *" db3"* ]]; then
  [[ -f $W/db3.h5 ]] || vb/$first/gencase build-dev/shared/dualsphysics-cases/CaseDambreak_Def.xml $W/db3 -dp:0.004 >/dev/null 2>&1
  [[ -f $W/db3l.h5 ]] || vb/$first/gencase build-dev/shared/dualsphysics-cases/CaseDambreak_Def.xml $W/db3l >/dev/null 2>&1
fi
echo "case,var,round,value,hash,output_s" > $OUT/ab.csv
rec() { python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); k=sys.argv[2]; print(r["ns_per_particle_step"] if k=="ns" else r["loop_time_s"], r.get("state_hash",""), r.get("output_time_s",""))' $1/run.json $2; }
t_end=$(( $(date +%s) + ${DEADLINE:-500} ))
for r in $(seq 1 ${ROUNDS:-2}); do
 for c in ${CASES:-s4 s1}; do
  for v in $VARS; do
   (( $(date +%s) > t_end )) && break 3
   B="env $(envof $v) vb/$(binof $v)/seaspring"; o=$W/o_${c}_$v; rm -rf $o; X=$(argsof $v)
   case $c in
    s4) $B $A $X -nsteps:${S4STEPS:-150} $W/s4m $o >/dev/null 2>&1; k=ns;;
    s1) $B $A $X -nsteps:${S1STEPS:-300} $W/s1m $o >/dev/null 2>&1; k=ns;;
    s13) $B $A $X -nsteps:${S13STEPS:-80} $W/s13m $o >/dev/null 2>&1; k=ns;;
    sps) $B $A $X -viscolamsps:1e-6 -nsteps:${S4STEPS:-150} $W/s4m $o >/dev/null 2>&1; k=ns;;
    s4h5) $B ${A/-sv:none/-sv:h5} $X -tmax:0.02 $W/s4m $o >/dev/null 2>&1; k=loop;;
    late) $B $A $X -restart:$W/late/restart.h5 -nsteps:$((LSTEP+300)) $W/s1m $o >/dev/null 2>&1; k=ns;;
    l3) $B -gpu -sv:none -progress:0 $X -tmax:0.02 $W/l3d $o >/dev/null 2>&1; k=loop;;
    db3) $B -gpu -sv:none -progress:0 $X -nsteps:${DB3STEPS:-400} $W/db3 $o >/dev/null 2>&1; k=ns;;
    db3l) $B -gpu -sv:none -progress:0 $X -tmax:0.3 $W/db3l $o >/dev/null 2>&1; k=loop;;
    db3x) $B -gpu -sv:none -progress:0 $X -tmax:1.0 $W/db3l $o >/dev/null 2>&1; k=loop;;
    l2) $B -gpu -sv:none -progress:0 $X -tmax:0.1 $W/l2d $o >/dev/null 2>&1; k=loop;;
    ant) $B -gpu -sv:none -progress:0 $X -tmax:0.1 $W/ant $o >/dev/null 2>&1; k=loop;;
    v2d) $B -gpu -sv:none -progress:0 $X -tmax:0.5 $W/v2d $o >/dev/null 2>&1; k=loop;;
    rtd) $B -gpu -sv:none -progress:0 $X -tmax:0.3 $W/rtd $o >/dev/null 2>&1; k=loop;;
   esac
   [[ -f $o/run.json ]] || { echo "$c,$v,$r: no run.json"; continue; }
   read val h os < <(rec $o $k); echo "$c,$v,$r,$val,$h,$os" | tee -a $OUT/ab.csv
  done
 done
done
python3 - $OUT/ab.csv <<'P'
import csv,sys,statistics as st
rows=list(csv.DictReader(open(sys.argv[1])))
cases=[];vars_=[]
for r in rows:
    if r['case'] not in cases: cases.append(r['case'])
    if r['var'] not in vars_: vars_.append(r['var'])
print("case," + ",".join(vars_) + ",ratios vs " + vars_[0])
for c in cases:
    med={v: st.median([float(r['value']) for r in rows if r['case']==c and r['var']==v] or [float('nan')]) for v in vars_}
    hs={v: {r['hash'] for r in rows if r['case']==c and r['var']==v} for v in vars_}
    print(c + "," + ",".join(f"{med[v]:.4f}" for v in vars_) + "," + ",".join(f"{med[v]/med[vars_[0]]:.3f}" for v in vars_[1:]) + "  hashes " + " ".join(f"{v}:{'/'.join(sorted(x))}" for v,x in hs.items()))
P
