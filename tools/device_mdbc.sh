#!/usr/bin/env bash
# Runs ON the GPU machine (device tool), from the repository root, with build-dev carried
# (tools/device_build.sh): the mDBC set of issue 12, one table per step in $OUT.
#   still     still-water tanks, 2D and 3D, DBC and mDBC (each SlipMode), 1 s: the lowest fluid
#             row's pressure against hydrostatic and its height, means over the last 0.1 s
#   impact    tools/validate.py on cases/dambreak_impact2d (DBC) and _mdbc (SlipMode 1, and 2 and
#             3 as copies), every resolution, GPU; the reports are tarred into $OUT
#   front     the same for cases/dambreak_front2d and _mdbc (the surge front on z = 0.06 and 0.03 m)
#   plate     the same for cases/hydrostatic_plate and _mdbc (mDBC on the deforming plate)
#   gate      the same for cases/antoci_gate2d and _mdbc (mDBC on the rubber gate)
#   parity    state hashes of cpu 1 and 2 threads and gpu on the mDBC cases
#   cost      SPHERIC Test 2 at dp 0.006 (4.36 M particles): ns/particle/step, DBC against mDBC
#   cost2d    the 2D impact case at its fine dp (0.005), the same first COST2D_STEPS steps (default
#             4000: the collapse and the first run-up) with DBC and with mDBC free-slip, two rounds
#             alternated (COST2D_ROUNDS): ms per step; with BASE_BIN also the baseline build's
#             mDBC run (its own gencase) and its state hash
# Usage: tools/device_mdbc.sh still impact cost
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export LD_LIBRARY_PATH="$root/build-dev/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export SEASPRING_SHARED="$root/build-dev/shared"
bin="$root/build-dev/bin"
out="${OUT:-/tmp/seaspring_out}"
work=/tmp/seaspring_mdbc
mkdir -p "$out" "$work"
py=/usr/bin/python3
/usr/bin/python3 -c "import numpy, h5py, matplotlib" 2>/dev/null || py=/opt/torch/.venv/bin/python3
gpu="$(nvidia-smi --query-gpu=name --format=csv,noheader | head -1)"
echo "$gpu" >"$out/gpu.txt"

# A tank (2D: 0.4 x 0.3 m; 3D: 0.4 x 0.2 x 0.3 m), water 0.2 m deep, dp 0.01, h = 2 dp, 3 wall
# layers; with the normals geometry (the inner faces dp/2 inside the first wall row).
tank_xml() {  # dim params
    local dim=$1 params=$2 y0=0 y1=0 py0=-1 sy=2
    [[ $dim == 3 ]] && { y0=-0.05; y1=0.25; py0=0; sy=0.2; }
    cat <<EOF
<?xml version="1.0" encoding="UTF-8" ?>
<case><casedef>
  <constantsdef><gravity x="0" y="0" z="-9.81" /><rhop0 value="1000" /><hswl value="0" auto="true" />
    <gamma value="7" /><speedsystem value="0" auto="true" /><coefsound value="20" />
    <speedsound value="0" auto="true" /><hdp value="2" /><cflnumber value="0.2" /></constantsdef>
  <mkconfig boundcount="240" fluidcount="9" />
  <geometry><definition dp="0.01"><pointmin x="-0.05" y="$y0" z="-0.05" /><pointmax x="0.45" y="$y1" z="0.35" /></definition>
  <commands>
  <list name="GeometryForNormals">
    <setactive drawpoints="0" drawshapes="1" /><setshapemode>actual | bound</setshapemode>
    <setmkbound mk="0" /><setnormalinvert invert="true" />
    <drawbox><boxfill>bottom | left | right | front | back</boxfill><point x="0" y="$py0" z="0" /><size x="0.4" y="$sy" z="0.3" /><layers vdp="-0.5" /></drawbox>
    <shapeout file="hdp" /><resetdraw />
  </list>
  <mainlist><runlist name="GeometryForNormals" />
    <setdrawmode mode="full" />
    <setmkfluid mk="0" /><drawbox><boxfill>solid</boxfill><point x="0" y="$py0" z="0" /><size x="0.4" y="$sy" z="0.2" /></drawbox>
    <setmkbound mk="0" /><drawbox><boxfill>bottom | left | right | front | back</boxfill><point x="0" y="$py0" z="0" /><size x="0.4" y="$sy" z="0.3" /><layers vdp="0,1,2" /></drawbox>
  </mainlist></commands></geometry>
  <normals active="true"><distanceh value="2.0" /><geometryfile file="[CaseName]_hdp_Actual.vtk" /></normals>
</casedef>
<execution><parameters>$params
  <parameter key="StepAlgorithm" value="2" /><parameter key="Kernel" value="2" /><parameter key="ViscoTreatment" value="1" />
  <parameter key="Visco" value="0.01" /><parameter key="DensityDT" value="3" />
  <parameter key="TimeMax" value="1.0" /><parameter key="TimeOut" value="0.01" />
</parameters></execution></case>
EOF
}

