"""Metrics of a series against a reference, checks against tolerances, convergence order.

Definitions (docs/validation.md):
- peak: the sample of largest |value| (sign kept), ours against the reference's peak (or the
  analytic value); optional window.
- peak_time: the time of our peak against the time of the reference's peak.
- rms: ours interpolated (linearly) at the reference's sample times inside the window,
  RMS of the difference; against an analytic value, RMS of our samples minus the value.
- mean: time average (trapezoidal) of ours over the window against the analytic value, or
  against the reference's time average over the same window.
- onset_time: the first time in the window at which the series reaches the check's threshold
  (rising to it for a threshold >= 0, falling to it for a negative one), interpolated linearly
  between the samples on either side, ours against the reference's (e.g. the arrival of an
  impact at a pressure sensor).
A check passes when |ours - reference| <= abs_tol + rel_tol * |scale| (+ the reference's band
when use_band), scale being the reference value (rms: the reference's peak). The error shown
is relative when only rel_tol is given, absolute otherwise.
"""
import math

import numpy as np


class MetricError(Exception):
    """A metric that cannot be computed (no samples in the window, zero reference, ...)."""


def _window(t, window):
    if window is None:
        return np.ones(t.shape, dtype=bool)
    return (t >= window[0]) & (t <= window[1])


def peak(t, v, window=None):
    """(value, time) of the sample with the largest |value| inside the window; the first
    such sample on ties."""
    m = _window(t, window)
    if not m.any():
        raise MetricError(f"no sample inside the window {window} (series spans {t[0]:.4g}-{t[-1]:.4g} s)")
    idx = np.nonzero(m)[0]
    k = idx[np.argmax(np.abs(v[idx]))]
    return float(v[k]), float(t[k])


def _covers(t, window, what="run"):
    span = window[1] - window[0]
    if t[0] > window[0] + 0.01 * span or t[-1] < window[1] - 0.01 * span:
        raise MetricError(f"the {what} spans {t[0]:.4g}-{t[-1]:.4g} s, not the window "
                          f"{window[0]:.4g}-{window[1]:.4g} s")


def time_mean(t, v, window=None):
    """Trapezoidal time average over the window (default: the whole series)."""
    if window is None:
        window = [float(t[0]), float(t[-1])]
    _covers(t, window)
    if window[1] <= window[0] or t.size < 2:
        raise MetricError(f"window {window} too short for a time average")
    inner = (t > window[0]) & (t < window[1])
    tt = np.concatenate(([window[0]], t[inner], [window[1]]))
    vv = np.interp(tt, t, v)
    return float(np.sum(0.5 * (vv[1:] + vv[:-1]) * np.diff(tt)) / (window[1] - window[0]))


def onset(t, v, threshold, window=None):
    """Time of the first crossing of THRESHOLD inside the window: the first sample with
    value >= threshold (<= threshold when threshold < 0), the time interpolated linearly
    between it and the sample before. The series must start below the threshold (above it
    for a negative one) inside the window: a series that is already there has no onset."""
    m = _window(t, window)
    idx = np.nonzero(m)[0]
    if idx.size == 0:
        raise MetricError(f"no sample inside the window {window} (series spans {t[0]:.4g}-{t[-1]:.4g} s)")
    tt, vv = t[idx], v[idx]
    sign = 1.0 if threshold >= 0 else -1.0
    hit = np.nonzero(sign * vv >= sign * threshold)[0]
    where = f"inside the window {window}" if window is not None else "in the series"
    if hit.size == 0:
        raise MetricError(f"never reaches the threshold {threshold:g} {where} "
                          f"(extreme {vv.max() if sign > 0 else vv.min():.4g})")
    k = int(hit[0])
    if k == 0:
        raise MetricError(f"already at the threshold {threshold:g} at the first sample {where} "
                          f"(t = {tt[0]:.4g} s): no onset")
    v0, v1 = vv[k - 1], vv[k]
    return float(tt[k - 1] + (threshold - v0) / (v1 - v0) * (tt[k] - tt[k - 1]))


def rms_error(t, v, rt, rv, window=None):
    """RMS of ours (interpolated) minus the reference at the reference's times inside the
    window and inside our time range. Returns (rms, number of points)."""
    if window is not None:
        _covers(t, window)
    m = _window(rt, window) & (rt >= t[0]) & (rt <= t[-1])
    if not m.any():
        raise MetricError(f"no reference sample inside the window {window} and the run's "
                          f"time range {t[0]:.4g}-{t[-1]:.4g} s")
    d = np.interp(rt[m], t, v) - rv[m]
    return float(np.sqrt(np.mean(d * d))), int(m.sum())


