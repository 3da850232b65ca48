"""`seaspring-post isosurface` end to end (issue 15): a small 3D tank of still water (dp 0.02 m,
water 0.1 m deep) run for 0.02 s, its free surface contoured by VTK under pvpython
(tools/isosurface.py, vtkFlyingEdges3D), and the surface opened in ParaView (XMLPolyDataReader):
it must have triangles, lie at the water's top (the top particle row z = 0.1 m plus about half a
spacing: 0.1 <= z <= 0.125 m) and span the tank's inside; also the 2D still tank
(tests/data/gauges): contour lines at about z = 0.2 m. tools/isosurface.py's errors name the file.

Broken on purpose once (then restored): tools/isosurface.py contoured at level * 10: the 3D
surface had no cells and test_3d_surface_opens_in_paraview failed, the 2D one no lines and
test_2d_contour_lines failed.

Skips (visibly) without pvpython or without the binaries: SEASPRING_BIN names their folder
(default build/bin); SEASPRING_POST, when set, names seaspring-post."""
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tools"))

from validation.paraview import pvpython_command, run_pvpython, seaspring_binaries  # noqa: E402

TANK3D = """<?xml version="1.0" encoding="UTF-8" ?>
<case><casedef><constantsdef><gravity x="0" y="0" z="-9.81" /><rhop0 value="1000" /><hswl value="0" auto="true" />
    <gamma value="7" /><speedsystem value="0" auto="true" /><coefsound value="20" />
    <speedsound value="0" auto="true" /><coefh value="1.0" /><cflnumber value="0.2" /></constantsdef>
  <mkconfig boundcount="240" fluidcount="9" />
  <geometry><definition dp="0.02"><pointmin x="-0.05" y="-0.05" z="-0.05" /><pointmax x="0.35" y="0.25" z="0.25" /></definition>
  <commands><mainlist>
    <setdrawmode mode="full" />
    <setmkfluid mk="0" /><drawbox><boxfill>solid</boxfill><point x="0" y="0" z="0" /><size x="0.3" y="0.2" z="0.1" /></drawbox>
    <setmkbound mk="0" /><drawbox><boxfill>bottom | left | right | front | back</boxfill><point x="0" y="0" z="0" /><size x="0.3" y="0.2" z="0.2" /></drawbox>
  </mainlist></commands></geometry>
</casedef>
<execution><parameters>
  <parameter key="StepAlgorithm" value="2" /><parameter key="Kernel" value="2" /><parameter key="ViscoTreatment" value="1" />
  <parameter key="Visco" value="0.01" /><parameter key="DensityDT" value="3" />
  <parameter key="TimeMax" value="0.02" /><parameter key="TimeOut" value="0.01" />
</parameters></execution></case>
"""

# Runs under pvpython: SURFACE.vtp ... Prints "surface PATH points cells xmin xmax ymin ymax zmin zmax".
OPEN_SCRIPT = r'''
import sys
from paraview import simple as pv
for path in sys.argv[1:]:
    r = pv.XMLPolyDataReader(FileName=[path])
    r.UpdatePipeline()
    info = r.GetDataInformation()
    b = info.GetBounds()
    arrays = [r.PointData.GetArray(k).Name for k in range(len(r.PointData))]
    print("surface", path, info.GetNumberOfPoints(), info.GetNumberOfCells(), *b, ",".join(arrays))
'''


