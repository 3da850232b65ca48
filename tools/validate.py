#!/usr/bin/env python3
"""Runs SeaSpring's validation cases and reports them against their references.

For each case (cases/<name>/validation.json) and each resolution asked for: gencase, seaspring,
then the gauge series against the references (analytic values or data files with their
digitisation band): a PNG per quantity, the checks against their tolerances, the convergence
order and error against wall time; REPORT/<case>.md + .json and REPORT/README.md (one row per
case). Exit status 1 when a case fails. Schema and details: docs/validation.md.

Examples:
  /usr/bin/python3 tools/validate.py --ci --backend cpu --out out/validation    # report in out/validation/report
  /usr/bin/python3 tools/validate.py --all --resolution all --backend gpu --paraview --report docs/validation
Needs numpy, h5py, matplotlib (Debian python3-numpy python3-h5py python3-matplotlib: run with
/usr/bin/python3 where another python3 comes first on PATH).
"""
import argparse
import datetime
import json
import os
import shlex
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
try:
    import numpy, h5py, matplotlib  # noqa: F401,E401  (the tools' dependencies)
except ImportError as _missing:  # e.g. a pyenv python3 first on PATH: use Debian's, which has them
    if os.path.realpath(sys.executable) != os.path.realpath("/usr/bin/python3") and os.path.exists("/usr/bin/python3"):
        os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)
    sys.exit(f"validate.py: {_missing}; install python3-numpy python3-h5py python3-matplotlib "
             "(tools/setup-deps.sh)")

from validation import ROOT, evaluate, paraview, plots, report, runner, spec  # noqa: E402
from validation.spec import RESOLUTIONS  # noqa: E402


def parse(argv):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sel = ap.add_mutually_exclusive_group()
    sel.add_argument("--cases", help="comma-separated case names (folders of cases/)")
    sel.add_argument("--all", action="store_true", help="every case with a validation.json")
    sel.add_argument("--ci", action="store_true", help='the cases marked "ci": true (default)')
    ap.add_argument("--resolution", default="coarse",
                    help="coarse, medium, fine, a comma-separated list, or all (default coarse)")
    ap.add_argument("--backend", choices=("cpu", "gpu", "auto"), default="auto",
                    help="seaspring -cpu or -gpu (auto: the solver's choice, the GPU when usable)")
    ap.add_argument("--threads", type=int, help="OpenMP threads for -cpu (default: all cores)")
    ap.add_argument("--out", default=os.path.join(ROOT, "out", "validation"), help="run folders (default out/validation)")
    ap.add_argument("--report", help="report folder (default OUT/report; the committed results are "
                                      "updated only with an explicit --report docs/validation)")
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "bin"), help="folder of gencase and seaspring")
    ap.add_argument("--cases-dir", default=os.path.join(ROOT, "cases"), help=argparse.SUPPRESS)
    ap.add_argument("--timeout", type=float, default=3600, help="limit per gencase/seaspring call [s]")
    ap.add_argument("--tmax", type=float, help="override every resolution's tmax [s] (smoke tests)")
    ap.add_argument("--reuse", action="store_true", help="post-process finished runs found in --out instead of running")
    ap.add_argument("--dry-run", action="store_true", help="print the commands only")
    ap.add_argument("--paraview", action="store_true",
                    help="check each case's finest run with ParaView and render REPORT/<case>.png (needs pvpython)")
    ap.add_argument("--picture-only", action="store_true",
                    help="run (or --reuse) the first --resolution with VTU output and only add the ParaView "
                         "picture to the existing REPORT/<case>.json/.md (e.g. a CPU picture for GPU results)")
    a = ap.parse_args(argv)
    if a.report is None:  # never docs/validation by default: a plain run must not overwrite committed results
        a.report = os.path.join(a.out, "report")
    if a.resolution == "all":
        a.resolutions = list(RESOLUTIONS)
    else:
        a.resolutions = [r.strip() for r in a.resolution.split(",") if r.strip()]
        bad = [r for r in a.resolutions if r not in RESOLUTIONS]
        if bad or not a.resolutions:
            ap.error(f"--resolution {a.resolution}: expected {', '.join(RESOLUTIONS)} or all")
    if a.threads is not None and a.threads < 1:
        ap.error("--threads must be >= 1")
    a.paraview = a.paraview or a.picture_only
    if a.picture_only:
        a.resolutions = a.resolutions[:1]
    a.vtk = a.paraview
    if a.backend == "auto":
        a.backend = None
    return a


class Opts:
    """What runner.run_resolution needs."""
    def __init__(self, a):
        self.bin, self.out, self.threads, self.timeout = a.bin, a.out, a.threads, a.timeout
        self.backend = a.backend
        self.reuse, self.dry_run, self.vtk = a.reuse, a.dry_run, a.vtk


def select_cases(a):
    found = spec.find_cases(a.cases_dir)
    if a.cases:
        names = [c.strip().rstrip("/").split("/")[-1] for c in a.cases.split(",") if c.strip()]
        return names
    if a.all:
        return found
    ci = []
    for n in found:
        try:
            if spec.load(os.path.join(a.cases_dir, n, "validation.json")).ci:
                ci.append(n)
        except spec.SpecError:
            ci.append(n)      # reported as a failure below
    return ci


def git_commit():
    """SEASPRING_COMMIT when set (the GPU machines get a copy of the tree whose .git may be
    stale), else `git describe` of the tree."""
    if os.environ.get("SEASPRING_COMMIT"):
        return os.environ["SEASPRING_COMMIT"]
    try:
        return subprocess.run(["git", "-C", ROOT, "describe", "--always", "--dirty"], capture_output=True,
                              text=True, timeout=20).stdout.strip() or "?"
    except (OSError, subprocess.SubprocessError):
        return "?"


