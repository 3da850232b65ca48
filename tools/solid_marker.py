#!/usr/bin/env python3
"""Displacement history of a solid marker from a seaspring output folder.

The marker is the solid particle (type 2) nearest to POINT in the initial configuration
(first part file), or the mean of the K nearest with --k. Writes CSV `time_s;dx_m;dy_m;dz_m`
to stdout or --csv, and with --ref-x/--ref-z (CSV files `time_s,displacement_m`) prints the
peak and RMS error against them.

Usage: solid_marker.py OUTDIR --point X,Y,Z [--k 1] [--csv FILE] [--ref-x F] [--ref-z F]
Needs numpy and h5py (Debian: python3-numpy python3-h5py; run with /usr/bin/python3).
"""
import argparse
import glob
import os
import sys

import numpy as np
import h5py


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("outdir")
    ap.add_argument("--point", required=True, help="X,Y,Z [m] in the initial configuration")
    ap.add_argument("--k", type=int, default=1, help="average over the k nearest solid particles")
    ap.add_argument("--csv", help="write the series here (default: stdout)")
    ap.add_argument("--ref-x", help="reference CSV (time_s, displacement_m) for dx")
    ap.add_argument("--ref-z", help="reference CSV (time_s, displacement_m) for dz")
    ap.add_argument("--window", type=float, default=None, help="RMS window end [s] (default: common range)")
    a = ap.parse_args()
    files = sorted(glob.glob(os.path.join(a.outdir, "data", "part_*.h5")))
    if not files:
        sys.exit(f"{a.outdir}/data: no part files")
    point = np.array([float(v) for v in a.point.split(",")])
    if point.size != 3:
        sys.exit(f"--point {a.point}: expected X,Y,Z")
    with h5py.File(files[0], "r") as f:
        if "disp" not in f:
            sys.exit(f"{files[0]}: no solid fields (/disp): the case has no VCPM solids")
        pos0 = f["pos"][:]
        solid = np.nonzero(f["type"][:] == 2)[0]
    d2 = ((pos0[solid] - point) ** 2).sum(axis=1)
    pick = np.sort(solid[np.argsort(d2)[: a.k]])
    rows = []
    for fn in files:
        with h5py.File(fn, "r") as f:
            rows.append([f.attrs["time"], *f["disp"][pick].astype(float).mean(axis=0)])
    rows = np.array(rows)
    out = open(a.csv, "w") if a.csv else sys.stdout
    out.write("time_s;dx_m;dy_m;dz_m\n")  # ';' as the solver's CSV files
    for r in rows:
        out.write(f"{r[0]:.6g};{r[1]:.6e};{r[2]:.6e};{r[3]:.6e}\n")
    if a.csv:
        out.close()
    print(f"marker: {a.k} particle(s) nearest to {a.point}, first at {pos0[pick[0]]}", file=sys.stderr)
    for ref, col, name in ((a.ref_x, 1, "dx"), (a.ref_z, 3, "dz")):
        if not ref:
            continue
        rt, rv = np.loadtxt(ref, delimiter=",", skiprows=1, unpack=True)
        t_end = min(rows[-1, 0], rt[-1]) if a.window is None else a.window
        m = (rt >= rows[0, 0]) & (rt <= t_end)
        if not m.any():
            print(f"{name}: no reference point inside the run's time range (0-{rows[-1, 0]:.3f} s)", file=sys.stderr)
            continue
        ours = np.interp(rt[m], rows[:, 0], rows[:, col])
        rms = np.sqrt(np.mean((ours - rv[m]) ** 2))
        k = np.argmax(np.abs(rows[:, col]))
        kr = np.argmax(np.abs(rv))
        print(f"{name}: peak {rows[k, col]:.4e} m at {rows[k, 0]:.3f} s (reference {rv[kr]:.4e} m at {rt[kr]:.3f} s, "
              f"{100 * (rows[k, col] / rv[kr] - 1):+.1f}%); RMS vs reference over {rt[m][0]:.3f}-{rt[m][-1]:.3f} s: "
              f"{rms:.3e} m", file=sys.stderr)


if __name__ == "__main__":
    main()