step_still() {
    local table="$out/still.txt"
    echo "still-water tank, 1 s, water 0.2 m, dp 0.01, h 2dp, symplectic/Wendland/art 0.01/DDT3; $gpu" >"$table"
    for dim in 2 3; do
        for v in "DBC:1:1" "mDBC-slip1:2:1" "mDBC-noslip:2:2" "mDBC-freeslip:2:3"; do
            IFS=: read -r name b s <<<"$v"
            local d="$work/still${dim}d_$name"
            mkdir -p "$d"
            tank_xml $dim "<parameter key=\"Boundary\" value=\"$b\" /><parameter key=\"SlipMode\" value=\"$s\" />" >"$d/tank_Def.xml"
            "$bin/gencase" "$d/tank_Def.xml" "$d/tank" >/dev/null || { echo "gencase failed $name" | tee -a "$table"; continue; }
            rm -rf "$d/out"/{Run.out,run.json,parts.xdmf,ledger.csv,data,vtk,gauges}  # an earlier run (seaspring refuses to mix)
            "$bin/seaspring" -gpu -sv:h5 -progress:0 "$d/tank" "$d/out" >"$d/log" 2>&1 || { tail -3 "$d/log"; continue; }
            local np wall
            np=$(grep -o 'Particles: [0-9]*' "$d/log" | cut -d' ' -f2)
            wall=$(grep -o 'in [0-9.]* s wall' "$d/log" | cut -d' ' -f2)
            $py - "$d/out/data" "$dim" "$name" "$np" "$wall" >>"$table" <<'PY'
import glob, sys, h5py, numpy as np
d, dim, name, np_, wall = sys.argv[1:]
ratios, gaps = [], []
for fn in sorted(glob.glob(d + '/*.h5')):
    f = h5py.File(fn)
    t = f['time'][()] if 'time' in f else None
    pos = f['pos'][:]; p = f['press'][:]; ty = f['type'][:]
    sel = (ty == 3) & (np.abs(pos[:, 0] - 0.2) <= 0.1)
    if dim == '3': sel &= np.abs(pos[:, 1] - 0.1) <= 0.05
    z = pos[sel, 2]; pr = p[sel]
    low = z < z.min() + 0.005; top = z > z.max() - 0.005
    zl, zt = z[low].mean(), z[top].mean()
    ratios.append(pr[low].mean() / (1000 * 9.81 * (zt + 0.005 - zl))); gaps.append((zl - 0.005) / 0.01 - 0.5)
r, g = np.array(ratios[-10:]), np.array(gaps[-10:])
print('%sD %-14s np %8s  wall %7s s  lowest row p/hydrostatic %.4f (last 0.1 s: %.4f..%.4f)  offset %+.3f dp' % (dim, name, np_, wall, r.mean(), r.min(), r.max(), g.mean()))
PY
        done
    done
    cat "$table"
}

