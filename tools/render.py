#!/usr/bin/env pvpython
"""Pictures and a movie of a SeaSpring run, with ParaView (pvpython; tools/render runs it under
xvfb-run -a when there is no display).

Usage: tools/render RUNDIR [--out DIR] [--fluid speed|press] [--solid disp|damage]
           [--range MIN,MAX] [--first N] [--last N] [--every K] [--width PIXELS]
           [--view auto|xz|iso] [--title TEXT] [--movie auto|avi|ogv|mp4|none] [--fps F]

Reads RUNDIR/parts.xdmf and writes DIR/frame_NNNN.png (default DIR = RUNDIR/render), one per
output time (NNNN = the part number): fluid particles coloured by speed |vel| or pressure,
VCPM solids by displacement |disp| or damage, walls grey; 2D cases seen along y, 3D cases cut
at mid-width (the drawing is tools/paraview_check.py's). The colour ranges are fixed over the
frames (the fields' range over every frame rendered, or --range for the fluid) so the movie
does not flicker. Then the movie DIR/movie.avi from the frames with VTK's vtkFFMPEGWriter
(ParaView's own FFmpeg libraries: no ffmpeg program needed), else DIR/movie.ogv
(vtkOggTheoraWriter); with --movie mp4 the ffmpeg program makes DIR/movie.mp4 (H.264) and the
script stops with a message when ffmpeg is not installed.
Exit 0, 2 with a message on bad input (no parts.xdmf, nothing to draw), 1 when a frame is blank.
"""
import argparse
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import numpy as np  # noqa: E402
from paraview import servermanager  # noqa: E402
from paraview import simple as pv  # noqa: E402
from vtkmodules.numpy_interface import dataset_adapter as dsa  # noqa: E402
from vtkmodules.vtkIOImage import vtkPNGReader  # noqa: E402

import paraview_check as pc  # noqa: E402  (spacing, part, show, check_picture)


class InputError(Exception):
    pass


def fetch(src, t):
    src.UpdatePipeline(t)
    return dsa.WrapDataObject(servermanager.Fetch(src))


def field_range(verts, times, array, types, mag=True):
    lo, hi = np.inf, -np.inf
    for t in times:
        d = fetch(verts, t)
        if array not in pc.arrays_of(d.VTKObject):
            continue
        mask = np.isin(np.asarray(d.PointData["type"]), types)
        if "excluded" in pc.arrays_of(d.VTKObject):
            mask &= np.asarray(d.PointData["excluded"]) == 0
        v = np.asarray(d.PointData[array])[mask]
        if v.size == 0:
            continue
        if mag and v.ndim == 2:
            v = np.linalg.norm(v, axis=1)
        lo, hi = min(lo, float(v.min())), max(hi, float(v.max()))
    return (lo, hi) if lo <= hi else (0.0, 1.0)


def fixed(array, rng):
    """The colour scale of `array` set to rng and kept there over the frames."""
    lut = pv.GetColorTransferFunction(array)
    lut.AutomaticRescaleRangeMode = "Never"
    lut.RescaleTransferFunction(rng[0], rng[1])


