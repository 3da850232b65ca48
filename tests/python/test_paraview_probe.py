"""ParaView's SPH probe agrees with `seaspring-post measure` (issue 15): the still tank of
tests/data/gauges (2D, dp 0.01, Wendland C2) run for 0.2 s, the pressure at four points inside
the water at the last part file, measured by `seaspring-post measure` and by ParaView's SPH
Dataset Interpolator on parts.xdmf (under pvpython, xvfb-run -a when there is no display);
they must agree within 2% of the measure's value.

ParaView's settings (ParaView 5.11; docs/solver.md, "ParaView's SPH filters"):
- Kernel `SPHWendlandQuinticKernel`: VTK's vtkWendlandQuinticKernel is our Wendland C2,
  W = a_D (1 - q/2)^4 (2q + 1), q = r/h, a_2D = 7/(4 pi h^2), a_3D = 21/(16 pi h^3), with
  CutoffFactor 2, so Kernel > Spatial Step = the part file's `h` gives the support 2h: no
  other mapping is needed (the Shepard sums agree with the measure's wsum to float round-off);
- Kernel > Dimension = the part file's `dimension`, Mass Array `mass`, Density Array `rhop`,
  Compute Shepard Sum on;
- Shepard normalisation: vtkSPHInterpolator has ShepardNormalization, but ParaView 5.11's
  filter does not show it; the script sets it on the filter's VTK object
  (GetClientSideObject(), pvpython's built-in session) and also checks the GUI's way,
  press / "Shepard Summation" (a Calculator), against the measure. Without the normalisation
  ParaView's press is the measure's times Σ V W (about 0.5% high inside the water).
The points stay more than 2h from the walls, so the wall particles that ParaView also sums
(the measure takes only active fluid) do not enter.

Skips (visibly) without pvpython or without the binaries: SEASPRING_BIN names their folder
(default build/bin); SEASPRING_POST, when set, names seaspring-post. Debian: paraview
python3-paraview xvfb xauth."""
import csv
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tools"))

from validation.paraview import pvpython_command, run_pvpython, run_still_tank, seaspring_binaries  # noqa: E402

# x, y, z [m]: water 0.4 m wide and 0.2 m deep, h = 0.0141 (2h = 0.028); pressures 760-1430 Pa.
POINTS = [(0.10, 0.0, 0.05), (0.20, 0.0, 0.05), (0.30, 0.0, 0.08), (0.20, 0.0, 0.12)]
TOLERANCE = 0.02

# Runs under pvpython: RUNDIR POINTSFILE H DIMENSION. Prints one line per point:
# "probe K press_normalised press_over_shepard_sum shepard_sum" at the last time step.
PROBE_SCRIPT = r'''
import sys
from paraview import simple as pv
from paraview import servermanager
import vtkmodules.vtkFiltersPoints  # noqa: F401  (wraps vtkSPHInterpolator's own methods)
from vtkmodules.numpy_interface import dataset_adapter as dsa

rundir, pointsfile, h, dim = sys.argv[1], sys.argv[2], float(sys.argv[3]), int(sys.argv[4])
coords = []
with open(pointsfile) as f:
    for line in f:
        if line[:1].isdigit() or line[:1] in "-.":
            coords += [float(c) for c in line.split()[:3]]
probe = pv.PolyPointSource(Points=coords)
reader = pv.Xdmf3ReaderS(FileName=[rundir + "/parts.xdmf"])
reader.UpdatePipelineInformation()
t = reader.TimestepValues[-1]


def interpolate(shepard):
    # Input = the particles, Source = the points to probe (as in ParaView's Probe filters).
    f = pv.SPHDatasetInterpolator(Input=reader, Source=probe)
    f.Kernel = "SPHWendlandQuinticKernel"
    f.Kernel.SpatialStep = h          # cutoff factor 2: support 2h, as ours
    f.Kernel.Dimension = dim
    f.MassArray = "mass"
    f.DensityArray = "rhop"
    f.ComputeShepardSum = 1
    f.GetClientSideObject().SetShepardNormalization(1 if shepard else 0)
    f.UpdatePipeline(t)
    d = dsa.WrapDataObject(servermanager.Fetch(f))
    return list(d.PointData["press"]), list(d.PointData["Shepard Summation"])


pn, _ = interpolate(True)
pr, ws = interpolate(False)
print(f"time {t!r}")
for k in range(len(pn)):
    print(f"probe {k} {pn[k]!r} {pr[k] / ws[k]!r} {ws[k]!r}")
'''


