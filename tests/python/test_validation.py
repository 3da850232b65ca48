"""Tests of tools/validation (tools/validate.py): metrics on synthetic series with known
answers, CSV readers, spec errors, and a whole validation run with stand-in binaries.

Run: /usr/bin/python3 -m unittest discover -s tests/python -v
(needs Debian's python3-numpy, python3-h5py, python3-matplotlib)."""
import contextlib
import io
import json
import os
import stat
import sys
import tempfile
import textwrap
import unittest

import numpy as np

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tools"))

from validation import metrics, series, spec  # noqa: E402
from validation.spec import Check, Reference  # noqa: E402
import validate  # noqa: E402


class Metrics(unittest.TestCase):
    t = np.linspace(0.0, 1.0, 1001)

    def test_peak_keeps_the_sign_and_respects_the_window(self):
        v = -2.0 * np.sin(np.pi * self.t)                  # peak -2 at t = 0.5
        self.assertEqual(metrics.peak(self.t, v), (-2.0, 0.5))
        val, at = metrics.peak(self.t, v, [0.0, 0.25])
        self.assertAlmostEqual(val, -2.0 * np.sin(np.pi * 0.25), 12)
        self.assertAlmostEqual(at, 0.25, 12)
        with self.assertRaisesRegex(metrics.MetricError, "no sample inside"):
            metrics.peak(self.t, v, [2.0, 3.0])

    def test_rms_of_a_constant_offset(self):
        rt = np.array([0.1, 0.2, 0.3, 0.9, 1.5])           # 1.5: outside our run, ignored
        rms, n = metrics.rms_error(self.t, self.t ** 2 + 0.1, rt, rt ** 2, None)
        self.assertAlmostEqual(rms, 0.1, 6)
        self.assertEqual(n, 4)
        rms, n = metrics.rms_error(self.t, self.t ** 2 + 0.1, rt, rt ** 2, [0.15, 0.35])
        self.assertEqual(n, 2)
        with self.assertRaisesRegex(metrics.MetricError, "not the window"):
            metrics.rms_error(self.t, self.t, rt, rt, [0.0, 2.0])

    def test_time_mean_is_exact_for_a_linear_series(self):
        tt = np.array([0.0, 0.3, 0.35, 1.0])               # uneven samples
        self.assertAlmostEqual(metrics.time_mean(tt, 2 * tt + 1, [0.1, 0.9]), 2.0, 12)
        self.assertAlmostEqual(metrics.time_mean(tt, 2 * tt + 1), 2.0, 12)

    def test_checks_relative_absolute_and_band(self):
        ref = Reference(label="a", kind="analytic", value=-2.0, band=0.05)
        v = -2.1 * np.sin(np.pi * self.t)
        out = metrics.evaluate(Check("peak", rel_tol=0.06), ref, self.t, v)
        self.assertEqual(out["error_kind"], "rel")
        self.assertAlmostEqual(out["error"], -0.05, 12)
        self.assertTrue(out["passed"])
        self.assertFalse(metrics.evaluate(Check("peak", rel_tol=0.04), ref, self.t, v)["passed"])
        self.assertTrue(metrics.evaluate(Check("peak", rel_tol=0.04, use_band=True), ref, self.t, v)["passed"])
        out = metrics.evaluate(Check("peak", abs_tol=0.05), ref, self.t, v)
        self.assertEqual(out["error_kind"], "abs")
        self.assertAlmostEqual(out["error"], -0.1, 12)
        self.assertFalse(out["passed"])
        both = Check("peak", abs_tol=0.05, rel_tol=0.025)   # 0.05 + 0.025 * 2 = 0.1 allowed
        self.assertTrue(metrics.evaluate(both, ref, self.t, v)["passed"])
        out = metrics.evaluate(Check("mean", window=[0.0, 1.0], rel_tol=0.01), ref, self.t, v)
        self.assertAlmostEqual(out["ours"], -2.1 * 2 / np.pi, 5)

    def test_checks_against_a_series(self):
        rt = np.linspace(0, 1, 11)
        data = Reference(label="d", kind="experiment", file="x", band=0.0)
        v = np.sin(np.pi * (self.t - 0.1))                 # our peak 0.1 s late
        out = metrics.evaluate(Check("peak_time", abs_tol=0.05), data, self.t, v, (rt, np.sin(np.pi * rt)))
        self.assertAlmostEqual(out["error"], 0.1, 9)
        self.assertFalse(out["passed"])
        out = metrics.evaluate(Check("rms", abs_tol=0.2), data, self.t, np.sin(np.pi * self.t) + 0.1,
                               (rt, np.sin(np.pi * rt)))
        self.assertAlmostEqual(out["ours"], 0.1, 6)
        self.assertTrue(out["passed"])
        zero = Reference(label="z", kind="analytic", value=0.0)
        with self.assertRaisesRegex(metrics.MetricError, "use abs_tol"):
            metrics.evaluate(Check("mean", rel_tol=0.1), zero, self.t, v)

    def test_onset_is_the_first_interpolated_crossing_of_the_threshold(self):
        t = np.array([0.0, 0.1, 0.2, 0.3, 0.4, 0.5])
        v = np.array([0.0, 0.0, 0.5, 2.0, 0.5, 3.0])      # reaches 1 between 0.2 and 0.3
        self.assertAlmostEqual(metrics.onset(t, v, 1.0), 0.2 + 0.1 / 3.0, 12)
        self.assertAlmostEqual(metrics.onset(t, v, 1.0, [0.35, 0.5]), 0.4 + 0.1 * 0.5 / 2.5, 12)
        self.assertAlmostEqual(metrics.onset(t, -v, -1.0), 0.2 + 0.1 / 3.0, 12)   # falling to a negative one
        with self.assertRaisesRegex(metrics.MetricError, "never reaches the threshold 5"):
            metrics.onset(t, v, 5.0)
        with self.assertRaisesRegex(metrics.MetricError, "already at the threshold"):
            metrics.onset(t, v, 1.0, [0.3, 0.5])
        # as a check: a noisy step about 0.03 s early against a clean one (ours crosses 0.5
        # between the samples at 0.519 and 0.52 s)
        tt = np.linspace(0.0, 1.0, 1001)
        ours = np.where(tt >= 0.52, 1.0 + 0.2 * np.sin(200 * tt), 0.0)
        rt = np.array([0.0, 0.4, 0.5, 0.6, 1.0])
        rv = np.array([0.0, 0.0, 0.0, 1.0, 1.0])            # crosses 0.5 at 0.55
        data = Reference(label="d", kind="experiment", file="x", time_band=0.01)
        c = Check("onset_time", abs_tol=0.01, threshold=0.5)
        out = metrics.evaluate(c, data, tt, ours, (rt, rv))
        self.assertAlmostEqual(out["reference"], 0.55, 12)
        self.assertTrue(0.519 < out["ours"] < 0.52, out["ours"])
        self.assertAlmostEqual(out["error"], out["ours"] - 0.55, 12)
        self.assertEqual(out["error_kind"], "abs")
        self.assertFalse(out["passed"])
        self.assertTrue(metrics.evaluate(Check("onset_time", abs_tol=0.035, threshold=0.5), data, tt, ours,
                                         (rt, rv))["passed"])
        self.assertFalse(metrics.evaluate(Check("onset_time", abs_tol=0.025, threshold=0.5), data, tt, ours,
                                          (rt, rv))["passed"])
        self.assertTrue(metrics.evaluate(Check("onset_time", abs_tol=0.025, threshold=0.5, use_band=True),
                                         data, tt, ours, (rt, rv))["passed"])
        with self.assertRaisesRegex(metrics.MetricError, "ours: never reaches"):
            metrics.evaluate(Check("onset_time", abs_tol=0.01, threshold=0.5), data, tt, 0 * tt, (rt, rv))
        with self.assertRaisesRegex(metrics.MetricError, "reference: never reaches"):
            metrics.evaluate(Check("onset_time", abs_tol=0.01, threshold=0.5), data, tt, ours, (rt, 0 * rv))

    def test_convergence_orders(self):
        dps = [0.004, 0.002, 0.001]
        errs = [3.0 * d ** 2 for d in dps]
        for p in metrics.orders(dps, errs):
            self.assertAlmostEqual(p, 2.0, 12)
        self.assertAlmostEqual(metrics.richardson_order(dps, [1 + 5 * d ** 1.5 for d in dps]), 1.5, 9)
        self.assertEqual(metrics.orders([0.004, 0.002], [0.0, 1.0]), [None])
        self.assertIsNone(metrics.richardson_order([0.004, 0.002, 0.0015], [1, 2, 3]))


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8") as f:
        f.write(textwrap.dedent(text).lstrip())
    return path


