#!/usr/bin/env bash
# Runs ON the GPU machine (device tool), from the repository root, with build-dev carried.
# The VCPM surface correction (VcpmSurfaceCorrection, physics/vcpm_surface.h) against the plain
# lattice, both on the GPU:
#  1. the 3D cantilever of cases/cantilever3d_tipload (100 x 10 x 10 mm steel, clamped) under a
#     gravity step of 1 m/s^2 instead of its tip load: first frequency from the free end's
#     marker over 0.1 s against Timoshenko (converged beam elements, Cowper's shear factor), at
#     4 and 8 particles through the thickness, nu 0.3 and 0.49;
#  0. parity: state hashes on 1, 2 and 16 CPU threads and the GPU with the correction on;
#  2. the hydrostatic plate (cases/hydrostatic_plate) at 4 and 8 particles through the plate:
#     mean mid-span deflection over 0.01-0.1 s against the analytic strip 6.860e-5 m;
#  3. beam: the hanging beam (cases/hanging_beam) at dp 0.02, 0.01, 0.005, plain and corrected;
#  4. liao: DualSPHysics' FlexStruc Liao 2D case as shipped (shared/dualsphysics-cases), plate
#     top's horizontal displacement (tools/solid_marker.py; series in $OUT/liao2d_top_sc*.csv).
# Writes $OUT/surface.txt. Usage: tools/device_surface.sh [parity|cantilever|plate|beam|liao]...
# SC_LIST (default "0 1"): the lattices compared: 0 plain, 1 corrected (the default: with the rows'
# bending since 2026-11-27), 1r0 corrected without the rows' bending (VcpmRowBending 0), 1r1 with
# them (VcpmRowBending 1, the default's bits). PARITY_SC (default 1):
# the lattice of the parity part.
set -uo pipefail
SC_LIST=${SC_LIST:-0 1}
scparams() {  # the <parameter> lines of one SC_LIST entry
  case $1 in
    1r1) echo '<parameter key="VcpmSurfaceCorrection" value="1" /><parameter key="VcpmRowBending" value="1" />' ;;
    1r0) echo '<parameter key="VcpmSurfaceCorrection" value="1" /><parameter key="VcpmRowBending" value="0" />' ;;
    *) echo "<parameter key=\"VcpmSurfaceCorrection\" value=\"$1\" />" ;;
  esac
}
parts=("$@")
[[ ${#parts[@]} -eq 0 ]] && parts=(parity cantilever plate liao)
WORK_NAME=seaspring_surface TABLE_NAME=surface.txt
# shellcheck source=tools/device_env.sh
source "$(dirname "${BASH_SOURCE[0]}")/device_env.sh"

if want parity; then
  echo "== parity with the surface correction (CPU 1, 2, 16 threads, GPU)" | tee -a "$table"
  sed -e '/<pointload/d' -e 's|<gravity x="0" y="0" z="0"|<gravity x="0" y="0" z="-1"|' \
    -e "s|<parameters>|<parameters>$(scparams "${PARITY_SC:-1}")|" \
    "$root/cases/cantilever3d_tipload/CantileverTipLoad3D_Def.xml" >"$work/ClPar_Def.xml"
  "$bin/gencase" "$work/ClPar_Def.xml" "$work/clpar" -dp:0.0025 >/dev/null
  parity cantilever3d_surface "$work/clpar" 3000
  sed "s|<parameters>|<parameters>$(scparams "${PARITY_SC:-1}")|" \
    "$root/cases/hydrostatic_plate/HydrostaticPlate_Def.xml" >"$work/PlatePar_Def.xml"
  "$bin/gencase" "$work/PlatePar_Def.xml" "$work/platepar" -dp:0.025 >/dev/null
  parity plate2d_surface "$work/platepar" 400
fi

if want cantilever; then
  echo "== 3D cantilever, gravity step 1 m/s^2, first frequency (GPU)" | tee -a "$table"
  for nu in 0.3 0.49; do
    for sc in $SC_LIST; do
      sed -e '/<pointload/d' -e 's|<gravity x="0" y="0" z="0"|<gravity x="0" y="0" z="-1"|' \
        -e "s|poissratio=\"0.3\"|poissratio=\"$nu\"|" \
        -e 's|</vcpmsolids>|</vcpmsolids><gauges><default><computedt value="0.0001" /><output value="true" /></default><solidmarker name="Tip"><point x="0.1" y="0.005" z="0.005" /><target mkbound="1" /></solidmarker></gauges>|' \
        -e "s|<parameters>|<parameters>$(scparams "$sc")|" \
        -e 's|<parameter key="TimeMax" value="0.5"|<parameter key="TimeMax" value="0.1"|' \
        -e 's|<parameter key="TimeOut" value="0.005"|<parameter key="TimeOut" value="0.05"|' \
        "$root/cases/cantilever3d_tipload/CantileverTipLoad3D_Def.xml" >"$work/Cl_${nu}_$sc.xml"
      for dp in 0.0025 0.00125; do
        c="cl_${nu}_${sc}_$dp"
        "$bin/gencase" "$work/Cl_${nu}_$sc.xml" "$work/$c" -dp:$dp >"$work/$c.gencase.log" 2>&1 || tail -2 "$work/$c.gencase.log"
        start=$(date +%s)
        "$bin/seaspring" -gpu -overwrite -sv:none -progress:0 "$work/$c" "$work/o_$c" >"$work/$c.log" 2>&1
        wall=$(( $(date +%s) - start ))
        "$py" - "$work/o_$c/gauges/GaugesMarker_Tip.csv" "$nu" "$dp" "$sc" "$wall" <<'EOF' | tee -a "$table"
import sys, math, numpy as np
f, nu, dp, sc, wall = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), sys.argv[4], sys.argv[5]
E, rho, t, L = 2.1e9, 7800.0, 0.01, 0.1
def timoshenko(ne=400):
    G = E / (2 * (1 + nu)); k = 10 * (1 + nu) / (12 + 11 * nu); A, I = t * t, t ** 4 / 12
    n = ne + 1; K = np.zeros((2 * n, 2 * n)); M = np.zeros((2 * n, 2 * n)); h = L / ne
    for e in range(ne):
        idx = [2 * e, 2 * e + 1, 2 * e + 2, 2 * e + 3]
        kb = E * I / h * np.array([[0, 0, 0, 0], [0, 1, 0, -1], [0, 0, 0, 0], [0, -1, 0, 1]])
        B = np.array([-1 / h, -0.5, 1 / h, -0.5]); ks = k * G * A * h * np.outer(B, B)
        m = rho * A * h / 6 * np.array([[2, 0, 1, 0], [0, 0, 0, 0], [1, 0, 2, 0], [0, 0, 0, 0]]) + \
            rho * I * h / 6 * np.array([[0, 0, 0, 0], [0, 2, 0, 1], [0, 0, 0, 0], [0, 1, 0, 2]])
        for a in range(4):
            for b in range(4):
                K[idx[a], idx[b]] += kb[a, b] + ks[a, b]; M[idx[a], idx[b]] += m[a, b]
    fr = list(range(2, 2 * n))
    w2 = np.sort(np.real(np.linalg.eigvals(np.linalg.solve(M[np.ix_(fr, fr)], K[np.ix_(fr, fr)]))))
    return math.sqrt(w2[0]) / (2 * math.pi)
f_eb = 1.8751 ** 2 / (2 * math.pi) * math.sqrt(E * t ** 4 / 12 / (rho * t * t * L ** 4))
f_t = timoshenko()
d = np.genfromtxt(f, delimiter=';', names=True)
tt, z = d['time'], d['dispz']
s = z - z.mean()
cr = [tt[i] - s[i] * (tt[i + 1] - tt[i]) / (s[i + 1] - s[i]) for i in range(len(s) - 1) if s[i] > 0 >= s[i + 1]]
fr = (len(cr) - 1) / (cr[-1] - cr[0])
print("  nu %.2f, %2d thick, correction %s: f %.2f Hz, Timoshenko %.2f (EB %.2f): %+.2f %%  (%s s wall)" %
      (nu, round(t / dp), sc, fr, f_t, f_eb, 100 * (fr / f_t - 1), wall))
EOF
      done
    done
  done
fi

if want plate; then
  echo "== hydrostatic plate, mean mid-span deflection 0.01-0.1 s / analytic 6.860e-5 m (GPU)" | tee -a "$table"
  for sc in $SC_LIST; do
    sed "s|<parameters>|<parameters>$(scparams "$sc")|" \
      "$root/cases/hydrostatic_plate/HydrostaticPlate_Def.xml" >"$work/Plate_$sc.xml"
    for dp in 0.0125 0.00625; do
      c="plate_${sc}_$dp"
      "$bin/gencase" "$work/Plate_$sc.xml" "$work/$c" -dp:$dp >/dev/null 2>&1
      start=$(date +%s)
      "$bin/seaspring" -gpu -overwrite -sv:none -progress:0 -tmax:0.1 "$work/$c" "$work/o_$c" >"$work/$c.log" 2>&1
      wall=$(( $(date +%s) - start ))
      "$py" - "$work/o_$c/gauges/GaugesMarker_Mid.csv" "$dp" "$sc" "$wall" <<'EOF' | tee -a "$table"
import sys, numpy as np
d = np.genfromtxt(sys.argv[1], delimiter=';', names=True)
m = (d['time'] >= 0.01) & (d['time'] <= 0.1)
w = d['dispz'][m].mean()
print("  %d particles thick, correction %s: mean %.4e m = %.4f x analytic  (%s s wall)" %
      (round(0.05 / float(sys.argv[2])), sys.argv[3], w, w / -6.860e-5, sys.argv[4]))
EOF
    done
  done
fi
if want beam; then
  echo "== hanging beam (seed 000 3.1), free-end displacement / 1D bar rho g L^2/(2E) = 1.4715 mm, 5 s damped (GPU)" | tee -a "$table"
  for sc in $SC_LIST; do
    sed "s|<parameters>|<parameters>$(scparams "$sc")|" \
      "$root/cases/hanging_beam/HangingBeam_Def.xml" >"$work/Beam_$sc.xml"
    for dp in 0.02 0.01 0.005; do
      c="beam_${sc}_$dp"
      "$bin/gencase" "$work/Beam_$sc.xml" "$work/$c" -dp:$dp >/dev/null 2>&1
      start=$(date +%s)
      "$bin/seaspring" -gpu -overwrite -progress:0 "$work/$c" "$work/o_$c" >"$work/$c.log" 2>&1 || tail -3 "$work/$c.log"
      wall=$(( $(date +%s) - start ))
      "$py" - "$work/o_$c" "$dp" "$sc" "$wall" <<'EOF' | tee -a "$table"
import sys, glob, h5py, numpy as np
fs = sorted(glob.glob(sys.argv[1] + '/data/part_*.h5'))
with h5py.File(fs[0]) as f: p0 = f['pos'][:]; ty = f['type'][:]
with h5py.File(fs[-1]) as f: p1 = f['pos'][:]
z0 = p0[ty == 2, 2]; bot = np.abs(z0 - z0.min()) < 1e-9
u = (p1[ty == 2, 2] - p0[ty == 2, 2])[bot].mean()
print("  dp %s, correction %s: free end %.5e m = %.4f x the 1D bar  (%s s wall)" % (sys.argv[2], sys.argv[3], -u, -u / 1.4715e-3, sys.argv[4]))
EOF
    done
  done
fi

if want liao; then
  echo "== DualSPHysics' FlexStruc Liao 2D as shipped (CaseDambreak2D_FSI_Def.xml: dp 2 mm, plate drawn 8 mm = 5 particles," | tee -a "$table"
  echo "   nu 0.49, plane strain, TimeMax 1 s): plate top (0.6, 0, 0.09) horizontal displacement (GPU)" | tee -a "$table"
  cp "$root/build-dev/shared-cases/flexstruc/DambreakGateTimeSeries.csv" "$work/"
  for sc in $SC_LIST; do
    sed "s|<parameters>|<parameters>$(scparams "$sc")|" \
      "$root/build-dev/shared-cases/flexstruc/CaseDambreak2D_FSI_Def.xml" >"$work/Liao_$sc.xml"
    c="liao_$sc"
    "$bin/gencase" "$work/Liao_$sc.xml" "$work/$c" >"$work/$c.gencase.log" 2>&1 || tail -3 "$work/$c.gencase.log"
    start=$(date +%s)
    "$bin/seaspring" -gpu -overwrite -progress:0 "$work/$c" "$work/o_$c" >"$work/$c.log" 2>&1 || tail -3 "$work/$c.log"
    wall=$(( $(date +%s) - start ))
    "$py" "$root/tools/solid_marker.py" "$work/o_$c" --point 0.6,0,0.09 --csv "$out/liao2d_top_sc$sc.csv" >/dev/null
    "$py" - "$out/liao2d_top_sc$sc.csv" "$sc" "$wall" <<'EOF' | tee -a "$table"
import sys, numpy as np
d = np.genfromtxt(sys.argv[1], delimiter=';', names=True)
i = int(np.argmax(d['dx_m']))
print("  correction %s: peak dx %.4f m at t %.3f s (dz there %.4f m); dx at 1 s %.4f m  (%s s wall)" %
      (sys.argv[2], d['dx_m'][i], d['time_s'][i], d['dz_m'][i], d['dx_m'][-1], sys.argv[3]))
EOF
  done
fi
cat "$table"
