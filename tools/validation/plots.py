"""PNG plots: each quantity (our curves over the references) and speed against error."""
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

_RES_STYLE = {"coarse": ("#9ecae1", 1.2), "medium": ("#4292c6", 1.5), "fine": ("#08306b", 1.9)}
_REF_COLOURS = ["#d62728", "#ff7f0e", "#2ca02c", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f"]


def quantity_plot(path, title, q, cq, runs):
    """Our series at each resolution over the references (bands shaded, analytic values
    dashed), with the check windows marked."""
    fig, ax = plt.subplots(figsize=(7.5, 4.2), dpi=110)
    for i, ref in enumerate(q.references):
        col = _REF_COLOURS[i % len(_REF_COLOURS)]
        s = cq["refs"][i]
        if ref.kind == "analytic":
            ax.axhline(ref.value, color=col, ls="--", lw=1.2, label=f"{ref.label} ({ref.value:.4g})")
        elif s is not None:
            t, v = s
            style = "o" if ref.kind == "experiment" else "-"
            ax.plot(t, v, style, color=col, ms=4, lw=1.0, mfc="none" if i else col, label=ref.label)
            if ref.band > 0:
                ax.fill_between(t, v - ref.band, v + ref.band, color=col, alpha=0.15, lw=0)
    for run in runs:
        res = run["resolution"]
        if res not in cq["ours"]:
            continue
        t, v = cq["ours"][res]
        colour, lw = _RES_STYLE.get(res, ("k", 1.5))
        ax.plot(t, v, "-", color=colour, lw=lw, label=f"SeaSpring {res} (dp {run['dp']:g} m)")
    t_end = max([cq["ours"][r][0][-1] for r in cq["ours"]] + [c.window[1] for c in q.checks if c.window] + [0])
    if t_end > 0:           # the time range we ran, the y range of what is visible there
        ax.set_xlim(left=min([0.0] + [s[0][0] for s in cq["ours"].values()]), right=1.05 * t_end)
        ys = [r.value for r in q.references if r.kind == "analytic"]
        for t, v in list(cq["ours"].values()) + [s for s in cq["refs"] if s is not None]:
            ys += list(v[t <= 1.05 * t_end])
        if ys:
            lo, hi = min(ys), max(ys)
            pad = 0.08 * (hi - lo) if hi > lo else 0.1 * abs(hi) or 1.0
            ax.set_ylim(lo - pad, hi + pad)
    if getattr(q, "ylim", None):                          # the spec's fixed y range
        ax.set_ylim(*q.ylim)
    windows = {tuple(c.window) for c in q.checks if c.window}
    for w in sorted(windows):
        ax.axvspan(w[0], w[1], color="0.5", alpha=0.06, lw=0)
    for thr in sorted({c.threshold for c in q.checks if getattr(c, "threshold", None) is not None}):
        ax.axhline(thr, color="0.4", ls=":", lw=0.8)      # onset_time thresholds
    ax.set_xlabel("time [s]")
    ax.set_ylabel(q.label)
    ax.set_title(title, fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="best")
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)
    return path


def speed_plot(path, title, primary):
    """|error| of the primary check against wall time, log-log, one point per resolution."""
    rows = [r for r in primary["rows"] if r.get("wall_time_s") and r["error"]]
    if len(rows) < 2:
        return None
    fig, ax = plt.subplots(figsize=(5.5, 4.0), dpi=110)
    x = [r["wall_time_s"] for r in rows]
    rel = rows[0]["error_kind"] == "rel"
    y = [abs(r["error"]) * (100 if rel else 1) for r in rows]
    ax.loglog(x, y, "o-", color="#08306b")
    ax.margins(0.2)
    for xi, yi, r in zip(x, y, rows):
        ax.annotate(f"{r['resolution']}\n{r['particles'] or '?'} particles", (xi, yi), fontsize=7,
                    textcoords="offset points", xytext=(5, 4))
    ax.set_xlabel(f"wall time [s] ({rows[-1].get('device') or '?'})")
    unit = "%" if rel else ""
    ax.set_ylabel(f"|error| of {primary['quantity']} {primary['metric']} {unit}".strip())
    ax.set_title(title, fontsize=10)
    ax.grid(alpha=0.3, which="both")
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)
    return path


def case_plots(report_dir, spec, result, curves):
    """Writes <case>_<quantity>.png for each quantity and <case>_speed.png; returns the
    file names written (relative to REPORT_DIR)."""
    os.makedirs(report_dir, exist_ok=True)
    names = {}
    for q in spec.quantities:
        cq = curves.get(q.name)
        if not cq or (not cq["ours"] and not any(s is not None for s in cq["refs"])):
            continue
        fn = f"{spec.name}_{q.name}.png"
        quantity_plot(os.path.join(report_dir, fn), f"{spec.title}: {q.name}", q, cq, result["runs"])
        names[q.name] = fn
    if result.get("primary"):
        fn = f"{spec.name}_speed.png"
        if speed_plot(os.path.join(report_dir, fn), f"{spec.title}: speed against error", result["primary"]):
            names["_speed"] = fn
    return names