class ParaViewProbeAgreesWithMeasure(unittest.TestCase):
    def test_still_tank_pressure_within_2_percent(self):
        prefix, why = pvpython_command()
        if prefix is None:
            self.skipTest(why)
        gencase, seaspring, post, why = seaspring_binaries()
        if why:
            self.skipTest(why)
        tmp = tempfile.mkdtemp(prefix="seaspring_pvprobe_")
        try:
            run = run_still_tank(gencase, seaspring, tmp)
            points = os.path.join(tmp, "points.txt")
            with open(points, "w", encoding="utf-8") as f:
                f.write("POINTS\n" + "".join(f"{x:g} {y:g} {z:g}\n" for x, y, z in POINTS))
            mcsv = os.path.join(tmp, "measure.csv")
            subprocess.run([post, "measure", "-dirin", run, "-points", points, "-vars", "press,wsum",
                            "-savecsv", mcsv], check=True, stdout=subprocess.DEVNULL, timeout=120)
            with open(mcsv, encoding="utf-8") as f:
                rows = list(csv.DictReader(f, delimiter=";"))
            last = rows[-1]
            h, dim = self.part_constants(run)

            script = os.path.join(tmp, "probe.py")
            with open(script, "w", encoding="utf-8") as f:
                f.write(PROBE_SCRIPT)
            cmd = prefix + [script, run, points, repr(h), str(dim)]
            p = run_pvpython(cmd)
            out = p.stdout + p.stderr
            self.assertEqual(p.returncode, 0, out[-4000:])
            probes = {}
            for line in p.stdout.splitlines():
                w = line.split()
                if w[:1] == ["time"]:
                    pv_time = float(w[1])
                elif w[:1] == ["probe"]:
                    probes[int(w[1])] = tuple(float(v) for v in w[2:5])
            self.assertEqual(sorted(probes), list(range(len(POINTS))), out[-4000:])
            self.assertAlmostEqual(pv_time, float(last["time"]), delta=1e-6)

            print(f"\nt = {float(last['time']):.6g} s, h = {h:.6g} m, dimension {dim}")
            print("point             measure [Pa]  ParaView [Pa]  rel.diff   press/ShepSum rel.diff   wsum  ShepSum")
            for k, pt in enumerate(POINTS):
                m = float(last[f"press_{k}"])
                wsum = float(last[f"wsum_{k}"])
                pn, pg, ws = probes[k]
                dn, dg = (pn - m) / m, (pg - m) / m
                print(f"{pt!s:17} {m:12.4f}  {pn:13.4f}  {dn:+.2e}  {pg:13.4f} {dg:+.2e}  {wsum:.5f} {ws:.5f}")
                self.assertGreaterEqual(m, 500.0, f"point {k} {pt} is too shallow")
                self.assertLessEqual(abs(pn - m), TOLERANCE * m, f"point {k} {pt}: ParaView {pn} vs measure {m}")
                self.assertLessEqual(abs(pg - m), TOLERANCE * m, f"point {k} {pt}: press/Shepard {pg} vs measure {m}")
                self.assertLessEqual(abs(ws - wsum), TOLERANCE * wsum, f"point {k} {pt}: Shepard sum {ws} vs wsum {wsum}")
        finally:
            shutil.rmtree(tmp, ignore_errors=True)

    @staticmethod
    def part_constants(run):
        """h and dimension of the last part file (h5py, else h5dump)."""
        parts = sorted(f for f in os.listdir(os.path.join(run, "data")) if f.startswith("part_"))
        path = os.path.join(run, "data", parts[-1])
        try:
            import h5py
            with h5py.File(path, "r") as f:
                return float(f.attrs["h"]), int(f.attrs["dimension"])
        except ImportError:
            vals = []
            for name in ("h", "dimension"):
                out = subprocess.run(["h5dump", "-a", "/" + name, path], capture_output=True, text=True,
                                     check=True).stdout
                vals.append(out.split("(0):")[1].split()[0])
            return float(vals[0]), int(vals[1])


if __name__ == "__main__":
    unittest.main()
