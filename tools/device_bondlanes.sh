#!/usr/bin/env bash
# Runs ON the GPU machine (device tool) with build-dev carried: the solid sub-cycle's bond lanes
# (physics/vcpm_substep.h, SEASPRING_BOND_LANES). For each round, each case runs with each lane
# count back to back: the Antoci gate 2D and FlexStruc Liao 2D over their first TMAX (default
# 0.05 s; ms per step), and FlexStruc Liao 3D over NSTEPS3D steps (default 300; the solid phase
# of SEASPRING_TIMERS=1, ms per step; 0 skips it). Prints every run's figure and state hash,
# then the medians per case and lane count.
# Env: LANES (default "1 2 4"), ROUNDS (default 3), TMAX, NSTEPS3D, W (work folder).
set -u
export LD_LIBRARY_PATH=$PWD/build-dev/lib
b=build-dev/bin; w=${W:-/tmp/wbl}; mkdir -p $w
nvidia-smi --query-gpu=name --format=csv,noheader
src=build-dev/shared/dualsphysics-cases/flexstruc
[[ -f $w/ant.h5 ]] || $b/gencase cases/antoci_gate2d/AntociGate2D_Def.xml $w/ant >/dev/null
[[ -f $w/liao.h5 ]] || $b/gencase $src/CaseDambreak2D_FSI_Def.xml $w/liao >/dev/null 2>&1
n3=${NSTEPS3D:-300}
if ((n3 > 0)) && [[ ! -f $w/l3.h5 ]]; then
  cp $src/DambreakGateTimeSeries.csv $w/ 2>/dev/null
  $b/gencase $src/CaseDambreak3D_FSI_Def.xml $w/l3 >/dev/null 2>&1 || echo "gencase Liao 3D failed"
fi
res=$w/results.txt; : >$res
for ((r = 1; r <= ${ROUNDS:-3}; ++r)); do
  for l in ${LANES:-1 2 4}; do
    for c in ant liao; do
      SEASPRING_BOND_LANES=$l $b/seaspring -overwrite -gpu -sv:none -progress:0 -tmax:${TMAX:-0.05} $w/$c $w/o_$c >$w/log 2>&1
      steps=$(grep -o '[0-9]* steps to' $w/log | cut -d' ' -f1); loop=$(grep -o 'loop [0-9.]*' $w/log | cut -d' ' -f2)
      hash=$(grep -o 'State hash: [0-9a-f]*' $w/log | cut -d' ' -f3)
      v=$(python3 -c "print('%.4f' % (1000 * $loop / $steps))" 2>/dev/null || echo NA)
      echo "$c lanes=$l round=$r ms_per_step=$v hash=$hash" | tee -a $res
    done
    if ((n3 > 0)); then
      SEASPRING_BOND_LANES=$l SEASPRING_TIMERS=1 $b/seaspring -overwrite -gpu -sv:none -progress:0 -nsteps:$n3 $w/l3 $w/o_l3 >$w/log 2>&1
      sol=$(grep -o 'solid [0-9.]*' $w/log | tail -1 | cut -d' ' -f2)
      hash=$(grep -o 'State hash: [0-9a-f]*' $w/log | cut -d' ' -f3)
      echo "liao3d lanes=$l round=$r solid_ms_per_step=${sol:-NA} hash=$hash" | tee -a $res
      [[ -z $sol ]] && tail -5 $w/log
    fi
  done
done
echo "== medians"
python3 - "$res" <<'EOF'
import sys, collections, statistics
d = collections.defaultdict(list); h = collections.defaultdict(set)
for line in open(sys.argv[1]):
    f = dict(kv.split("=", 1) for kv in line.split()[1:])
    key = (line.split()[0], int(f["lanes"]))
    v = [x for k, x in f.items() if k.endswith("per_step")][0]
    if v != "NA": d[key].append(float(v))
    h[line.split()[0]].add(f["hash"])
base = {}
for (c, l) in sorted(d):
    m = statistics.median(d[(c, l)])
    if l == 1: base[c] = m
    print("  %-7s lanes %2d  %9.4f  (x%.3f of 1 lane)  n=%d" % (c, l, m, m / base.get(c, m), len(d[(c, l)])))
for c, s in h.items(): print("  %-7s hashes: %s" % (c, " ".join(sorted(s))) + ("" if len(s) == 1 else "  DIFFER"))
EOF
