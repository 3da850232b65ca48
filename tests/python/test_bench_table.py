"""Tests of tools/bench_table.py's sluice records (tools/bench.sh sluice, sluicerun): the window's
estimate, the coarse run's whole-run factor and the whole-run estimate, on synthetic solver logs
with known answers; and of its capacity records (bench.sh capacity) on a synthetic run.

Run: /usr/bin/python3 -m unittest discover -s tests/python -p test_bench_table.py -v"""
import csv
import json
import os
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
TABLE = os.path.join(ROOT, "tools", "bench_table.py")


def write_log(path, np_, lines):
    """A solver log: the banner's particle count, then progress lines (t, steps, loop seconds) as
    the solver prints them (ns per particle per step = loop / (steps * particles))."""
    with open(path, "w") as f:
        f.write(f"  particles: {np_}\n  backend: gpu (Test GPU)\n")
        for t, steps, loop in lines:
            ns = loop * 1e9 / (steps * np_)
            f.write(f"t={t:.5f}/2 s  steps={steps}  dt=1.000e-05  100.0 steps/s  {ns:.6f} ns/particle/step  "
                    "fluid=1  dtmin-hits=0  ETA 1 s\n")


def run(*args):
    subprocess.run([sys.executable, TABLE, *args], check=True, stdout=subprocess.DEVNULL)


