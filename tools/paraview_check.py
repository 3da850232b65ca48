#!/usr/bin/env python3
"""Checks a SeaSpring run with ParaView's own readers and renders a picture of it.

Usage: xvfb-run -a pvpython tools/paraview_check.py RUNDIR|RUNDIR/parts.xdmf
           [--png FILE] [--title TEXT] [--time T] [--width PIXELS] [--view auto|xz|iso]
(Debian: paraview python3-paraview xvfb xauth; ParaView 5.11.) It
- opens parts.xdmf with the XDMF3 reader: the number of time steps must equal the number of
  part files in RUNDIR/data, the last step must have points and the arrays the solver writes
  (vel rhop press type mk id excluded mass; disp strain damage broken when there are solids);
- opens RUNDIR/vtk/part_*.vtu (when present) with the VTU reader: one file per time step,
  the same points and arrays;
- with --png, renders the last step (or --time): fluid coloured by velocity magnitude, solids
  by displacement magnitude (by damage when bonds broke), walls grey; 2D cases seen along y,
  3D cases cut at mid-width; and checks that the picture is not blank.
Exit 0 when everything passed, 1 otherwise; one summary line per part ('xdmf:', 'vtu:',
'picture:', 'FAIL ...').
"""
import argparse
import glob
import os
import sys

from paraview import servermanager
from paraview import simple as pv
from vtkmodules.numpy_interface import dataset_adapter as dsa
from vtkmodules.vtkIOImage import vtkPNGReader
import numpy as np

FLUID_ARRAYS = ("vel", "rhop", "press", "type", "mk", "id", "excluded", "mass")
SOLID_ARRAYS = ("disp", "strain", "damage", "broken")
failures = []


def fail(msg):
    failures.append(msg)
    print("FAIL " + msg)


def arrays_of(data):
    pd = data.GetPointData()
    return [pd.GetArrayName(i) for i in range(pd.GetNumberOfArrays())]


def check_xdmf(xdmf, rundir):
    reader = pv.Xdmf3ReaderS(FileName=[xdmf])
    reader.UpdatePipelineInformation()
    times = list(reader.TimestepValues)
    nparts = len(glob.glob(os.path.join(rundir, "data", "part_*.h5")))
    if not times:
        fail(f"{xdmf}: no time steps")
        return reader, times, None
    if nparts and nparts != len(times):
        fail(f"{xdmf}: {len(times)} time steps but {nparts} part files in data/")
    reader.UpdatePipeline(times[-1])
    data = dsa.WrapDataObject(servermanager.Fetch(reader))
    names = arrays_of(data.VTKObject)
    solids = "type" in names and bool(np.any(np.asarray(data.PointData["type"]) == 2))
    need = FLUID_ARRAYS + (SOLID_ARRAYS if solids else ())
    missing = [n for n in need if n not in names]
    if missing:
        fail(f"{xdmf}: missing arrays {', '.join(missing)}")
    if data.GetNumberOfPoints() == 0:
        fail(f"{xdmf}: no points at t = {times[-1]}")
    print(f"xdmf: {len(times)} time steps (t = {times[0]:g} .. {times[-1]:g} s), {data.GetNumberOfPoints()} points, "
          f"{data.GetNumberOfCells()} cells, arrays {' '.join(names)}{', solids' if solids else ''}")
    return reader, times, (data.GetNumberOfPoints(), set(names), solids)


def check_vtu(vtkdir, times, info):
    files = sorted(glob.glob(os.path.join(vtkdir, "part_*.vtu")))
    if not files:
        print(f"vtu: no {vtkdir}/part_*.vtu (run with -sv:h5,vtk to check them)")
        return
    if times and len(files) != len(times):
        fail(f"{vtkdir}: {len(files)} VTU files but {len(times)} XDMF time steps")
    reader = pv.XMLUnstructuredGridReader(FileName=files)
    reader.UpdatePipelineInformation()
    steps = list(reader.TimestepValues) or [0]
    reader.UpdatePipeline(steps[-1])
    data = servermanager.Fetch(reader)
    names = arrays_of(data)
    if info:
        npts, xnames, solids = info
        if data.GetNumberOfPoints() != npts:
            fail(f"{files[-1]}: {data.GetNumberOfPoints()} points, the XDMF has {npts}")
        missing = [n for n in sorted(xnames | {"mass"}) if n not in names]
        if missing:
            fail(f"{files[-1]}: missing arrays {', '.join(missing)}")
    print(f"vtu: {len(files)} files, {len(steps)} time steps in the reader, {data.GetNumberOfPoints()} points, "
          f"{data.GetNumberOfCells()} cells, arrays {' '.join(names)}")