# validate.py on a DBC case and its mDBC sibling (SlipMode 1; 2 and 3 as copies), every resolution.
variants() {  # dbc_case mdbc_case report_name
    local cases="$1,$2" xml
    xml=$(cd "$root/cases/$2" && ls *_Def.xml | head -1)
    for s in 2 3; do
        local c="$root/cases/$2_slip$s" x="${xml%_Def.xml}Slip${s}_Def.xml"
        rm -rf "$c"
        cp -r "$root/cases/$2" "$c"
        mv "$c/$xml" "$c/$x"
        sed -i "s/key=\"SlipMode\" value=\"1\"/key=\"SlipMode\" value=\"$s\"/" "$c/$x"
        sed -i "s/$xml/$x/; s/, mDBC\"/, mDBC SlipMode $s\"/" "$c/validation.json"
        cases="$cases,$2_slip$s"
    done
    $py "$root/tools/validate.py" --cases "$cases" --resolution all --backend gpu \
        --bin "$bin" --out "$work/$3" --report "$work/$3/report" 2>&1 | tail -40
    (cd "$work/$3" && tar -czf "$out/$3_report.tgz" report)
}
step_impact() {
    variants dambreak_impact2d dambreak_impact2d_mdbc impact
    # The probes 1.5 h off the wall row (the checked ones) and half a kernel off the wall surface
    # (P*_near), for every case and resolution: window mean and onset against the experiment's
    # (cases/dambreak_impact2d/validation.json: P1 3220 Pa over 0.62-1.36 s, onset 0.6129 s at
    # 588.6 Pa; P2 812.7 Pa over 1.11-1.53 s, onset 1.1552 s at 294.3 Pa).
    $py - "$work/impact" >"$out/impact_probes.txt" <<'PY'
import csv, glob, os, sys
import numpy as np
ref = {'P1': (3220.0, (0.62, 1.36), 0.6129, 588.6, 0.4), 'P2': (812.7, (1.11, 1.53), 1.1552, 294.3, 0.8)}
for case in sorted(os.listdir(sys.argv[1])):
    for res in ('coarse', 'medium', 'fine'):
        d = os.path.join(sys.argv[1], case, res, 'gauges')
        if not os.path.isdir(d): continue
        cells = []
        for g in ('P1', 'P1_near', 'P2', 'P2_near'):
            f = os.path.join(d, 'GaugesPress_%s.csv' % g)
            if not os.path.exists(f): cells.append('%s -' % g); continue
            rows = list(csv.reader(open(f), delimiter=';'))
            a = np.array([[float(x) for x in r] for r in rows[1:] if r]); h = rows[0]
            t, p = a[:, 0], a[:, h.index('press')]
            mean, win, t_on, thr, t_from = ref[g[:2]]
            w = (t >= win[0]) & (t <= win[1])
            hit = np.nonzero((p >= thr) & (t >= t_from))[0]
            on = float('nan')
            if len(hit):
                i = hit[0]; on = t[i] if i == 0 else t[i-1] + (t[i] - t[i-1]) * (thr - p[i-1]) / (p[i] - p[i-1])
            cells.append('%s %+.1f%% %+.3f s' % (g, 100 * (p[w].mean() / mean - 1), on - t_on))
        print('%-30s %-7s %s' % (case, res, ' | '.join(cells)))
PY
    cat "$out/impact_probes.txt"
}
step_front() { variants dambreak_front2d dambreak_front2d_mdbc front; }
step_plate() { variants hydrostatic_plate hydrostatic_plate_mdbc plate; }
step_gate() { variants antoci_gate2d antoci_gate2d_mdbc gate; }