class SluiceRecords(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp()
        self.raw = os.path.join(self.dir, "runs.csv")

    def rows(self):
        with open(self.raw, newline="") as f:
            return list(csv.DictReader(f))

    def test_window_factor_and_whole_run_estimate(self):
        # The fine run: 100 steps per 0.001 s at 10 ms a step in its window from t = 0.005 s:
        # 100,000 steps per simulated second x 10 ms = 1,000 s per simulated second; 2 s: 2000/3600 h.
        fine = os.path.join(self.dir, "fine.log")
        write_log(fine, 1000, [(0.001 * k, 100 * k, 1.0 * k) for k in range(1, 20)])
        run("sluice", self.raw, "new", "1", fine, "0.005", "600", "2")
        # The coarse run: 10 s per simulated second up to t = 0.5 s, 30 after it, to t = 1 s
        # (progress lines every 0.05 s); its rate over the fine window's interval is 10, its whole
        # run 40 s over 1 s: factor 4.
        coarse = os.path.join(self.dir, "coarse.log")
        pts, loop = [], 0.0
        for k in range(1, 21):
            t = 0.05 * k
            loop += 0.05 * (10.0 if t <= 0.5 + 1e-12 else 30.0)
            pts.append((t, 50 * k, loop))
        write_log(coarse, 100, pts)
        rj = os.path.join(self.dir, "run.json")
        with open(rj, "w") as f:
            json.dump({"physical_time_s": 1.0, "loop_time_s": 40.0, "steps": 1000, "state_hash": "ab"}, f)
        run("sluice-run", self.raw, "new", "1", coarse, rj, "0.005", "0.0065")
        rows = {r["bench"]: r for r in self.rows()}
        self.assertAlmostEqual(float(rows["sluice3d"]["value"]), 2000.0 / 3600.0, places=4)
        self.assertAlmostEqual(float(rows["sluice3d_run"]["value"]), 4.0, places=4)
        self.assertIn("the dp 1 mm window", rows["sluice3d_run"]["note"])
        self.assertIn("0.2-0.4 s 10", rows["sluice3d_run"]["note"])  # a phase of the coarse run
        out = os.path.join(self.dir, "bench.csv")
        run("table", self.raw, out)
        with open(out, newline="") as f:
            table = {r[0]: r for r in csv.reader(f)}
        whole = table["Sluice gate 3D dp 1 mm, 2 s (whole-run est.)"]
        self.assertAlmostEqual(float(whole[2]), 4.0 * 2000.0 / 3600.0, places=2)
        self.assertEqual(whole[6], "n/a")  # the coarse run reached 1 s of 2: not judged

    def test_a_coarse_run_without_progress_lines_fails_visibly(self):
        coarse = os.path.join(self.dir, "coarse.log")
        write_log(coarse, 100, [])  # stopped before its first progress line
        run("sluice-run", self.raw, "new", "1", coarse, os.path.join(self.dir, "none.json"), "0.005", "0.0065")
        (row,) = self.rows()
        self.assertEqual(row["status"], "FAILED")
        self.assertIn("no rate", row["note"])


class CapacityRecords(unittest.TestCase):
    def test_largest_case_on_the_gpu_and_in_host_memory(self):
        d = tempfile.mkdtemp()
        raw = os.path.join(d, "runs.csv")
        mib = 1024.0 * 1024.0
        n = 1000000
        # The run: 150 B per particle in its arrays, a 10,000 MiB device, memory.used peaking at
        # 1,000 MiB; the solver's host peak 400 MB, gencase's 200 MiB, the case file 50 MB.
        rj = os.path.join(d, "run.json")
        with open(rj, "w") as f:
            json.dump({"particles": {"total": n}, "steps": 10, "physical_time_s": 1e-3, "loop_time_s": 1.0,
                       "ns_per_particle_step": 100.0, "state_hash": "ab",
                       "memory": {"host_peak_bytes": 400 * n, "gpu_arrays_peak_bytes": 150 * n,
                                  "gpu_arrays_bytes_per_particle": 150.0, "gpu_total_bytes": 10000 * mib}}, f)
        samples = os.path.join(d, "capacity.mem")
        with open(samples, "w") as f:
            f.write("500\n1000\n700\n")
        run("record", raw, "capacity", "new", "1", "gpu_bpp", rj)
        run("memory", raw, "capacity_smi_peak", "new", "1", samples, str(n))
        log = os.path.join(d, "spheric.gencase.log")
        with open(log, "w") as f:
            f.write("Particles: 1000000 (...)\nFinished in 1.00 s (host memory peak 200.0 MiB)\n")
        with open(os.path.join(d, "spheric.h5"), "wb") as f:
            f.write(b"\0" * (50 * n))
        run("capacity", raw, "new", "1", rj, log, str(64 * 2**30))
        with open(raw, newline="") as f:
            rows = {r["bench"]: r for r in csv.DictReader(f)}
        self.assertAlmostEqual(float(rows["capacity"]["value"]), 150.0)
        self.assertAlmostEqual(float(rows["capacity_smi_peak"]["value"]), 1000.0)
        self.assertAlmostEqual(float(rows["capacity_host_bpp"]["value"]), 400.0)
        self.assertAlmostEqual(float(rows["capacity_gencase_bpp"]["value"]), 200.0 * mib / n, places=3)
        self.assertAlmostEqual(float(rows["capacity_case_bpp"]["value"]), 50.0)
        # GPU: 1 M + 9,000 MiB / 150 B; host: 64 GiB / 400 B (the solver's is the larger).
        self.assertAlmostEqual(float(rows["capacity_n_gpu"]["value"]), (n + 9000 * mib / 150.0) / 1e6, places=3)
        self.assertAlmostEqual(float(rows["capacity_n_host"]["value"]), 64 * 2**30 / 400.0 / 1e6, places=3)
        out = os.path.join(d, "bench.csv")
        run("table", raw, out)
        with open(out, newline="") as f:
            table = {r[0]: r for r in csv.reader(f)}
        self.assertIn("Largest SPHERIC-like case, this GPU", table)

    def test_a_run_without_memory_figures_fails_visibly(self):
        d = tempfile.mkdtemp()
        raw = os.path.join(d, "runs.csv")
        run("capacity", raw, "new", "1", os.path.join(d, "none.json"), os.path.join(d, "none.log"), "1")
        with open(raw, newline="") as f:
            rows = list(csv.DictReader(f))
        self.assertEqual(len(rows), 5)
        self.assertTrue(all(r["status"] == "FAILED" for r in rows))


if __name__ == "__main__":
    unittest.main()
