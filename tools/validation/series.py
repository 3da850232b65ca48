"""Time series: the solver's gauge CSVs, reference data files, and solid markers from the
part files (the 'marker' extension, for runs without gauges)."""
import glob
import os
import re

import numpy as np


class SeriesError(Exception):
    """A series that cannot be read: the message names the file and what is wrong."""


def _clean(name):
    """Header name without units or spaces: 'dispx [m]' -> 'dispx'."""
    return re.sub(r"\s*[\[(].*$", "", name.strip()).strip().lower()


def _rows(path, delim):
    rows = []
    with open(path, encoding="utf-8", errors="replace") as f:
        for n, line in enumerate(f, 1):
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            cells = line.split(delim) if delim else line.split()
            if cells and cells[-1].strip() == "":
                cells = cells[:-1]          # trailing separator
            rows.append((n, [c.strip() for c in cells]))
    return rows


def _numbers(path, rows):
    try:
        data = [[float(c) for c in cells] for _, cells in rows]
    except ValueError:
        for n, cells in rows:
            for c in cells:
                try:
                    float(c)
                except ValueError:
                    raise SeriesError(f"{path}:{n}: not a number: {c!r}")
    widths = {len(r) for r in data}
    if len(widths) != 1:
        n = next(n for (n, _), r in zip(rows, data) if len(r) != len(data[0]))
        raise SeriesError(f"{path}:{n}: expected {len(data[0])} columns like the first data row")
    return np.array(data, dtype=float)


def read_gauge(path, column):
    """A solver gauge CSV (';' separated, one header line): returns (time, values) of COLUMN
    (a header name, matched without units and case, or an index)."""
    if not os.path.isfile(path):
        raise SeriesError(f"{path}: gauge file not found")
    rows = _rows(path, ";")
    if not rows:
        raise SeriesError(f"{path}: empty file")
    header = [_clean(c) for c in rows[0][1]]
    data = rows[1:]
    if not data:
        raise SeriesError(f"{path}: header only, no data rows")
    arr = _numbers(path, data)
    if isinstance(column, int):
        idx = column
    else:
        try:
            idx = header.index(_clean(column))
        except ValueError:
            raise SeriesError(f"{path}: no column '{column}' (header: {';'.join(rows[0][1])})")
    if not 0 <= idx < arr.shape[1]:
        raise SeriesError(f"{path}: column {column} out of range ({arr.shape[1]} columns)")
    return _sorted(arr[:, 0], arr[:, idx])


def _sorted(t, v):
    order = np.argsort(t, kind="stable")
    return t[order], v[order]


def read_reference(ref):
    """A reference data file (',' ';' or blank separated, optional header lines): returns
    (time, values) scaled by the reference's time_scale and value_scale, sorted by time."""
    path = ref.path
    if not os.path.isfile(path):
        raise SeriesError(f"{path}: reference file not found (from '{ref.file}'; "
                          "set SEASPRING_SHARED when the shared folder is elsewhere)")
    with open(path, encoding="utf-8", errors="replace") as f:
        sample = f.read(4096)
    delim = "," if "," in sample else (";" if ";" in sample else None)
    rows = _rows(path, delim)
    while rows:                               # header lines: anything not numeric
        try:
            [float(c) for c in rows[0][1]]
            break
        except ValueError:
            rows = rows[1:]
    if not rows:
        raise SeriesError(f"{path}: no numeric rows")
    arr = _numbers(path, rows)
    for col in (ref.time_column, ref.value_column):
        if col >= arr.shape[1]:
            raise SeriesError(f"{path}: column {col} out of range ({arr.shape[1]} columns)")
    return _sorted(arr[:, ref.time_column] * ref.time_scale, arr[:, ref.value_column] * ref.value_scale)


_FIELDS = {"pos": "pos", "disp": "disp", "vel": "vel"}


def marker_series(rundir, point, k, column):
    """Mean of FIELD[component] over the K solid particles nearest to POINT in the first part
    file, at every part file of RUNDIR/data. COLUMN is posx|posy|posz|dispx|…|velz."""
    m = re.fullmatch(r"(pos|disp|vel)([xyz])", str(column).lower())
    if not m:
        raise SeriesError(f"marker column '{column}': expected pos, disp or vel + x, y or z")
    import h5py
    files = sorted(glob.glob(os.path.join(rundir, "data", "part_*.h5")))
    if not files:
        raise SeriesError(f"{rundir}/data: no part files")
    comp = "xyz".index(m.group(2))
    with h5py.File(files[0], "r") as f:
        if m.group(1) not in f:
            raise SeriesError(f"{files[0]}: no /{m.group(1)}")
        pos0 = f["pos"][:]
        solid = np.nonzero(f["type"][:] == 2)[0]
    cand = solid if solid.size else np.arange(pos0.shape[0])
    d2 = ((pos0[cand] - np.asarray(point, dtype=float)) ** 2).sum(axis=1)
    pick = np.sort(cand[np.argsort(d2, kind="stable")[:k]])
    t, v = [], []
    for fn in files:
        with h5py.File(fn, "r") as f:
            t.append(float(f.attrs["time"]))
            v.append(float(np.asarray(f[m.group(1)][pick, comp], dtype=float).mean()))
    return np.array(t), np.array(v)


def quantity_series(q, rundir):
    """Our series of quantity Q in RUNDIR: its gauge CSV, else its marker; scaled."""
    path = os.path.join(rundir, "gauges", q.gauge) if q.gauge else None
    if path and (os.path.isfile(path) or q.marker is None):
        t, v = read_gauge(path, q.column)
    else:
        t, v = marker_series(rundir, q.marker["point"], q.marker.get("k", 1), q.column)
    if t.size == 0:
        raise SeriesError(f"{path or rundir}: no samples")
    if q.subtract:
        t2, v2 = read_gauge(os.path.join(rundir, "gauges", q.subtract["gauge"]), q.subtract["column"])
        v = v - np.interp(t, t2, v2)
    return t, v * q.scale
