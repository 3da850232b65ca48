#!/usr/bin/env bash
# Pair lanes (-pairlanes, physics/fluid_interaction.h) measured on the GPU machine: the small
# cases of issue 16 (Antoci gate 2D over its first 0.05 s; FlexStruc Liao 2D, DualSPHysics'
# CaseDambreak2D_FSI_Def.xml, over 0.05 s) and SPHERIC Test 2 at 116,658 and 1,116,258 particles
# (DualSPHysics' Spheric2Dam_100K.xml and _01M.xml, fixed step counts; optionally `sphdp`, the
# 100K definition at -dp:LANES_SPH_DP, default 0.0175: about 114 k fluid particles), each with several lane
# counts, all runs of a round back to back and the rounds repeated. Prints one table last: the
# median figure per case and lane count, its ratio to one lane, and the state hashes.
# Runs from the repository root with build-dev carried (tools/device_build.sh).
#   tools/device_lanes.sh [ROUNDS]       (default 3)
# Env: SS_BIN (default build-dev/bin), OUT (the raw CSV and the logs; default /tmp/seaspring_lanes),
#      LANES_CASES (default "antoci2d liao2d sph100k sph1m"), LANES_BACKEND (default -gpu).
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
rounds=${1:-3}
bin=${SS_BIN:-$root/build-dev/bin}
[[ -d $root/build-dev/lib ]] && export LD_LIBRARY_PATH=$root/build-dev/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
out=${OUT:-/tmp/seaspring_lanes}
mkdir -p "$out"
work=$(mktemp -d /tmp/lanes.XXXX)
shared=$root/build-dev/shared/dualsphysics-cases
[[ -d $shared ]] || shared=$root/../shared/dualsphysics-cases
read -r -a backend <<<"${LANES_BACKEND:--gpu}"
cases=${LANES_CASES:-antoci2d liao2d sph100k sph1m}
raw=$out/lanes.csv
echo "case,lanes,round,steps,physical_time_s,loop_time_s,ms_per_step,state_hash,options" >"$raw"

gen() { "$bin/gencase" "$@" >"$work/gen.log" 2>&1 || { echo "gencase failed: $*"; tail -3 "$work/gen.log"; }; }
declare -A kase args lanes_of
kase[antoci2d]=$work/antoci; args[antoci2d]="-tmax:0.05"; lanes_of[antoci2d]="1 2 4 8"
kase[liao2d]=$work/liao2d/liao; args[liao2d]="-tmax:0.05"; lanes_of[liao2d]="1 2 4 8"
kase[sph100k]=$work/sph100k; args[sph100k]="-nsteps:400"; lanes_of[sph100k]="1 2 4 8"
kase[sph1m]=$work/sph1m; args[sph1m]="-nsteps:200"; lanes_of[sph1m]="1 2"
kase[sphdp]=$work/sphdp; args[sphdp]="-nsteps:300"; lanes_of[sphdp]="1 2 4"
for c in $cases; do
  case $c in
    antoci2d) gen "$root/cases/antoci_gate2d/AntociGate2D_Def.xml" "$work/antoci" ;;
    liao2d) mkdir -p "$work/liao2d"
            cp "$shared/flexstruc/CaseDambreak2D_FSI_Def.xml" "$shared/flexstruc/DambreakGateTimeSeries.csv" "$work/liao2d/"
            gen "$work/liao2d/CaseDambreak2D_FSI_Def.xml" "$work/liao2d/liao" ;;
    sph100k) gen "$shared/Spheric2Dam_100K.xml" "$work/sph100k" ;;
    sph1m) gen "$shared/Spheric2Dam_01M.xml" "$work/sph1m" ;;
    sphdp) gen "$shared/Spheric2Dam_100K.xml" "$work/sphdp" -dp:"${LANES_SPH_DP:-0.0175}" ;;
  esac
done

for ((r = 1; r <= rounds; ++r)); do
  for c in $cases; do
    for l in ${lanes_of[$c]}; do
      o=$work/o_${c}_$l
      rm -rf "$o"
      # shellcheck disable=SC2086
      if "$bin/seaspring" "${backend[@]}" -pairlanes:"$l" ${args[$c]} -sv:none -progress:0 "${kase[$c]}" "$o" \
           >"$out/${c}_$l.log" 2>&1; then
        python3 - "$o/run.json" "$c" "$l" "$r" >>"$raw" <<'EOF'
import json, sys
r = json.load(open(sys.argv[1]))
print(",".join([sys.argv[2], sys.argv[3], sys.argv[4], str(r["steps"]), f'{r["physical_time_s"]:.6g}',
                f'{r["loop_time_s"]:.4f}', f'{1e3 * r["loop_time_s"] / r["steps"]:.5f}', r["state_hash"],
                '"' + str(r.get("physics", "")).replace(',', ';') + '"']))
EOF
      else
        echo "FAILED: $c lanes $l round $r"; tail -5 "$out/${c}_$l.log"
      fi
    done
  done
done

python3 - "$raw" <<'EOF'
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1])))
cases = []
for r in rows:
    if r["case"] not in cases: cases.append(r["case"])
print("\n| case | lanes | rounds | steps | ms per step (median) | / 1 lane | loop s (median) | state hash |")
print("|---|---|---|---|---|---|---|---|")
for c in cases:
    sel = [r for r in rows if r["case"] == c]
    base = None
    for l in sorted({int(r["lanes"]) for r in sel}):
        s = [r for r in sel if int(r["lanes"]) == l]
        ms = statistics.median(float(r["ms_per_step"]) for r in s)
        loop = statistics.median(float(r["loop_time_s"]) for r in s)
        if l == 1: base = ms
        hashes = sorted({r["state_hash"] for r in s})
        steps = sorted({r["steps"] for r in s})
        ratio = f"{ms / base:.3f}" if base else "-"
        print(f"| {c} | {l} | {len(s)} | {'/'.join(steps)} | {ms:.4f} | {ratio} | {loop:.3f} | {' '.join(hashes)} |")
EOF
rm -rf "$work"
