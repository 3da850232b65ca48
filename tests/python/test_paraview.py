"""ParaView reads a real run: the default case (cases/dambreak3d) at dp 0.04 for 0.1 s with
part files and VTU output, then tools/paraview_check.py under pvpython (xvfb-run -a when there
is no display) checks the XDMF and VTU series and renders a picture that must not be blank.

Skips (visibly) without pvpython or without the binaries: SEASPRING_BIN names their folder
(default build/bin). Debian: paraview python3-paraview xvfb xauth."""
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tools"))

from validation.paraview import pvpython_command  # noqa: E402


class ParaViewReadsARun(unittest.TestCase):
    def test_dambreak3d_xdmf_vtu_and_picture(self):
        prefix, why = pvpython_command()
        if prefix is None:
            self.skipTest(why)
        bindir = os.environ.get("SEASPRING_BIN", os.path.join(ROOT, "build", "bin"))
        gencase, seaspring = (os.path.join(bindir, b) for b in ("gencase", "seaspring"))
        if not (os.access(gencase, os.X_OK) and os.access(seaspring, os.X_OK)):
            self.skipTest(f"no gencase/seaspring in {bindir} (set SEASPRING_BIN)")
        tmp = tempfile.mkdtemp(prefix="seaspring_pv_")
        try:
            xml = os.path.join(ROOT, "cases", "dambreak3d", "DamBreak3D_Def.xml")
            case = os.path.join(tmp, "DamBreak3D")
            subprocess.run([gencase, xml, case, "-dp:0.04"], check=True, stdout=subprocess.DEVNULL, timeout=120)
            subprocess.run([seaspring, "-cpu", "-threads:2", "-tmax:0.1", "-tout:0.02", "-sv:h5,vtk", "-quiet",
                            case, os.path.join(tmp, "run")], check=True, stdout=subprocess.DEVNULL, timeout=300)
            png = os.path.join(tmp, "dambreak3d.png")
            p = subprocess.run(prefix + [os.path.join(ROOT, "tools", "paraview_check.py"), os.path.join(tmp, "run"),
                                         "--png", png, "--title", "dam break 3D"],
                               capture_output=True, text=True, timeout=300)
            out = p.stdout + p.stderr
            print(out)
            self.assertEqual(p.returncode, 0, out)
            self.assertIn("xdmf: 6 time steps", out)
            self.assertIn("vtu: 6 files", out)
            self.assertIn("picture:", out)
            self.assertGreater(os.path.getsize(png), 10000)
        finally:
            shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    unittest.main()