def make_movie(frames, out_dir, kind, fps):
    """The movie from the PNG frames; returns its path or a message starting with 'no movie'."""
    if kind == "none":
        return "no movie (--movie none)"
    if kind == "mp4":
        ff = shutil.which("ffmpeg")
        if not ff:
            raise InputError("--movie mp4 needs the ffmpeg program, which is not installed (Debian: ffmpeg); "
                             "--movie avi uses ParaView's own FFmpeg libraries")
        path = os.path.join(out_dir, "movie.mp4")
        listing = os.path.join(out_dir, "frames.txt")
        with open(listing, "w", encoding="utf-8") as f:
            for fr in frames:
                f.write(f"file '{os.path.abspath(fr)}'\nduration {1.0 / fps}\n")
        subprocess.run([ff, "-y", "-loglevel", "error", "-f", "concat", "-safe", "0", "-i", listing,
                        "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-pix_fmt", "yuv420p", "-c:v", "libx264", path],
                       check=True)
        return path
    writers = []
    if kind in ("auto", "avi"):
        try:
            from vtkmodules.vtkIOFFMPEG import vtkFFMPEGWriter
            writers.append(("movie.avi", vtkFFMPEGWriter))
        except ImportError:
            if kind == "avi":
                raise InputError("--movie avi: this ParaView has no vtkFFMPEGWriter") from None
    if kind in ("auto", "ogv"):
        try:
            from vtkmodules.vtkIOOggTheora import vtkOggTheoraWriter
            writers.append(("movie.ogv", vtkOggTheoraWriter))
        except ImportError:
            if kind == "ogv":
                raise InputError("--movie ogv: this ParaView has no vtkOggTheoraWriter") from None
    if not writers:
        return "no movie: neither vtkFFMPEGWriter nor vtkOggTheoraWriter in this ParaView (the frames are there)"
    name, cls = writers[0]
    path = os.path.join(out_dir, name)
    reader = vtkPNGReader()
    w = cls()
    w.SetInputConnection(reader.GetOutputPort())
    w.SetFileName(path)
    w.SetRate(int(max(1, round(fps))))
    if hasattr(w, "SetQuality"):
        w.SetQuality(2)
    started = False
    for fr in frames:
        reader.SetFileName(fr)
        reader.Modified()
        reader.Update()
        if not started:
            w.Start()
            started = True
        w.Write()
    w.End()
    if w.GetError():
        return f"no movie: {cls.__name__} failed on {path}"
    return path


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("run", help="run folder (with parts.xdmf) or the parts.xdmf file")
    ap.add_argument("--out", help="output folder (default RUNDIR/render)")
    ap.add_argument("--fluid", choices=("speed", "press"), default="speed")
    ap.add_argument("--solid", choices=("disp", "damage"), default="disp")
    ap.add_argument("--range", help="MIN,MAX of the fluid colour scale (default: over the frames)")
    ap.add_argument("--first", type=int, default=0, help="first part number")
    ap.add_argument("--last", type=int, default=-1, help="last part number (default: the last)")
    ap.add_argument("--every", type=int, default=1, help="every K-th output time")
    ap.add_argument("--width", type=int, default=1200)
    ap.add_argument("--view", choices=("auto", "xz", "iso"), default="auto")
    ap.add_argument("--title", default="")
    ap.add_argument("--movie", choices=("auto", "avi", "ogv", "mp4", "none"), default="auto")
    ap.add_argument("--fps", type=float, default=10.0)
    a = ap.parse_args(argv)
    xdmf = os.path.abspath(a.run)
    if os.path.isdir(xdmf):
        xdmf = os.path.join(xdmf, "parts.xdmf")
    if not os.path.isfile(xdmf):
        raise InputError(f"{xdmf}: not found (give the run's OUTDIR)")
    rundir = os.path.dirname(xdmf)
    out_dir = os.path.abspath(a.out or os.path.join(rundir, "render"))
    os.makedirs(out_dir, exist_ok=True)
    frange = None
    if a.range:
        try:
            frange = tuple(float(v) for v in a.range.split(","))
        except ValueError:
            frange = ()
        if len(frange) != 2 or not frange[0] < frange[1]:
            raise InputError(f"--range '{a.range}': expected MIN,MAX with MIN < MAX")
    if a.every < 1:
        raise InputError("--every must be >= 1")

    reader = pv.Xdmf3ReaderS(FileName=[xdmf])
    reader.UpdatePipelineInformation()
    times = list(reader.TimestepValues)
    if not times:
        raise InputError(f"{xdmf}: no time steps")
    last = len(times) - 1 if a.last < 0 else min(a.last, len(times) - 1)
    index = list(range(a.first, last + 1, a.every))
    if not index:
        raise InputError(f"{xdmf}: no output time in parts {a.first}..{last}")
    verts = pv.MaskPoints(Input=reader, OnRatio=1, MaximumNumberofPoints=2**31 - 1, GenerateVertices=1,
                          SingleVertexPerCell=1, RandomSampling=0)     # the XDMF Polyvertex has no cells
    first = fetch(verts, times[index[0]])
    pts, types = np.asarray(first.Points), np.asarray(first.PointData["type"])
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    ext = hi - lo
    dp = pc.spacing(pts, types)
    view_kind = a.view if a.view != "auto" else ("xz" if ext[1] < 2 * dp else "iso")
    src = verts
    if view_kind == "iso":
        src = pv.Clip(Input=verts, ClipType="Plane")
        src.ClipType.Origin = list((lo + hi) / 2)
        src.ClipType.Normal = [0, -1, 0]
    fluid_array, fluid_title = ("vel", "fluid |vel| [m/s]") if a.fluid == "speed" else ("press", "fluid pressure [Pa]")
    sel = [times[k] for k in index]
    if frange is None:
        frange = field_range(verts, sel, fluid_array, [3])
    solids = bool(np.any(types == 2))
    solid_array = "damage" if a.solid == "damage" else "disp"

    view = pv.CreateView("RenderView")
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [1, 1, 1]
    width = a.width
    W, H = ext[0] + 2 * dp, ext[2] + 2 * dp
    scale = W / (width - 180)
    height = int(np.clip(H / scale + 60, 300, 1.2 * width)) if view_kind == "xz" else int(0.65 * width)
    height += height % 2            # even sizes for the movie codecs
    scale = max(scale, H / (height - 60))
    view.ViewSize = [width, height]
    pc.show(pc.part(src, 0, 1), view, 0.5 * dp, colour=[0.62, 0.62, 0.62])
    fluid = pc.part(pc.part(src, 3, 3), 0, 0, "excluded")
    pc.show(fluid, view, 0.5 * dp, fluid_array, "Cool to Warm", fluid_title)
    fixed(fluid_array, frange)
    if solids:
        srange = field_range(verts, sel, solid_array, [2])
        pc.show(pc.part(src, 2, 2), view, 0.5 * dp, solid_array, "Inferno (matplotlib)",
                "solid damage" if solid_array == "damage" else "solid |disp| [m]")
        fixed(solid_array, (srange[0], max(srange[1], srange[0] + 1e-12)))
    text = pv.Text(Text="")
    td = pv.Show(text, view)
    td.Color, td.FontSize, td.WindowLocation = [0.1, 0.1, 0.1], 16, "Upper Center"
    view.ViewTime = sel[0]
    pv.Render(view)         # the first Render resets the camera: place it afterwards
    centre = list((lo + hi) / 2)
    if view_kind == "xz":
        fx = centre[0] + (width / 2 - (10 + 0.5 * W / scale)) * scale
        fz = centre[2] + (height / 2 - (20 + 0.5 * H / scale)) * scale
        view.CameraFocalPoint = [fx, centre[1], fz]
        view.CameraPosition = [fx, centre[1] - 10 * max(ext), fz]
        view.CameraViewUp = [0, 0, 1]
        view.CameraParallelProjection = 1
        view.CameraParallelScale = 0.5 * height * scale
    else:
        view.CameraFocalPoint = centre
        view.CameraPosition = [centre[0] + 0.6 * max(ext), centre[1] - 2.0 * max(ext), centre[2] + 0.9 * max(ext)]
        view.CameraViewUp = [0, 0, 1]
        view.ResetCamera(False)
        view.GetActiveCamera().Dolly(1.25)
    frames = []
    for k, t in zip(index, sel):
        view.ViewTime = t
        text.Text = f"{a.title}  t = {t:.3f} s" if a.title else f"t = {t:.3f} s"
        pv.Render(view)
        png = os.path.join(out_dir, f"frame_{k:04d}.png")
        pv.SaveScreenshot(png, view, ImageResolution=[width, height], TransparentBackground=0)
        pc.check_picture(png)
        frames.append(png)
    print(f"render: {len(frames)} frame(s) in {out_dir} ({a.fluid} {frange[0]:.4g}..{frange[1]:.4g})")
    print(f"render: movie: {make_movie(frames, out_dir, a.movie, a.fps)}")
    return 1 if pc.failures else 0


if __name__ == "__main__":
    try:
        code = main(sys.argv[1:])
    except InputError as e:
        print(f"render error: {e}", file=sys.stderr)
        code = 2
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(code)      # skip the X/GL teardown, which fails under xvfb-run (GLXBadContext)
