"""Markdown and JSON reports: REPORT/<case>.md and <case>.json per case, REPORT/README.md
over every <case>.json found in REPORT (so cases validated in separate runs share one table)."""
import glob
import json
import os

from .evaluate import fmt_allowed, fmt_error

MARK = {True: "✓", False: "✗"}


def _num(x, fmt="{:.3g}"):
    return "–" if x is None else fmt.format(x)


def device_text(run):
    dev = run.get("device") or "?"
    if run.get("backend") == "cpu" and run.get("threads"):
        return f"{dev} (CPU, {run['threads']} thread{'s' if run['threads'] != 1 else ''})"
    return f"{dev} ({(run.get('backend') or '?').upper()})"


def _check_name(q, c):
    w = f" {c['window'][0]:g}–{c['window'][1]:g} s" if c.get("window") else ""
    thr = f" (threshold {c['threshold']:g})" if c.get("threshold") is not None else ""
    return f"`{q['name']}` {c['metric']}{thr}{w} vs {c['against_label']}"


def _ours(out):
    if out is None or "failure" in out:
        return "–", "–"
    ref = out.get("reference")
    return f"{out['ours']:.4g}", "–" if ref is None else f"{ref:.4g}"


def case_markdown(result, images):
    r = result
    head = r.get("headline")
    runs = r["runs"]
    hrun = next((x for x in runs if x["resolution"] == head), None)
    lines = [f"# {r['title']} (`cases/{r['case']}`)", "",
             f"**{r['status']}**" + (f" at the {head} resolution — {device_text(hrun)}" if hrun else " (no run finished)")
             + f"; generated {r.get('date', '?')}, commit {r.get('commit', '?')}.", ""]
    if r.get("note"):
        lines += [r["note"], ""]
    lines += ["## Runs", "", "| resolution | dp [m] | tmax [s] | particles | steps | device | wall time [s] | state hash | run |",
              "|---|---|---|---|---|---|---|---|---|"]
    for x in runs:
        status = "ok" if x["ok"] else "FAILED: " + x["reason"].replace("|", "\\|")
        lines.append(f"| {x['resolution']} | {x['dp']:g} | {x['tmax']:g} | {_num(x.get('particles'), '{:,}')} | "
                     f"{_num(x.get('steps'), '{:,}')} | {device_text(x) if x.get('device') else '–'} | "
                     f"{_num(x.get('wall_time_s'), '{:.1f}')} | {x.get('state_hash') or '–'} | {status} |")
    for q in r["quantities"]:
        lines += ["", f"## `{q['name']}`: {q['label']}", ""]
        if q["name"] in images:
            lines += [f"![{q['name']}]({images[q['name']]})", ""]
        for i, ref in enumerate(q["references"]):
            src = f"value {ref['value']:.6g}" if ref["kind"] == "analytic" else f"`{ref['file']}`"
            band = f", band ±{ref['band']:g}" if ref.get("band") else ""
            err = f" — **{ref['error']}**" if ref.get("error") else ""
            lines.append(f"- reference {i}: {ref['label']} ({ref['kind']}; {src}{band}){err}")
        if any(c["results"] for c in q["checks"]):
            lines += ["", "| check | resolution | ours | reference | error | tolerance | result |",
                      "|---|---|---|---|---|---|---|"]
        for c in q["checks"]:
            for x in runs:
                out = c["results"].get(x["resolution"])
                if out is None:
                    continue
                ours, ref = _ours(out)
                res = out.get("failure") or MARK[out["passed"]]
                note = f" ({out['note']})" if out.get("note") else ""
                lines.append(f"| {_check_name(q, c)} | {x['resolution']} | {ours}{note} | {ref} | "
                             f"{fmt_error(out)} | {fmt_allowed(out)} | {res} |")
        for res, msg in q["series_errors"].items():
            lines.append(f"\n{res}: no series: {msg}")
    lines += _speed_section(r, images)
    if "_paraview" in images:
        lines += ["", "## ParaView", "", f"![{r['case']}]({images['_paraview']})"]
    if r.get("paraview"):
        lines += ["", f"ParaView check: {r['paraview']}"]
    cmds = [c for c in (r.get("command"), r.get("picture_command")) if c]
    if cmds:
        lines += ["", "Made with:", ""] + [f"    {c}" for c in cmds]
    if r["reasons"] or r.get("notes"):
        lines += ["", "## Problems", ""] + [f"- {x}" for x in r["reasons"] + r.get("notes", [])]
    return "\n".join(lines) + "\n"


