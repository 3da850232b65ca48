"""tools/render (issue 15): the 2D still tank (tests/data/gauges) run for 0.02 s with outputs
every 0.01 s; tools/render must write one non-blank PNG per output time (render.py checks each:
exit 1 when blank) and the movie (movie.avi through ParaView's vtkFFMPEGWriter, else movie.ogv);
--fluid press and --every; bad options stop with exit code 2 and a message; --movie mp4 without
the ffmpeg program says so.

Broken on purpose once (then restored): render.py named the frames by position instead of part
number (frame_{i}) with --every 2: test_frames_and_movie failed (frame_0002.png missing).

Skips (visibly) without pvpython or without the binaries (SEASPRING_BIN, default build/bin)."""
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
RENDER = os.path.join(ROOT, "tools", "render")


class Render(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        if not shutil.which("pvpython"):
            raise unittest.SkipTest("pvpython not found (Debian: apt-get install paraview python3-paraview xvfb xauth)")
        if not os.environ.get("DISPLAY") and not shutil.which("xvfb-run"):
            raise unittest.SkipTest("no DISPLAY and no xvfb-run (Debian: xvfb xauth)")
        bindir = os.environ.get("SEASPRING_BIN", os.path.join(ROOT, "build", "bin"))
        gencase, seaspring = (os.path.join(bindir, b) for b in ("gencase", "seaspring"))
        if not all(os.access(b, os.X_OK) for b in (gencase, seaspring)):
            raise unittest.SkipTest(f"no gencase/seaspring in {bindir} (set SEASPRING_BIN)")
        cls.tmp = tempfile.mkdtemp(prefix="seaspring_render_")
        case, cls.run_dir = os.path.join(cls.tmp, "tank"), os.path.join(cls.tmp, "run")
        xml = os.path.join(ROOT, "tests", "data", "gauges", "StillTank_Def.xml")
        subprocess.run([gencase, xml, case], check=True, stdout=subprocess.DEVNULL, timeout=120)
        subprocess.run([seaspring, "-cpu", "-threads:2", "-tmax:0.02", "-tout:0.01", "-quiet", case, cls.run_dir],
                       check=True, stdout=subprocess.DEVNULL, timeout=300)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def render(self, *args):
        p = subprocess.run([RENDER, self.run_dir, *args], capture_output=True, text=True, timeout=600)
        return p.returncode, p.stdout + p.stderr

    def test_frames_and_movie(self):
        out = os.path.join(self.tmp, "r1")
        rc, log = self.render("--out", out, "--fluid", "press", "--width", "600")
        self.assertEqual(rc, 0, log[-3000:])
        for k in range(3):
            self.assertTrue(os.path.isfile(os.path.join(out, f"frame_{k:04d}.png")), log[-3000:])
        movies = [m for m in ("movie.avi", "movie.ogv") if os.path.isfile(os.path.join(out, m))]
        self.assertTrue(movies, log[-3000:])
        self.assertGreater(os.path.getsize(os.path.join(out, movies[0])), 1000)
        self.assertIn("render: 3 frame(s)", log)
        out2 = os.path.join(self.tmp, "r2")
        rc, log = self.render("--out", out2, "--every", "2", "--movie", "none", "--width", "600")
        self.assertEqual(rc, 0, log[-3000:])
        self.assertEqual(sorted(os.listdir(out2)), ["frame_0000.png", "frame_0002.png"])

    def test_errors(self):
        rc, log = self.render("--range", "5,1")
        self.assertEqual(rc, 2)
        self.assertIn("--range '5,1': expected MIN,MAX with MIN < MAX", log)
        rc, log = subprocess.run([RENDER, os.path.join(self.tmp, "nowhere")], capture_output=True, text=True,
                                 timeout=600).returncode, ""
        self.assertEqual(rc, 2)
        if not shutil.which("ffmpeg"):
            rc, log = self.render("--out", os.path.join(self.tmp, "r3"), "--movie", "mp4", "--last", "0")
            self.assertEqual(rc, 2, log[-3000:])
            self.assertIn("--movie mp4 needs the ffmpeg program, which is not installed", log)


if __name__ == "__main__":
    unittest.main()