def rms_constant(t, v, value, window=None):
    if window is not None:
        _covers(t, window)
    m = _window(t, window)
    if not m.any():
        raise MetricError(f"no sample inside the window {window}")
    d = v[m] - value
    return float(np.sqrt(np.mean(d * d))), int(m.sum())


def evaluate(check, ref, t, v, ref_series=None):
    """One check of our series (t, v) against REF (a spec.Reference; REF_SERIES its (time,
    value) arrays unless analytic). Returns a dict: ours, reference, diff, error, error_kind,
    allowed (in the units of error), passed, note."""
    w = check.window
    analytic = ref.kind == "analytic"
    rt, rv = (None, None) if analytic else ref_series
    band = 0.0
    note = ""
    if w is not None and check.metric in ("peak", "peak_time"):
        _covers(t, w)
    if check.metric == "peak":
        ours, t_ours = peak(t, v, w)
        refv = ref.value if analytic else peak(rt, rv, w)[0]
        scale, diff, band = refv, ours - refv, ref.band
        note = f"at {t_ours:.4g} s"
    elif check.metric == "peak_time":
        ours = peak(t, v, w)[1]
        refv = peak(rt, rv, w)[1]
        scale, diff, band = refv, ours - refv, ref.time_band
    elif check.metric == "rms":
        if analytic:
            ours, n = rms_constant(t, v, ref.value, w)
            scale = ref.value
        else:
            ours, n = rms_error(t, v, rt, rv, w)
            scale = peak(rt, rv, w)[0]
        refv, diff, band = None, ours, ref.band
        note = f"{n} points"
    elif check.metric == "mean":
        ours = time_mean(t, v, w)
        refv = ref.value if analytic else time_mean(rt, rv, w if w else [float(t[0]), float(t[-1])])
        scale, diff, band = refv, ours - refv, ref.band
    elif check.metric == "onset_time":
        if check.threshold is None:
            raise MetricError("onset_time needs a threshold")
        if analytic:
            raise MetricError("onset_time needs a reference with a time series")
        if w is not None:
            _covers(t, w)
        try:
            ours = onset(t, v, check.threshold, w)
        except MetricError as e:
            raise MetricError(f"ours: {e}")
        try:
            refv = onset(rt, rv, check.threshold, w)
        except MetricError as e:
            raise MetricError(f"reference: {e}")
        scale, diff, band = refv, ours - refv, ref.time_band
    else:
        raise MetricError(f"unknown metric {check.metric}")
    band = band if check.use_band else 0.0
    rel_only = check.rel_tol is not None and check.abs_tol is None
    if rel_only and scale == 0:
        raise MetricError(f"{check.metric}: the reference is 0, a relative tolerance is undefined; use abs_tol")
    allowed = (check.abs_tol or 0.0) + (check.rel_tol or 0.0) * abs(scale) + band
    passed = abs(diff) <= allowed * (1 + 1e-12)
    if rel_only:
        error, shown, kind = diff / abs(scale), allowed / abs(scale), "rel"
    else:
        error, shown, kind = diff, allowed, "abs"
    return {"metric": check.metric, "ours": ours, "reference": refv, "diff": diff,
            "error": error, "error_kind": kind, "allowed": shown, "passed": bool(passed),
            "window": w, "note": note}


def orders(dps, errors):
    """Observed order between successive resolutions: log(e_i/e_i+1) / log(dp_i/dp_i+1).
    None where an error is zero or the spacings are equal."""
    out = []
    for (d1, e1), (d2, e2) in zip(zip(dps, errors), zip(dps[1:], errors[1:])):
        if not e1 or not e2 or d1 == d2 or not math.isfinite(e1) or not math.isfinite(e2):
            out.append(None)
        else:
            out.append(math.log(abs(e1) / abs(e2)) / math.log(d1 / d2))
    return out


def richardson_order(dps, values):
    """Self-convergence order from three values at spacings with one refinement ratio:
    log(|f1-f2| / |f2-f3|) / log(r). None when it is not defined."""
    if len(dps) != 3 or len(values) != 3:
        return None
    r1, r2 = dps[0] / dps[1], dps[1] / dps[2]
    a, b = values[0] - values[1], values[1] - values[2]
    if abs(r1 - r2) > 0.01 * r1 or r1 <= 1 or a == 0 or b == 0 or a * b < 0:
        return None
    return math.log(abs(a) / abs(b)) / math.log(r1)
