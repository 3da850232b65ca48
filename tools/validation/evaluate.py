"""Evaluates one case: reads our series and the references, runs every check at every
resolution that ran, the convergence orders and the speed-vs-error table of the primary
check (the first check of the first quantity that has one)."""
import dataclasses
import math

from . import metrics, series
from .spec import RESOLUTIONS


def _load_refs(q):
    """(series or None, error message or None) per reference of quantity Q."""
    out = []
    for ref in q.references:
        if ref.kind == "analytic":
            out.append((None, None))
            continue
        try:
            out.append((series.read_reference(ref), None))
        except series.SeriesError as e:
            out.append((None, str(e)))
    return out


def evaluate_case(spec, runs):
    """SPEC: a CaseSpec; RUNS: runner records in resolution order. Returns (result, curves):
    RESULT is JSON-serialisable (see docs/validation.md), CURVES holds the arrays to plot:
    {quantity: {"ours": {res: (t, v)}, "refs": [(t, v) or None]}}."""
    order = {r: i for i, r in enumerate(RESOLUTIONS)}
    runs = sorted(runs, key=lambda r: order[r["resolution"]])
    issues = []
    result = {"case": spec.name, "title": spec.title, "note": spec.note, "runs": runs,
              "quantities": [], "primary": None}
    curves = {}
    for q in spec.quantities:
        refs = _load_refs(q)
        cq = curves[q.name] = {"ours": {}, "refs": [s for s, _ in refs]}
        rq = {"name": q.name, "label": q.label, "source": q.gauge or "marker", "column": q.column,
              "references": [{"label": r.label, "kind": r.kind, "file": r.file, "value": r.value,
                              "band": r.band, "error": e} for r, (_, e) in zip(q.references, refs)],
              "series_errors": {}, "checks": []}
        for run in runs:
            if not run["ok"]:
                continue
            try:
                cq["ours"][run["resolution"]] = series.quantity_series(q, run["rundir"])
            except (series.SeriesError, OSError, KeyError) as e:
                rq["series_errors"][run["resolution"]] = str(e)
                issues.append(f"{run['resolution']}: {q.name}: {e}")
        for c in q.checks:
            ref = q.references[c.against]
            rc = {"key": c.key, "metric": c.metric, "against": c.against, "against_label": ref.label,
                  "rel_tol": c.rel_tol, "abs_tol": c.abs_tol, "window": c.window,
                  "use_band": c.use_band, "results": {}}
            if c.threshold is not None:
                rc["threshold"] = c.threshold
            for res, (t, v) in cq["ours"].items():
                ref_s, ref_err = refs[c.against]
                if ref_err:
                    out = {"passed": False, "failure": ref_err}
                else:
                    try:
                        cr = c
                        if res in c.by_resolution:
                            cr = dataclasses.replace(c, rel_tol=c.by_resolution[res][0], abs_tol=c.by_resolution[res][1])
                        out = metrics.evaluate(cr, ref, t, v, ref_s)
                    except metrics.MetricError as e:
                        out = {"passed": False, "failure": str(e)}
                if "failure" in out:
                    issues.append(f"{res}: {q.name} {c.metric}: {out['failure']}")
                rc["results"][res] = out
            rq["checks"].append(rc)
        result["quantities"].append(rq)
    _primary(result)
    _status(result, issues)
    return result, curves


def _primary(result):
    for rq in result["quantities"]:
        if not rq["checks"]:
            continue
        c = rq["checks"][0]
        rows = []
        for run in result["runs"]:
            out = c["results"].get(run["resolution"])
            if out is None or "failure" in out:
                continue
            rows.append({"resolution": run["resolution"], "dp": run["dp"],
                         "wall_time_s": run.get("wall_time_s"), "particles": run.get("particles"),
                         "device": run.get("device"), "error": out["error"],
                         "error_kind": out["error_kind"], "value": out["ours"]})
        dps = [r["dp"] for r in rows]
        errs = [abs(r["error"]) for r in rows]
        result["primary"] = {"quantity": rq["name"], "label": rq["label"], "check": c["key"],
                             "metric": c["metric"], "against_label": c["against_label"],
                             "rows": rows, "orders": metrics.orders(dps, errs),
                             "richardson": metrics.richardson_order(dps, [r["value"] for r in rows])}
        return


def _status(result, issues):
    """The case passes when every run succeeded and every check passed at the finest
    resolution that ran (the headline); coarser resolutions are reported, not judged."""
    ok_runs = [r for r in result["runs"] if r["ok"]]
    head = ok_runs[-1]["resolution"] if ok_runs else None
    result["headline"] = head
    reasons = [f"{r['resolution']}: {r['reason']}" for r in result["runs"] if not r["ok"]]
    reasons += [x for x in issues if x.startswith(f"{head}: ")] if head else []
    n_checks = 0
    for q in result["quantities"]:
        for c in q["checks"]:
            out = c["results"].get(head) if head else None
            n_checks += 1
            if out is not None and "failure" not in out and not out["passed"]:
                reasons.append(f"{head}: {q['name']} {c['metric']}: {fmt_error(out)} outside {fmt_allowed(out)}")
    if not result["runs"]:
        reasons.append("no resolution ran")
    result["reasons"] = reasons
    result["notes"] = [x for x in issues if x not in reasons]
    result["status"] = "FAIL" if reasons or not ok_runs else ("PASS" if n_checks else "NO CHECKS")


def fmt_error(out):
    """'−10.6%' or '1.02e-02' for a check result; the failure text when it failed to compute."""
    if out is None:
        return "–"
    if "failure" in out:
        return "error"
    e = out["error"]
    if not math.isfinite(e):
        return str(e)
    return f"{100 * e:+.3g}%" if out["error_kind"] == "rel" else f"{e:+.3g}"


def fmt_allowed(out):
    if out is None or "failure" in out:
        return "–"
    a = out["allowed"]
    return f"±{100 * a:.3g}%" if out["error_kind"] == "rel" else f"≤ {a:.3g}"
