"""Loads and checks cases/<name>/validation.json (schema: docs/validation.md).

Every error names the file, the key (as a JSON path such as quantities[0].checks[1].rel_tol)
and the offending value. Unknown keys give a warning (keys starting with '_' are comments).
"""
import json
import math
import os
from dataclasses import dataclass, field
from typing import List, Optional

from . import ROOT

METRICS = ("peak", "peak_time", "rms", "mean", "onset_time")
KINDS = ("experiment", "numerical", "analytic")
RESOLUTIONS = ("coarse", "medium", "fine")


class SpecError(Exception):
    """A bad validation.json: the message names the file, the key and the value."""


@dataclass
class Reference:
    label: str
    kind: str
    value: Optional[float] = None      # analytic
    file: Optional[str] = None         # as written in the spec
    path: Optional[str] = None         # resolved absolute path
    time_column: int = 0
    value_column: int = 1
    time_scale: float = 1.0
    value_scale: float = 1.0
    band: float = 0.0
    time_band: float = 0.0


@dataclass
class Check:
    metric: str
    against: int = 0
    rel_tol: Optional[float] = None
    abs_tol: Optional[float] = None
    window: Optional[List[float]] = None
    use_band: bool = False
    key: str = ""                       # JSON path, for messages
    # extension: tolerances for one resolution, e.g. {"coarse": {"rel_tol": 0.45}} (CI's coarse
    # runs judged by a regression bound, the fine runs by the published acceptance)
    by_resolution: dict = field(default_factory=dict)
    # onset_time: the value whose first crossing in the window is the onset (value units)
    threshold: Optional[float] = None


@dataclass
class Quantity:
    name: str
    label: str
    gauge: Optional[str] = None
    column: object = None
    scale: float = 1.0
    marker: Optional[dict] = None      # extension: {"point": [x,y,z], "k": 1}, read from part files
    subtract: Optional[dict] = None    # extension: {"gauge": ..., "column": ...} subtracted (e.g. a root marker)
    references: List[Reference] = field(default_factory=list)
    checks: List[Check] = field(default_factory=list)
    ylim: Optional[List[float]] = None  # extension: the plot's y range (e.g. to keep noisy spikes from hiding the data)


@dataclass
class Resolution:
    name: str
    dp: float
    tmax: float
    tout: Optional[float] = None
    args: List[str] = field(default_factory=list)
    timeout: Optional[float] = None


@dataclass
class CaseSpec:
    name: str
    path: str
    case_dir: str
    title: str
    xml: str
    ci: bool
    resolutions: dict
    quantities: List[Quantity]
    note: str = ""
    picture_time: Optional[float] = None   # extension: the time ParaView renders (default: the last)
    warnings: List[str] = field(default_factory=list)

    @property
    def xml_path(self):
        return os.path.join(self.case_dir, self.xml)


def shared_path(rel, root=ROOT):
    """Resolves a reference path written relative to the repository root. A path into
    ../shared is moved to $SEASPRING_SHARED when that is set."""
    if os.path.isabs(rel):
        return rel
    parts = os.path.normpath(rel).split(os.sep)
    env = os.environ.get("SEASPRING_SHARED")
    if env and len(parts) > 2 and parts[0] == ".." and parts[1] == "shared":
        return os.path.abspath(os.path.join(env, *parts[2:]))
    return os.path.abspath(os.path.join(root, rel))


class _Reader:
    def __init__(self, path):
        self.path = path
        self.warnings = []

    def fail(self, key, msg, value=None, show_value=True):
        shown = f" (value: {json.dumps(value)})" if show_value else ""
        raise SpecError(f"{self.path}: {key}: {msg}{shown}")

    def obj(self, d, key, allowed):
        if not isinstance(d, dict):
            self.fail(key, "expected a JSON object", d)
        for k in d:
            if k not in allowed and not k.startswith("_"):
                self.warnings.append(f"{self.path}: {key + '.' if key else ''}{k}: unknown key, ignored")
        return d

    def get(self, d, key, name, kind, required=True, default=None):
        path = f"{key}.{name}" if key else name
        if name not in d:
            if required:
                self.fail(path, "missing", show_value=False)
            return default
        v = d[name]
        if kind == "number":
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
                self.fail(path, "expected a finite number", v)
        elif kind == "int":
            if isinstance(v, bool) or not isinstance(v, int):
                self.fail(path, "expected an integer", v)
        elif kind == "str":
            if not isinstance(v, str) or not v.strip():
                self.fail(path, "expected a non-empty string", v)
        elif kind == "bool":
            if not isinstance(v, bool):
                self.fail(path, "expected true or false", v)
        elif kind == "list":
            if not isinstance(v, list):
                self.fail(path, "expected a JSON array", v)
        elif kind == "dict":
            if not isinstance(v, dict):
                self.fail(path, "expected a JSON object", v)
        return v

    def positive(self, d, key, name, required=True, allow_zero=False):
        v = self.get(d, key, name, "number", required)
        if v is not None and (v < 0 or (v == 0 and not allow_zero)):
            self.fail(f"{key}.{name}" if key else name, "must be " + ("≥ 0" if allow_zero else "> 0"), v)
        return v

    def window(self, d, key):
        w = self.get(d, key, "window", "list", required=False)
        if w is None:
            return None
        ok = len(w) == 2 and all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in w)
        if not ok or not w[0] < w[1]:
            self.fail(f"{key}.window", "expected [t_start, t_end] with t_start < t_end", w)
        return [float(w[0]), float(w[1])]