def spacing(points, types):
    """The particle spacing, from the fixed boundary particles' lattice coordinates."""
    p = points[types == 0] if np.any(types == 0) else points
    best = None
    for axis in range(3):
        u = np.unique(np.round(p[:, axis], 9))
        d = np.diff(u)
        d = d[d > 1e-9]
        if d.size:
            best = d.min() if best is None else min(best, d.min())
    if best is None:
        ext = np.ptp(points, axis=0)
        best = float(np.sqrt(max(ext[0] * max(ext[2], 1e-9), 1e-12) / max(len(points), 1)))
    return float(best)


def part(source, lo, hi, array="type"):
    t = pv.Threshold(Input=source, Scalars=["POINTS", array])
    t.LowerThreshold, t.UpperThreshold = lo, hi
    t.ThresholdMethod = "Between"
    return t


def show(src, view, radius, array=None, preset=None, title=None, colour=None):
    d = pv.Show(src, view)
    d.SetRepresentationType("Point Gaussian")
    d.GaussianRadius = radius
    d.ShaderPreset = "Plain circle"
    if array:
        pv.ColorBy(d, ("POINTS", array, "Magnitude"))
        lut = pv.GetColorTransferFunction(array)
        lut.ApplyPreset(preset, True)
        d.RescaleTransferFunctionToDataRange(False, True)
        d.SetScalarBarVisibility(view, True)
        bar = pv.GetScalarBar(lut, view)
        bar.Title, bar.ComponentTitle = title, ""
        bar.TitleColor = bar.LabelColor = [0.1, 0.1, 0.1]
        bar.TitleFontSize, bar.LabelFontSize = 14, 12
    else:
        pv.ColorBy(d, None)
        d.AmbientColor = d.DiffuseColor = colour
    return d