class IsosurfaceOpensInParaView(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.prefix, why = pvpython_command()
        if cls.prefix is None:
            raise unittest.SkipTest(why)
        cls.gencase, cls.seaspring, cls.post, why = seaspring_binaries()
        if why:
            raise unittest.SkipTest(why)
        cls.tmp = tempfile.mkdtemp(prefix="seaspring_iso_")

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def run_case(self, name, xml_path, tmax):
        case, run = os.path.join(self.tmp, name), os.path.join(self.tmp, name + "_run")
        subprocess.run([self.gencase, xml_path, case], check=True, stdout=subprocess.DEVNULL, timeout=120)
        subprocess.run([self.seaspring, "-cpu", "-threads:2", f"-tmax:{tmax}", "-tout:0.01", "-quiet", case, run],
                       check=True, stdout=subprocess.DEVNULL, timeout=300)
        return run

    def isosurface(self, run, prefix):
        env = dict(os.environ, SEASPRING_PVPYTHON=shutil.which("pvpython"))
        p = subprocess.run([self.post, "isosurface", "-dirin", run, "-last:1", "-savevtk", prefix],
                           capture_output=True, text=True, timeout=600, env=env)
        self.assertEqual(p.returncode, 0, p.stdout[-3000:] + p.stderr[-3000:])
        return [f"{prefix}_{k:04d}.vtp" for k in (0, 1)]

    def open_in_paraview(self, paths):
        script = os.path.join(self.tmp, "open.py")
        with open(script, "w", encoding="utf-8") as f:
            f.write(OPEN_SCRIPT)
        p = run_pvpython(self.prefix + [script] + paths)
        out = p.stdout + p.stderr
        self.assertEqual(p.returncode, 0, out[-4000:])
        res = {}
        for line in p.stdout.splitlines():
            w = line.split()
            if w[:1] == ["surface"]:
                res[w[1]] = (int(w[2]), int(w[3]), [float(v) for v in w[4:10]], w[10] if len(w) > 10 else "")
        self.assertEqual(sorted(res), sorted(paths), out[-4000:])
        return res

    def test_3d_surface_opens_in_paraview(self):
        xml = os.path.join(self.tmp, "Tank3D_Def.xml")
        with open(xml, "w", encoding="utf-8") as f:
            f.write(TANK3D)
        run = self.run_case("Tank3D", xml, 0.02)
        paths = self.isosurface(run, os.path.join(self.tmp, "surf3d", "Surface"))
        for path, (npts, ncells, b, arrays) in self.open_in_paraview(paths).items():
            print(f"\n{os.path.basename(path)}: {npts} points, {ncells} triangles, x {b[0]:.4f}..{b[1]:.4f} "
                  f"y {b[2]:.4f}..{b[3]:.4f} z {b[4]:.4f}..{b[5]:.4f}, arrays {arrays}")
            self.assertGreater(ncells, 100, path)
            self.assertIn("mass", arrays)
            # The top: z = 0.1 (top particle row) plus about half a spacing.
            self.assertGreaterEqual(b[5], 0.1, path)
            self.assertLessEqual(b[5], 0.125, path)
            # Across the tank's inside (walls at x = 0, 0.3 and y = 0, 0.2; the fluid 0.02 .. 0.28
            # by 0.02 .. 0.18): the surface reaches the walls' first particle rows.
            self.assertLessEqual(b[0], 0.03, path)
            self.assertGreaterEqual(b[1], 0.27, path)
            self.assertLessEqual(b[2], 0.03, path)
            self.assertGreaterEqual(b[3], 0.17, path)

    def test_2d_contour_lines(self):
        run = self.run_case("StillTank", os.path.join(ROOT, "tests", "data", "gauges", "StillTank_Def.xml"), 0.01)
        paths = self.isosurface(run, os.path.join(self.tmp, "surf2d", "Surface"))
        for path, (npts, ncells, b, _) in self.open_in_paraview(paths).items():
            print(f"\n{os.path.basename(path)}: {npts} points, {ncells} lines, z {b[4]:.4f}..{b[5]:.4f}")
            self.assertGreater(ncells, 20, path)
            self.assertGreaterEqual(b[5], 0.19, path)   # water 0.2 m deep, dp 0.01
            self.assertLessEqual(b[5], 0.215, path)

    def test_script_errors_name_the_file(self):
        pv = shutil.which("pvpython")
        missing = os.path.join(self.tmp, "none.vti")
        p = subprocess.run([pv, os.path.join(ROOT, "tools", "isosurface.py"), "--level", "0.5", missing,
                            os.path.join(self.tmp, "x.vtp")], capture_output=True, text=True, timeout=300)
        self.assertEqual(p.returncode, 2, p.stdout + p.stderr)
        self.assertIn(f"{missing}: no such file", p.stderr)
        jobs = os.path.join(self.tmp, "jobs.txt")
        with open(jobs, "w", encoding="utf-8") as f:
            f.write("abc\tg.vti\ts.vtp\n")
        p = subprocess.run([pv, os.path.join(ROOT, "tools", "isosurface.py"), "--jobs", jobs],
                           capture_output=True, text=True, timeout=300)
        self.assertEqual(p.returncode, 2)
        self.assertIn(f"{jobs}:1: level 'abc' is not a number", p.stderr)


if __name__ == "__main__":
    unittest.main()