def _reference(r, d, key, root):
    r.obj(d, key, {"label", "kind", "value", "file", "time_column", "value_column",
                   "time_scale", "value_scale", "band", "time_band"})
    kind = r.get(d, key, "kind", "str")
    if kind not in KINDS:
        r.fail(f"{key}.kind", f"expected one of {', '.join(KINDS)}", kind)
    ref = Reference(label=r.get(d, key, "label", "str"), kind=kind)
    if kind == "analytic":
        ref.value = float(r.get(d, key, "value", "number"))
        return ref
    ref.file = r.get(d, key, "file", "str")
    ref.path = shared_path(ref.file, root)
    for col in ("time_column", "value_column"):
        v = r.get(d, key, col, "int", required=False, default=getattr(ref, col))
        if v < 0:
            r.fail(f"{key}.{col}", "must be ≥ 0", v)
        setattr(ref, col, v)
    ref.time_scale = float(r.get(d, key, "time_scale", "number", False, 1.0))
    ref.value_scale = float(r.get(d, key, "value_scale", "number", False, 1.0))
    ref.band = float(r.positive(d, key, "band", False, True) or 0.0)
    ref.time_band = float(r.positive(d, key, "time_band", False, True) or 0.0)
    return ref


def _check(r, d, key, refs, qkey):
    r.obj(d, key, {"metric", "against", "rel_tol", "abs_tol", "window", "use_band", "by_resolution", "threshold"})
    metric = r.get(d, key, "metric", "str")
    if metric not in METRICS:
        r.fail(f"{key}.metric", f"expected one of {', '.join(METRICS)}", metric)
    c = Check(metric=metric, key=key)
    c.against = r.get(d, key, "against", "int", required=False, default=0)
    if not 0 <= c.against < len(refs):
        r.fail(f"{key}.against", f"no such reference in {qkey}.references ({len(refs)} given)", c.against)
    c.rel_tol = r.positive(d, key, "rel_tol", False, True)
    c.abs_tol = r.positive(d, key, "abs_tol", False, True)
    if c.rel_tol is None and c.abs_tol is None:
        r.fail(key, "needs rel_tol or abs_tol", d)
    c.window = r.window(d, key)
    c.use_band = r.get(d, key, "use_band", "bool", required=False, default=False)
    for res, tol in (r.get(d, key, "by_resolution", "dict", required=False) or {}).items():
        bkey = f"{key}.by_resolution.{res}"
        if res not in RESOLUTIONS:
            r.fail(bkey, f"expected one of {', '.join(RESOLUTIONS)}", res)
        r.obj(tol, bkey, {"rel_tol", "abs_tol"})
        rel, ab = r.positive(tol, bkey, "rel_tol", False, True), r.positive(tol, bkey, "abs_tol", False, True)
        if rel is None and ab is None:
            r.fail(bkey, "needs rel_tol or abs_tol", tol)
        c.by_resolution[res] = (rel, ab)
    c.threshold = r.get(d, key, "threshold", "number", required=metric == "onset_time")
    if c.threshold is not None:
        if metric != "onset_time":
            r.fail(f"{key}.threshold", f"only onset_time takes a threshold, not {metric}", c.threshold)
        c.threshold = float(c.threshold)
    ref = refs[c.against]
    if ref.kind == "analytic" and metric in ("peak_time", "onset_time"):
        r.fail(f"{key}.against", f"{metric} needs a reference with a time series, "
               f"not the analytic value '{ref.label}'", c.against)
    return c


