#!/usr/bin/env bash
# Runs ON the GPU machine (device tool): the hydrostatic plate (cases/hydrostatic_plate) at
# dp 0.025, 0.0125, 0.00625 and 0.003125 m (2 to 16 particles through the plate) to 0.1 s on
# the GPU; mid-span deflection series (tools/solid_marker.py, needs an h5py wheel in .whl) and
# its mean over 0.01-0.1 s (one acoustic period of the column) against the analytic 6.860e-5 m.
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export LD_LIBRARY_PATH="$root/build-dev/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
bin="$root/build-dev/bin"
out="${OUT:-/tmp/seaspring_out}"
work=/tmp/seaspring_plate
mkdir -p "$out" "$work"
python3 -m pip install -q --no-index --no-deps --no-compile --no-cache-dir --target /tmp/site "$root"/.whl/*.whl
for dp in 0.025 0.0125 0.00625 0.003125; do
  "$bin/gencase" "$root/cases/hydrostatic_plate/HydrostaticPlate_Def.xml" "$work/p$dp" -dp:$dp >/dev/null
  /usr/bin/time -f "dp $dp wall %e s" "$bin/seaspring" -overwrite -gpu -progress:0 -tmax:0.1 -tout:0.001 "$work/p$dp" "$work/o$dp" \
    >"$work/p$dp.log" 2>&1
  grep -E "Particles:|Solids|wall" "$work/p$dp.log" | tee -a "$out/plate_series.txt"
  PYTHONPATH=/tmp/site python3 "$root/tools/solid_marker.py" "$work/o$dp" --point 0.5,0,-0.025 --k 2 \
    --csv "$out/plate_mid_dp$dp.csv" 2>/dev/null
  PYTHONPATH=/tmp/site python3 - "$out/plate_mid_dp$dp.csv" "$dp" <<'PY' | tee -a "$out/plate_series.txt"
import sys, numpy as np
t, dx, dy, dz = np.loadtxt(sys.argv[1], delimiter=";", skiprows=1, unpack=True)
m = (t >= 0.01) & (t <= 0.1)
w = dz[m].mean()
print(f"dp {sys.argv[2]}: mean mid-span deflection 0.01-0.1 s {w:.4e} m = {w / -6.860e-5:.4f} x analytic; range {dz[m].min():.3e}..{dz[m].max():.3e}")
PY
done