class Series(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.d = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def test_gauge_columns_by_name_with_units_or_index(self):
        p = write(f"{self.d}/GaugesMarker_Tip.csv", """
            time [s];posx [m];posy [m];posz [m];dispx [m];dispy [m];dispz [m];
            0.1;1;0;0;0.5;0;0;
            0.0;1;0;0;0.25;0;0;
            """)
        t, v = series.read_gauge(p, "dispx")
        np.testing.assert_array_equal(t, [0.0, 0.1])       # sorted by time
        np.testing.assert_array_equal(v, [0.25, 0.5])
        np.testing.assert_array_equal(series.read_gauge(p, 4)[1], [0.25, 0.5])
        with self.assertRaisesRegex(series.SeriesError, r"GaugesMarker_Tip.csv: no column 'velx'.*header"):
            series.read_gauge(p, "velx")
        bad = write(f"{self.d}/bad.csv", "time;press\n0;1\n0.1;x\n")
        with self.assertRaisesRegex(series.SeriesError, r"bad.csv:3: not a number: 'x'"):
            series.read_gauge(bad, "press")
        with self.assertRaisesRegex(series.SeriesError, "gauge file not found"):
            series.read_gauge(f"{self.d}/none.csv", "press")

    def test_quantity_scaled_minus_another_gauge(self):
        write(f"{self.d}/gauges/GaugesMarker_Tip.csv", "time;dispx\n0;1\n1;3\n")
        write(f"{self.d}/gauges/GaugesMarker_Root.csv", "time;dispx\n0;0\n0.5;0.5\n1;1\n")
        q = spec.Quantity(name="q", label="q", gauge="GaugesMarker_Tip.csv", column="dispx", scale=-2.0,
                          subtract={"gauge": "GaugesMarker_Root.csv", "column": "dispx"})
        t, v = series.quantity_series(q, self.d)
        np.testing.assert_allclose(v, [-2.0, -4.0])

    def test_reference_with_header_columns_and_scales(self):
        p = write(f"{self.d}/ref.csv", "time_s,midspan_deflection_1e-4m\n0.002,-0.5\n0.001,-0.7\n")
        ref = Reference(label="r", kind="numerical", file="ref.csv", path=p, value_scale=1e-4, time_scale=2.0)
        t, v = series.read_reference(ref)
        np.testing.assert_allclose(t, [0.002, 0.004])
        np.testing.assert_allclose(v, [-0.7e-4, -0.5e-4])
        ref.path = f"{self.d}/missing.csv"
        with self.assertRaisesRegex(series.SeriesError, "missing.csv: reference file not found.*SEASPRING_SHARED"):
            series.read_reference(ref)


GOOD = {
    "title": "T", "xml": "Case_Def.xml", "ci": True,
    "resolutions": {"coarse": {"dp": 0.004, "tmax": 0.5}, "medium": {"dp": 0.002, "tmax": 0.5},
                    "fine": {"dp": 0.001, "tmax": 0.5}},
    "quantities": [{
        "name": "tip_dx", "label": "tip [m]", "gauge": "GaugesMarker_Tip.csv", "column": "dispx", "scale": 1.0,
        "references": [{"label": "exp", "kind": "experiment", "file": "../shared/x/ref.csv", "band": 0.001},
                       {"label": "analytic", "kind": "analytic", "value": 1.0}],
        "checks": [{"metric": "mean", "against": 1, "window": [0.25, 0.5], "rel_tol": 0.05},
                   {"metric": "peak", "against": 0, "rel_tol": 0.15},
                   {"metric": "peak_time", "against": 0, "abs_tol": 0.05},
                   {"metric": "rms", "against": 0, "window": [0, 0.36], "abs_tol": 0.005}]}],
}


class Spec(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.case = os.path.join(self.tmp.name, "cases", "mycase")
        write(os.path.join(self.case, "Case_Def.xml"), "<case/>\n")
        self.path = os.path.join(self.case, "validation.json")

    def tearDown(self):
        self.tmp.cleanup()

    def load(self, d):
        with open(self.path, "w") as f:
            f.write(d if isinstance(d, str) else json.dumps(d, indent=1))
        return spec.load(self.path, root=self.tmp.name)

    def mutated(self, fn):
        d = json.loads(json.dumps(GOOD))
        fn(d)
        return d

    def test_the_documented_example_loads(self):
        s = self.load(GOOD)
        self.assertEqual(s.name, "mycase")
        self.assertEqual(list(s.resolutions), ["coarse", "medium", "fine"])
        q = s.quantities[0]
        self.assertEqual(q.references[0].path, os.path.abspath(os.path.join(self.tmp.name, "../shared/x/ref.csv")))
        self.assertEqual(q.checks[3].window, [0.0, 0.36])
        os.environ["SEASPRING_SHARED"] = "/elsewhere/shared"
        try:
            self.assertEqual(self.load(GOOD).quantities[0].references[0].path, "/elsewhere/shared/x/ref.csv")
        finally:
            del os.environ["SEASPRING_SHARED"]

    def assertSpecError(self, d, *parts):
        with self.assertRaises(spec.SpecError) as cm:
            self.load(d)
        msg = str(cm.exception)
        for p in (self.path,) + parts:
            self.assertIn(p, msg)

    def test_errors_name_the_file_the_key_and_the_value(self):
        self.assertSpecError('{"title": "T",\n "xml": }', ":2:", "not valid JSON")
        self.assertSpecError(self.mutated(lambda d: d.pop("title")), "title: missing")
        self.assertSpecError(self.mutated(lambda d: d["resolutions"]["coarse"].update(dp="0.004")),
                             "resolutions.coarse.dp", "finite number", '"0.004"')
        self.assertSpecError(self.mutated(lambda d: d["resolutions"]["coarse"].update(tmax=-1)),
                             "resolutions.coarse.tmax", "> 0", "-1")
        self.assertSpecError(self.mutated(lambda d: d["resolutions"].update(huge={"dp": 1, "tmax": 1})),
                             "resolutions", "huge")
        self.assertSpecError(self.mutated(lambda d: d.update(xml="Nope_Def.xml")), "xml", "Nope_Def.xml")
        q = "quantities[0]"
        self.assertSpecError(self.mutated(lambda d: d["quantities"][0]["checks"][1].update(metric="max")),
                             f"{q}.checks[1].metric", '"max"')
        self.assertSpecError(self.mutated(lambda d: d["quantities"][0]["checks"][1].update(against=2)),
                             f"{q}.checks[1].against", "no such reference", "2")
        self.assertSpecError(self.mutated(lambda d: d["quantities"][0]["checks"][2].update(against=1)),
                             f"{q}.checks[2].against", "peak_time needs")
        self.assertSpecError(self.mutated(lambda d: d["quantities"][0]["checks"][1].pop("rel_tol")),
                             f"{q}.checks[1]", "needs rel_tol or abs_tol")
        self.assertSpecError(self.mutated(lambda d: d["quantities"][0]["checks"][3].update(window=[0.4, 0.1])),
                             f"{q}.checks[3].window", "[0.4, 0.1]")
        self.assertSpecError(self.mutated(lambda d: d["quantities"][0]["references"][0].update(kind="guess")),
                             f"{q}.references[0].kind", '"guess"')
        self.assertSpecError(self.mutated(lambda d: d["quantities"][0].pop("column")), f"{q}.column")
        self.assertSpecError(self.mutated(lambda d: d["quantities"][0].update(ylim=[2, 1])), f"{q}.ylim", "[2, 1]")
        self.assertEqual(self.load(self.mutated(lambda d: d["quantities"][0].update(ylim=[-1, 2]))).quantities[0].ylim,
                         [-1.0, 2.0])

    def test_onset_time_needs_a_threshold_and_a_series(self):
        def add(check):
            return self.mutated(lambda d: d["quantities"][0]["checks"].append(check))
        s = self.load(add({"metric": "onset_time", "against": 0, "threshold": 500, "window": [0.1, 0.4],
                           "abs_tol": 0.01}))
        c = s.quantities[0].checks[4]
        self.assertEqual((c.metric, c.threshold, c.window), ("onset_time", 500.0, [0.1, 0.4]))
        q = "quantities[0]"
        self.assertSpecError(add({"metric": "onset_time", "against": 0, "abs_tol": 0.01}),
                             f"{q}.checks[4].threshold: missing")
        self.assertSpecError(add({"metric": "onset_time", "against": 1, "threshold": 1, "abs_tol": 0.01}),
                             f"{q}.checks[4].against", "onset_time needs")
        self.assertSpecError(add({"metric": "mean", "against": 0, "threshold": 1, "rel_tol": 0.1}),
                             f"{q}.checks[4].threshold", "only onset_time takes a threshold")
        self.assertSpecError(add({"metric": "onset_time", "against": 0, "threshold": "1", "abs_tol": 0.01}),
                             f"{q}.checks[4].threshold", "finite number")

    def test_unknown_keys_warn(self):
        s = self.load(self.mutated(lambda d: d.update(colour="red", _comment="ok")))
        self.assertEqual(len(s.warnings), 1)
        self.assertIn("colour: unknown key", s.warnings[0])


FAKE_GENCASE = """#!{py}
import os, sys
out = sys.argv[2]
dp = [a.split(":")[1] for a in sys.argv if a.startswith("-dp:")][0]
os.makedirs(os.path.dirname(out), exist_ok=True)
open(out + ".xml", "w").write(dp)
"""
FAKE_SEASPRING = """#!{py}
import json, os, sys
name, outdir = sys.argv[-2], sys.argv[-1]
if "broken" in outdir:
    print("Error: the solid went unstable"); sys.exit(1)
dp = float(open(name + ".xml").read())
tmax = float([a.split(":")[1] for a in sys.argv if a.startswith("-tmax:")][0])
os.makedirs(os.path.join(outdir, "gauges"), exist_ok=True)
with open(os.path.join(outdir, "gauges", "GaugesMarker_Tip.csv"), "w") as f:
    f.write("time;posx;posy;posz;dispx;dispy;dispz\\n")
    for i in range(101):
        t = tmax * i / 100
        f.write(f"{{t}};0;0;0;{{(1 + dp ** 2) * min(t / 0.1, 1.0)}};0;0\\n")
json.dump({{"wall_time_s": 1e-3 / dp, "particles": {{"total": int(1 / dp)}}, "device": "Fake GPU",
           "backend": "gpu", "steps": 10, "state_hash": "0", "physical_time_s": tmax,
           "stop_reason": "TimeMax reached"}}, open(os.path.join(outdir, "run.json"), "w"))
"""


class CommandLine(unittest.TestCase):
    def test_the_report_goes_under_out_unless_given(self):
        a = validate.parse([])
        self.assertEqual(a.report, os.path.join(a.out, "report"))
        self.assertFalse(os.path.abspath(a.report).startswith(os.path.join(ROOT, "docs")), a.report)
        self.assertEqual(validate.parse(["--out", "/tmp/v"]).report, os.path.join("/tmp/v", "report"))
        self.assertEqual(validate.parse(["--out", "/tmp/v", "--report", "/tmp/r"]).report, "/tmp/r")


class WholeRun(unittest.TestCase):
    """tools/validate.py with stand-in binaries: dispx = (1 + dp²) after 0.1 s, so its mean
    against the analytic 1 has error dp², order 2."""

    def test_report_convergence_and_a_failing_case(self):
        with tempfile.TemporaryDirectory() as d:
            for exe, text in (("gencase", FAKE_GENCASE), ("seaspring", FAKE_SEASPRING)):
                p = write(f"{d}/bin/{exe}", text.format(py=sys.executable))
                os.chmod(p, os.stat(p).st_mode | stat.S_IXUSR)
            g = json.loads(json.dumps(GOOD))
            q = g["quantities"][0]
            q["references"] = q["references"][1:]
            q["checks"] = [{"metric": "mean", "against": 0, "window": [0.2, 0.5], "rel_tol": 1e-4},
                           {"metric": "peak", "against": 0, "abs_tol": 1e-3}]
            for case in ("good", "broken"):
                write(f"{d}/cases/{case}/Case_Def.xml", "<case/>\n")
                write(f"{d}/cases/{case}/validation.json", json.dumps(g))
            write(f"{d}/cases/bad/validation.json", "{}")
            args = ["--all", "--resolution", "all", "--bin", f"{d}/bin", "--cases-dir", f"{d}/cases",
                    "--out", f"{d}/out", "--report", f"{d}/report", "--backend", "gpu"]
            with contextlib.redirect_stdout(io.StringIO()) as out:
                code = validate.main(args)
            self.assertEqual(code, 1, out.getvalue())
            with open(f"{d}/report/good.json") as f:
                good = json.load(f)
            self.assertEqual(good["status"], "PASS", out.getvalue())
            self.assertEqual(good["headline"], "fine")
            p = good["primary"]
            self.assertEqual([r["resolution"] for r in p["rows"]], ["coarse", "medium", "fine"])
            for o in p["orders"]:
                self.assertAlmostEqual(o, 2.0, 3)
            for png in ("good_tip_dx.png", "good_speed.png"):
                self.assertTrue(os.path.getsize(f"{d}/report/{png}") > 1000, png)
            with open(f"{d}/report/broken.json") as f:
                broken = json.load(f)
            self.assertEqual(broken["status"], "FAIL")
            self.assertIn("the solid went unstable", broken["reasons"][0])
            with open(f"{d}/report/README.md") as f:
                readme = f.read()
            self.assertIn("| [good](good.md) | fine | 1,000 | Fake GPU (GPU) |", readme)
            self.assertIn("**PASS**", readme)
            self.assertIn("bad/validation.json: title: missing", readme)
            self.assertIn("## Speed against error", readme)


if __name__ == "__main__":
    unittest.main()