# State hashes of -cpu -threads:1, -threads:2 and -gpu on the mDBC cases (each SlipMode with a
# moving piston; the plate with mDBC on its deforming face; the 3D still tank).
step_parity() {
    local table="$out/parity.txt" x="$work/parity"
    mkdir -p "$x"
    echo "state hashes, $gpu: cpu -threads:1 | cpu -threads:2 | gpu" >"$table"
    for s in 1 2 3; do
        sed "s|<!--PARAMETERS-->|<parameter key=\"Boundary\" value=\"2\" /><parameter key=\"SlipMode\" value=\"$s\" /><parameter key=\"StepAlgorithm\" value=\"2\" /><parameter key=\"Kernel\" value=\"2\" /><parameter key=\"ViscoTreatment\" value=\"3\" /><parameter key=\"Visco\" value=\"1e-6\" /><parameter key=\"DensityDT\" value=\"3\" />|" \
            "$root/tests/data/phases/PistonTankMdbc2D_Def.xml" >"$x/piston$s"_Def.xml
        "$bin/gencase" "$x/piston$s"_Def.xml "$x/piston$s" >/dev/null
    done
    "$bin/gencase" "$root/cases/hydrostatic_plate_mdbc/HydrostaticPlateMdbc_Def.xml" "$x/plate" -dp:0.0125 >/dev/null
    tank_xml 3 '<parameter key="Boundary" value="2" /><parameter key="SlipMode" value="2" />' >"$x/tank3d_Def.xml"
    "$bin/gencase" "$x/tank3d_Def.xml" "$x/tank3d" >/dev/null
    for spec in piston1:600 piston2:600 piston3:600 plate:400 tank3d:300; do
        local name=${spec%%:*} n=${spec##*:} hs=()
        for mode in "-cpu -threads:1" "-cpu -threads:2" "-gpu"; do
            rm -rf "$x/o_$name"/{Run.out,run.json,parts.xdmf,ledger.csv,data,vtk,gauges}  # an earlier run (seaspring refuses to mix)
            hs+=("$("$bin/seaspring" $mode -nsteps:$n -sv:none -progress:0 "$x/$name" "$x/o_$name" 2>&1 | grep -o 'State hash: [0-9a-f]*' | cut -d' ' -f3)")
        done
        local same=DIFFER
        [[ -n "${hs[0]}" && "${hs[0]}" == "${hs[1]}" && "${hs[0]}" == "${hs[2]}" ]] && same=same
        echo "$name $n steps: ${hs[*]} $same" | tee -a "$table"
    done
}

step_cost() {
    local table="$out/cost.txt" x="$work/spheric"
    mkdir -p "$x"
    sed -e 's/<normals active="false">/<normals active="true">/' \
        "$root/build-dev/shared-cases/Spheric2Dam_01M.xml" >"$x/sph_Def.xml"
    "$bin/gencase" "$x/sph_Def.xml" "$x/sph" -dp:0.006 >"$x/gencase.log" 2>&1 || { tail -5 "$x/gencase.log"; return; }
    grep -i normals "$x/gencase.log"
    echo "SPHERIC Test 2, dp 0.006, symplectic/Wendland/art/DDT3, 200 steps; $gpu" >"$table"
    for round in 1 2; do
        for b in 1 2; do
            sed -i "s/key=\"Boundary\" value=\"[12]\"/key=\"Boundary\" value=\"$b\"/" "$x/sph.xml"
            rm -rf "$x/o$b"/{Run.out,run.json,parts.xdmf,ledger.csv,data,vtk,gauges}  # an earlier run (seaspring refuses to mix)
            "$bin/seaspring" -gpu -symplectic -wendland -ddt:3 -nsteps:200 -sv:none -progress:0 "$x/sph" "$x/o$b" >"$x/log$b" 2>&1
            echo "round $round Boundary=$b: $(grep -E 'Finished' "$x/log$b" | grep -o '[0-9.]* ns/particle/step') $(grep -o 'Particles: [0-9]*' "$x/log$b") $(grep -o 'mDBC: .*' "$x/log$b" | head -1)" | tee -a "$table"
        done
    done
}

step_cost2d() {
    local table="$out/cost2d.txt" x="$work/cost2d" n="${COST2D_STEPS:-4000}"
    mkdir -p "$x"
    cp "$root/cases/dambreak_impact2d/DambreakImpact2D_Def.xml" "$x/dbc_Def.xml"
    sed -e 's/key="SlipMode" value="1"/key="SlipMode" value="3"/' \
        "$root/cases/dambreak_impact2d_mdbc/DambreakImpact2DMdbc_Def.xml" >"$x/mdbc_Def.xml"
    for c in dbc mdbc; do "$bin/gencase" "$x/${c}_Def.xml" "$x/$c" -dp:0.005 >/dev/null 2>&1 || echo "gencase $c failed"; done
    # The baseline runs a case written by its own gencase (a newer gencase may write parameters it does not know).
    if [[ -n "${BASE_BIN:-}" ]]; then
        "$root/$BASE_BIN/gencase" "$x/mdbc_Def.xml" "$x/mdbc_base" -dp:0.005 >/dev/null 2>&1 || echo "baseline gencase failed"
    fi
    echo "2D impact, dp 0.005, first $n steps, symplectic/Wendland/art 0.02/DDT; $gpu" >"$table"
    one() {  # label bin case
        "$2/seaspring" -gpu -overwrite -nsteps:$n -sv:none -progress:0 "$x/$3" "$x/o_$1" >"$x/log_$1" 2>&1 || tail -3 "$x/log_$1"
        echo "$1: $(grep -o 'loop [0-9.]* s' "$x/log_$1") $(grep -o 'Particles: [0-9]*' "$x/log_$1") $(grep -o 'State hash: [0-9a-f]*' "$x/log_$1")" |
            awk -v n=$n '{ for (i = 1; i <= NF; i++) if ($i == "loop") { printf "%s  %.4f ms/step\n", $0, 1000 * $(i + 1) / n } }' |
            tee -a "$table"
    }
    for round in $(seq 1 "${COST2D_ROUNDS:-2}"); do
        one "dbc" "$bin" dbc
        one "mdbc-freeslip" "$bin" mdbc
        [[ -n "${BASE_BIN:-}" ]] && one "mdbc-freeslip-base" "$root/$BASE_BIN" mdbc_base
    done
}

for s in "$@"; do "step_$s"; done