def render(reader, times, args):
    t = times[-1] if args.time is None else min(times, key=lambda x: abs(x - args.time))
    verts = pv.MaskPoints(Input=reader, OnRatio=1, MaximumNumberofPoints=2**31 - 1, GenerateVertices=1,
                          SingleVertexPerCell=1, RandomSampling=0)     # the XDMF Polyvertex has no cells
    verts.UpdatePipeline(t)
    data = dsa.WrapDataObject(servermanager.Fetch(verts))
    pts, types = np.asarray(data.Points), np.asarray(data.PointData["type"])
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    ext = hi - lo
    dp = spacing(pts, types)
    view_kind = args.view if args.view != "auto" else ("xz" if ext[1] < 2 * dp else "iso")
    src = verts
    if view_kind == "iso":      # cut at mid-width, keep the far half
        src = pv.Clip(Input=verts, ClipType="Plane")
        src.ClipType.Origin = list((lo + hi) / 2)
        src.ClipType.Normal = [0, -1, 0]
    view = pv.CreateView("RenderView")
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [1, 1, 1]
    view.ViewTime = t
    width = args.width
    W, H = ext[0] + 2 * dp, ext[2] + 2 * dp          # xz: 170 px on the right for the colour bars,
    scale = W / (width - 180)                        # 40 px above for the title, 20 below [m/px]
    height = int(np.clip(H / scale + 60, 300, 1.2 * width)) if view_kind == "xz" else int(0.65 * width)
    scale = max(scale, H / (height - 60))
    view.ViewSize = [width, height]
    show(part(src, 0, 1), view, 0.5 * dp, colour=[0.62, 0.62, 0.62])
    excl = part(part(src, 3, 3), 0, 0, "excluded")
    show(excl, view, 0.5 * dp, "vel", "Cool to Warm", "fluid |vel| [m/s]")
    solid_mask = types == 2
    if solid_mask.any():
        dmg = np.asarray(data.PointData["damage"])[solid_mask] if "damage" in arrays_of(data.VTKObject) else None
        field = "damage" if dmg is not None and dmg.max() > 0 else "disp"
        show(part(src, 2, 2), view, 0.5 * dp, field, "Inferno (matplotlib)",
             "solid damage" if field == "damage" else "solid |disp| [m]")
    title = pv.Text(Text=f"{args.title}  t = {t:.3f} s" if args.title else f"t = {t:.3f} s")
    td = pv.Show(title, view)
    td.Color, td.FontSize, td.WindowLocation = [0.1, 0.1, 0.1], 16, "Upper Center"
    pv.Render(view)         # the first Render resets the camera: place it afterwards
    centre = list((lo + hi) / 2)
    view.CameraFocalPoint = centre
    if view_kind == "xz":
        fx = centre[0] + (width / 2 - (10 + 0.5 * W / scale)) * scale
        fz = centre[2] + (height / 2 - (20 + 0.5 * H / scale)) * scale
        view.CameraFocalPoint = [fx, centre[1], fz]
        view.CameraPosition = [fx, centre[1] - 10 * max(ext), fz]
        view.CameraViewUp = [0, 0, 1]
        view.CameraParallelProjection = 1
        view.CameraParallelScale = 0.5 * height * scale
    else:
        view.CameraPosition = [centre[0] + 0.6 * max(ext), centre[1] - 2.0 * max(ext), centre[2] + 0.9 * max(ext)]
        view.CameraViewUp = [0, 0, 1]
        view.ResetCamera(False)
        view.GetActiveCamera().Dolly(1.25)
    pv.Render(view)
    os.makedirs(os.path.dirname(os.path.abspath(args.png)), exist_ok=True)
    pv.SaveScreenshot(args.png, view, ImageResolution=[width, height], TransparentBackground=0)
    check_picture(args.png)


def check_picture(png):
    r = vtkPNGReader()
    r.SetFileName(png)
    r.Update()
    img = r.GetOutput()
    if img is None or img.GetNumberOfPoints() == 0:
        fail(f"{png}: not written")
        return
    px = dsa.WrapDataObject(img).PointData[0]
    px = np.asarray(px)[:, :3].astype(int)
    background = np.all(px >= 250, axis=1)
    frac = 1 - background.mean()
    colours = len(np.unique(px[~background], axis=0)) if frac > 0 else 0
    w, h, _ = img.GetDimensions()
    print(f"picture: {png} {w}x{h}, {100 * frac:.1f}% of the pixels drawn, {colours} colours")
    if frac < 0.02 or colours < 16:
        fail(f"{png}: the picture is (nearly) blank")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run", help="run folder (with parts.xdmf) or the parts.xdmf file")
    ap.add_argument("--vtk", help="folder of part_*.vtu (default RUNDIR/vtk)")
    ap.add_argument("--png", help="render the picture into this file")
    ap.add_argument("--title", default="")
    ap.add_argument("--time", type=float, help="time to render [s] (default: the last)")
    ap.add_argument("--width", type=int, default=1200)
    ap.add_argument("--view", choices=("auto", "xz", "iso"), default="auto")
    args = ap.parse_args()
    xdmf = os.path.abspath(args.run)
    if os.path.isdir(xdmf):
        xdmf = os.path.join(xdmf, "parts.xdmf")
    if not os.path.isfile(xdmf):
        print(f"FAIL {xdmf}: not found")
        return 1
    rundir = os.path.dirname(xdmf)
    reader, times, info = check_xdmf(xdmf, rundir)
    check_vtu(args.vtk or os.path.join(rundir, "vtk"), times, info)
    if args.png and times and info and info[0]:
        render(reader, times, args)
    return 1 if failures else 0


if __name__ == "__main__":
    code = main()
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(code)      # skip the X/GL teardown, which fails under xvfb-run (GLXBadContext)