def _quantity(r, d, key, root):
    r.obj(d, key, {"name", "label", "gauge", "column", "scale", "marker", "subtract", "references", "checks",
                   "ylim"})
    q = Quantity(name=r.get(d, key, "name", "str"), label=r.get(d, key, "label", "str"))
    if not all(ch.isalnum() or ch in "_-" for ch in q.name):
        r.fail(f"{key}.name", "use letters, digits, '_' or '-' only (it names files)", q.name)
    q.gauge = r.get(d, key, "gauge", "str", required=False)
    q.marker = r.get(d, key, "marker", "dict", required=False)
    if q.gauge is None and q.marker is None:
        r.fail(key, "needs 'gauge' (a CSV in OUTDIR/gauges) or 'marker'", show_value=False)
    if q.marker is not None:
        r.obj(q.marker, f"{key}.marker", {"point", "k"})
        p = r.get(q.marker, f"{key}.marker", "point", "list")
        if len(p) != 3 or not all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in p):
            r.fail(f"{key}.marker.point", "expected [x, y, z]", p)
        k = r.get(q.marker, f"{key}.marker", "k", "int", required=False, default=1)
        if k < 1:
            r.fail(f"{key}.marker.k", "must be ≥ 1", k)
    q.subtract = r.get(d, key, "subtract", "dict", required=False)
    if q.subtract is not None:
        r.obj(q.subtract, f"{key}.subtract", {"gauge", "column"})
        r.get(q.subtract, f"{key}.subtract", "gauge", "str")
        sc = q.subtract.get("column")
        if sc is None or isinstance(sc, bool) or not isinstance(sc, (str, int)):
            r.fail(f"{key}.subtract.column", "expected a column name or index", sc, "column" in q.subtract)
    col = d.get("column")
    if col is None or isinstance(col, bool) or not isinstance(col, (str, int)) or col == "":
        r.fail(f"{key}.column", "expected a column name (as in the CSV header) or index", col,
               show_value="column" in d)
    q.column = col
    q.scale = float(r.get(d, key, "scale", "number", required=False, default=1.0))
    ylim = r.get(d, key, "ylim", "list", required=False)
    if ylim is not None:
        ok = len(ylim) == 2 and all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in ylim)
        if not ok or not ylim[0] < ylim[1]:
            r.fail(f"{key}.ylim", "expected [y_min, y_max] with y_min < y_max", ylim)
        q.ylim = [float(ylim[0]), float(ylim[1])]
    refs = r.get(d, key, "references", "list", required=False, default=[])
    q.references = [_reference(r, x, f"{key}.references[{i}]", root) for i, x in enumerate(refs)]
    checks = r.get(d, key, "checks", "list", required=False, default=[])
    q.checks = [_check(r, x, f"{key}.checks[{i}]", q.references, key) for i, x in enumerate(checks)]
    return q


def load(path, root=ROOT):
    """Reads and checks one validation.json; returns a CaseSpec or raises SpecError."""
    path = os.path.abspath(path)
    try:
        with open(path, encoding="utf-8") as f:
            text = f.read()
    except OSError as e:
        raise SpecError(f"{path}: cannot read: {e.strerror}")
    try:
        d = json.loads(text)
    except json.JSONDecodeError as e:
        raise SpecError(f"{path}:{e.lineno}:{e.colno}: not valid JSON: {e.msg}")
    r = _Reader(path)
    r.obj(d, "", {"title", "xml", "ci", "resolutions", "quantities", "note", "picture_time"})
    case_dir = os.path.dirname(path)
    spec = CaseSpec(name=os.path.basename(case_dir), path=path, case_dir=case_dir,
                    title=r.get(d, "", "title", "str"), xml=r.get(d, "", "xml", "str"),
                    ci=r.get(d, "", "ci", "bool", required=False, default=False),
                    resolutions={}, quantities=[], note=d.get("note", "") or "")
    spec.picture_time = r.positive(d, "", "picture_time", required=False, allow_zero=True)
    if not os.path.isfile(spec.xml_path):
        r.fail("xml", f"no such file in {case_dir}", spec.xml)
    res = r.get(d, "", "resolutions", "dict")
    if not res:
        r.fail("resolutions", "needs at least one of " + ", ".join(RESOLUTIONS), res)
    for name, rd in res.items():
        key = f"resolutions.{name}"
        if name not in RESOLUTIONS:
            r.fail("resolutions", f"unknown resolution '{name}' (expected {', '.join(RESOLUTIONS)})", name)
        r.obj(rd, key, {"dp", "tmax", "tout", "args", "timeout"})
        args = r.get(rd, key, "args", "list", required=False, default=[])
        if not all(isinstance(a, str) for a in args):
            r.fail(f"{key}.args", "expected a list of strings", args)
        spec.resolutions[name] = Resolution(name, r.positive(rd, key, "dp"), r.positive(rd, key, "tmax"),
                                            r.positive(rd, key, "tout", False), args,
                                            r.positive(rd, key, "timeout", False))
    quantities = r.get(d, "", "quantities", "list")
    if not quantities:
        r.fail("quantities", "needs at least one quantity", quantities)
    spec.quantities = [_quantity(r, q, f"quantities[{i}]", root) for i, q in enumerate(quantities)]
    names = [q.name for q in spec.quantities]
    for i, n in enumerate(names):
        if n in names[:i]:
            r.fail(f"quantities[{i}].name", "used twice", n)
    spec.warnings = r.warnings
    return spec


def find_cases(cases_dir):
    """Names of the case folders that hold a validation.json, sorted."""
    if not os.path.isdir(cases_dir):
        return []
    return sorted(n for n in os.listdir(cases_dir)
                  if os.path.isfile(os.path.join(cases_dir, n, "validation.json")))