def _speed_section(r, images):
    p = r.get("primary")
    if not p or not p["rows"]:
        return []
    lines = ["", "## Speed against error", "",
             f"Primary check: `{p['quantity']}` {p['metric']} against {p['against_label']}.", "",
             "| resolution | dp [m] | particles | device | wall time [s] | error |", "|---|---|---|---|---|---|"]
    for row in p["rows"]:
        e = f"{100 * row['error']:+.3g}%" if row["error_kind"] == "rel" else f"{row['error']:+.4g}"
        lines.append(f"| {row['resolution']} | {row['dp']:g} | {_num(row.get('particles'), '{:,}')} | "
                     f"{row.get('device') or '–'} | {_num(row.get('wall_time_s'), '{:.1f}')} | {e} |")
    if len(p["rows"]) >= 2:
        pairs = [f"{a['resolution']}→{b['resolution']}: {_num(o, '{:.2f}')}"
                 for a, b, o in zip(p["rows"], p["rows"][1:], p["orders"])]
        lines += ["", "Observed order of the error (log(e₁/e₂)/log(dp₁/dp₂)): " + "; ".join(pairs) + "."]
        if p.get("richardson") is not None:
            lines.append(f"Self-convergence order of the value from the three resolutions: {p['richardson']:.2f}.")
    if "_speed" in images:
        lines += ["", f"![speed against error]({images['_speed']})"]
    return lines


def write_case(report_dir, result, images):
    os.makedirs(report_dir, exist_ok=True)
    result = dict(result, images=images)
    with open(os.path.join(report_dir, f"{result['case']}.json"), "w", encoding="utf-8") as f:
        json.dump(result, f, indent=1, default=float)
    with open(os.path.join(report_dir, f"{result['case']}.md"), "w", encoding="utf-8") as f:
        f.write(case_markdown(result, images))


def _checks_cell(r):
    head = r.get("headline")
    parts = []
    for q in r["quantities"]:
        for c in q["checks"]:
            out = c["results"].get(head)
            if out is None:
                continue
            res = "error: " + out["failure"] if "failure" in out else MARK[out["passed"]]
            parts.append(f"{_check_name(q, c)}: {fmt_error(out)} ({fmt_allowed(out)}) {res}")
    return "<br>".join(parts).replace("|", "\\|") or "–"


def write_readme(report_dir):
    """REPORT/README.md from every <case>.json in REPORT."""
    results = []
    for fn in sorted(glob.glob(os.path.join(report_dir, "*.json"))):
        try:
            with open(fn, encoding="utf-8") as f:
                d = json.load(f)
        except (OSError, ValueError):
            continue
        if isinstance(d, dict) and "case" in d and "quantities" in d:
            results.append(d)
    lines = ["# Validation", "",
             "Generated by `tools/validate.py` (see [docs/validation.md](../validation.md)); one row per case at "
             "its finest resolution run. Each case's page has the plots, every resolution, the convergence "
             "order and the speed against error.", ""]
    cmds = []
    for r in results:
        for c in (r.get("command"), r.get("picture_command")):
            if c and c not in cmds:
                cmds.append(c)
    if cmds:
        lines += ["Commands:", ""] + [f"    {c}" for c in cmds] + [""]
    lines += ["| case | resolution | particles | device | wall time [s] | checks (error, tolerance) | result | date, commit |",
              "|---|---|---|---|---|---|---|---|"]
    for r in results:
        head = r.get("headline")
        run = next((x for x in r["runs"] if x["resolution"] == head), {})
        short = [x if len(x) < 160 else x[:157] + "…" for x in r["reasons"][:3]]
        why = ("<br>" + "<br>".join(short)).replace("|", "\\|") if r["status"] == "FAIL" and short else ""
        lines.append(f"| [{r['case']}]({r['case']}.md) | {head or '–'} | {_num(run.get('particles'), '{:,}')} | "
                     f"{device_text(run) if run else '–'} | {_num(run.get('wall_time_s'), '{:.1f}')} | "
                     f"{_checks_cell(r)} | **{r['status']}**{why} | {r.get('date', '?')}, {r.get('commit', '?')} |")
    speed = [r for r in results if r.get("primary") and len(r["primary"]["rows"]) >= 2]
    if speed:
        lines += ["", "## Speed against error", "", "| case | primary check | " +
                  " | ".join(["coarse", "medium", "fine"]) + " |", "|---|---|---|---|---|"]
        for r in speed:
            p = r["primary"]
            cells = []
            for res in ("coarse", "medium", "fine"):
                row = next((x for x in p["rows"] if x["resolution"] == res), None)
                if row is None:
                    cells.append("–")
                    continue
                e = f"{100 * abs(row['error']):.3g}%" if row["error_kind"] == "rel" else f"{abs(row['error']):.3g}"
                cells.append(f"{e} in {_num(row.get('wall_time_s'), '{:.1f}')} s")
            lines.append(f"| [{r['case']}]({r['case']}.md) | `{p['quantity']}` {p['metric']} | " + " | ".join(cells) + " |")
    pics = [r for r in results if (r.get("images") or {}).get("_paraview")]
    pics.sort(key=lambda r: "gate" not in r["case"])      # the sluice gate first
    for r in pics:
        lines += ["", f"### {r['title']}", "", f"![{r['case']}]({r['images']['_paraview']})"]
    with open(os.path.join(report_dir, "README.md"), "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")
    return results
