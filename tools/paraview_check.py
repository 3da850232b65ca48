#!/usr/bin/env python3
"""Opens a SeaSpring parts.xdmf with ParaView's XDMF3 reader and prints what it sees.

Usage: xvfb-run -a pvpython tools/paraview_check.py OUTDIR/parts.xdmf
(needs Debian's paraview and python3-paraview). Exits 1 when the series has no time steps,
no points, or lacks one of the arrays the solver writes.
"""
import os
import sys

from paraview.simple import Xdmf3ReaderS, servermanager

path = os.path.abspath(sys.argv[1])
reader = Xdmf3ReaderS(FileName=[path])
reader.UpdatePipelineInformation()
times = list(reader.TimestepValues)
print(f"{path}: {len(times)} time steps, t = {times[0] if times else None} .. {times[-1] if times else None}")
if not times:
    sys.exit(1)
reader.UpdatePipeline(times[-1])
data = servermanager.Fetch(reader)
pd = data.GetPointData()
names = [pd.GetArrayName(i) for i in range(pd.GetNumberOfArrays())]
print(f"points at the last time: {data.GetNumberOfPoints()}; arrays: {', '.join(names)}")
for name in ("rhop", "press"):
    if pd.GetArray(name) is not None:
        print(f"{name} range: {pd.GetArray(name).GetRange()}")
missing = [n for n in ("vel", "rhop", "press", "type", "mk", "id", "excluded") if n not in names]
if missing or data.GetNumberOfPoints() == 0:
    print("missing arrays: " + ", ".join(missing) if missing else "no points")
    sys.exit(1)