def failed_result(name, title, why):
    return {"case": name, "title": title, "note": "", "runs": [], "quantities": [], "primary": None,
            "headline": None, "status": "FAIL", "reasons": [why], "notes": []}


def validate_case(name, a, stamp):
    path = os.path.join(a.cases_dir, name, "validation.json")
    print(f"== {name}")
    try:
        s = spec.load(path)
    except spec.SpecError as e:
        print(f"  {e}")
        return failed_result(name, name, str(e)), {}
    for w in s.warnings:
        print(f"  warning: {w}")
    wanted = [r for r in a.resolutions if r in s.resolutions]
    if not wanted:
        print(f"  skipped: {path} has no resolution {', '.join(a.resolutions)}")
        return None, {}
    runs = []
    for r in wanted:
        if a.tmax:
            s.resolutions[r].tmax = a.tmax
        rec = runner.run_resolution(s, s.resolutions[r], Opts(a), say=print)
        runs.append(rec)
        if rec["ok"]:
            print(f"  {r}: {rec.get('particles')} particles, {rec.get('wall_time_s') or 0:.1f} s wall on {rec.get('device')}")
        elif not a.dry_run:
            print(f"  {r}: FAILED: {rec['reason']}")
    if a.dry_run:
        return None, {}
    if a.picture_only:
        return picture_only(a, s, runs, stamp)
    result, curves = evaluate.evaluate_case(s, runs)
    result.update(stamp)
    for rec in runs:
        if rec["rundir"].startswith(ROOT + os.sep):
            rec["rundir"] = os.path.relpath(rec["rundir"], ROOT)
    images = plots.case_plots(a.report, s, result, curves)
    ok = [x for x in result["runs"] if x["ok"]]
    if a.paraview and ok:
        picture(a, s, ok[-1], result, images)
    report.write_case(a.report, result, images)
    print(f"  {result['status']}" + "".join(f"\n    {x}" for x in result["reasons"]))
    return result, images


def picture(a, s, run, result, images):
    """ParaView check and picture of RUN into REPORT/<case>.png; notes it in RESULT."""
    png = os.path.join(a.report, f"{s.name}.png")
    t0 = time.monotonic()
    done, msg = paraview.render(os.path.join(ROOT, run["rundir"]), png, s.title, s.picture_time)
    secs = time.monotonic() - t0
    if done is None:
        print(f"  ParaView skipped: {msg}")
        return
    print(f"  ParaView ({secs:.1f} s): {'ok' if done else 'FAILED'}: {msg}")
    result["paraview"] = f"{'ok' if done else 'FAILED'} ({run['resolution']}, {run.get('device')}, {secs:.1f} s): {msg}"
    if done and os.path.isfile(png):
        images["_paraview"] = os.path.basename(png)
    elif not done:
        result["reasons"].append(f"ParaView check: {msg}")
        result["status"] = "FAIL"


def picture_only(a, s, runs, stamp):
    """--picture-only: render from the run just made (or reused) and add the picture to the
    case's existing report (REPORT/<case>.json), leaving its metrics as they are."""
    ok = [x for x in runs if x["ok"]]
    if not ok:
        print(f"  no picture: {runs[-1]['reason'] if runs else 'no run'}")
        return None, {}
    path = os.path.join(a.report, f"{s.name}.json")
    try:
        with open(path, encoding="utf-8") as f:
            result = json.load(f)
    except (OSError, ValueError):
        print(f"  no {path}: the picture is written, the report is not updated")
        result = None
    images = dict(result.get("images") or {}) if result else {}
    if result is not None:
        result["picture_command"] = stamp["command"]
    picture(a, s, ok[-1], result if result is not None else {"reasons": []}, images)
    if result is not None:
        report.write_case(a.report, result, images)
    return result, images


def main(argv=None):
    a = parse(sys.argv[1:] if argv is None else argv)
    names = select_cases(a)
    if not names:
        print(f"no cases selected (cases with a validation.json in {a.cases_dir}: "
              f"{', '.join(spec.find_cases(a.cases_dir)) or 'none'})")
        return 1 if (a.cases or a.all) else 0          # an empty CI set is not a failure
    shared = spec.shared_path(os.path.join("..", "shared", "validation-data"))
    if a.ci and not os.path.isdir(shared):
        # The references live beside the repository (../shared, or $SEASPRING_SHARED): without
        # them nothing can be checked, and ctest shows this test as skipped (SKIP_RETURN_CODE).
        print(f"validation: SKIPPED: {shared} is absent (the reference data; set SEASPRING_SHARED)")
        return 77
    cmd = "tools/validate.py " + " ".join(shlex.quote(x) for x in (sys.argv[1:] if argv is None else argv))
    stamp = {"date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d"), "commit": git_commit(),
             "command": cmd}
    t0 = time.monotonic()
    results = []
    for n in names:
        if not os.path.isfile(os.path.join(a.cases_dir, n, "validation.json")):
            print(f"== {n}\n  FAIL: no {os.path.join(a.cases_dir, n, 'validation.json')}")
            results.append(failed_result(n, n, f"no cases/{n}/validation.json"))
            continue
        r, _ = validate_case(n, a, stamp)
        if r is not None:
            if not r["runs"]:
                report.write_case(a.report, dict(r, **stamp), {})
            results.append(r)
    if a.dry_run:
        return 0
    report.write_readme(a.report)
    print(f"\nreport: {os.path.join(a.report, 'README.md')} ({time.monotonic() - t0:.0f} s)")
    for r in results:
        print(f"  {r['status']:9s} {r['case']}")
    return 1 if any(r["status"] == "FAIL" for r in results) else 0


if __name__ == "__main__":
    sys.exit(main())
