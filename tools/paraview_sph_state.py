"""ParaView state for probing and slicing a SeaSpring run with ParaView's SPH filters (issue 15):
open it with File > Load State (Python state file) in the ParaView GUI after setting PARTS below,
or run it with pvpython:

    pvpython tools/paraview_sph_state.py OUTDIR/parts.xdmf [--png FILE] [--csv FILE] [--time T]

(under `xvfb-run -a` on a machine without a display). It builds, on the run's parts.xdmf:
- "fluid": a Threshold on `type` = 3 (ParaView's SPH filters would otherwise sum the wall
  particles too);
- "slice": an SPH Plane Interpolator through the middle of the domain (the x-z plane, the
  plane of a 2D case), coloured by the Shepard-normalised pressure;
- "line": an SPH Line Interpolator along the vertical through the middle of the domain;
both with the solver's kernel: `SPHWendlandQuinticKernel` (VTK's Wendland quintic is our
Wendland C2 with cutoff factor 2, so Spatial Step = the part file's h; `SPHCubicKernel` for the
cubic spline), Dimension = the part file's `dimension`, Mass Array `mass`, Density Array `rhop`,
and the Shepard sum, by which a Calculator divides (`press_shepard`), as docs/solver.md says.
--png saves a picture of the slice at time T (default: the last), --csv the line's samples
(x, y, z, press_shepard, Shepard sum) at that time. h and the dimension come from the first part
file's attributes (h5py), or from H and DIMENSION below.
"""
import os
import sys

from paraview import simple as pv

# In the GUI (File > Load State): the run to open, and h / dimension when h5py is missing.
PARTS = "out/run/parts.xdmf"
H = None
DIMENSION = None


def part_constants(parts):
    """(h, dimension, kernel, domain box) from the first part file of parts.xdmf's folder."""
    data = os.path.join(os.path.dirname(os.path.abspath(parts)), "data")
    first = sorted(f for f in os.listdir(data) if f.startswith("part_") and f.endswith(".h5"))[0]
    try:
        import h5py
        with h5py.File(os.path.join(data, first), "r") as f:
            return float(f.attrs["h"]), int(f.attrs["dimension"]), str(f.attrs["kernel"])
    except ImportError:
        if H is None or DIMENSION is None:
            raise SystemExit("paraview_sph_state.py: no h5py: set H and DIMENSION at the top of the script")
        return float(H), int(DIMENSION), "Wendland C2"


def build(parts):
    h, dim, kernel = part_constants(parts)
    reader = pv.Xdmf3ReaderS(registrationName="parts.xdmf", FileName=[parts])
    reader.UpdatePipelineInformation()
    fluid = pv.Threshold(registrationName="fluid", Input=reader)
    fluid.Scalars = ["POINTS", "type"]
    fluid.LowerThreshold = 3
    fluid.UpperThreshold = 3
    fluid.UpdatePipeline(reader.TimestepValues[0] if reader.TimestepValues else 0.0)
    (xmin, xmax, ymin, ymax, zmin, zmax) = reader.GetDataInformation().GetBounds()
    centre = [0.5 * (xmin + xmax), 0.5 * (ymin + ymax), 0.5 * (zmin + zmax)]

    def kernel_settings(f):
        f.Kernel = "SPHCubicKernel" if "cubic" in kernel.lower() else "SPHWendlandQuinticKernel"
        f.Kernel.SpatialStep = h  # cutoff factor 2: support 2h, as the solver's
        f.Kernel.Dimension = dim
        f.MassArray = "mass"
        f.DensityArray = "rhop"
        f.ComputeShepardSum = 1

    slice_ = pv.SPHPlaneInterpolator(registrationName="slice_raw", Input=fluid, Source="Bounded Plane")
    kernel_settings(slice_)
    slice_.Source.Center = centre
    pad = 1e-3 * max(xmax - xmin, zmax - zmin)  # a 2D case has no thickness in y
    slice_.Source.BoundingBox = [xmin, xmax, ymin - pad, ymax + pad, zmin, zmax]
    slice_.Source.Normal = [0.0, 1.0, 0.0]
    slice_.Source.Resolution = 200
    slice_n = pv.Calculator(registrationName="slice", Input=slice_)
    slice_n.ResultArrayName = "press_shepard"
    slice_n.Function = 'press/max("Shepard Summation",1e-12)*("Shepard Summation">0.3)'
    line = pv.SPHLineInterpolator(registrationName="line_raw", Input=fluid, Source="Line")
    kernel_settings(line)
    line.Source.Point1 = [centre[0], centre[1], zmin]
    line.Source.Point2 = [centre[0], centre[1], zmax]
    line.Source.Resolution = 100
    line_n = pv.Calculator(registrationName="line", Input=line)
    line_n.ResultArrayName = "press_shepard"
    line_n.Function = 'press/max("Shepard Summation",1e-12)*("Shepard Summation">0.3)'

    view = pv.GetActiveViewOrCreate("RenderView")
    display = pv.Show(slice_n, view)
    pv.ColorBy(display, ("POINTS", "press_shepard"))
    display.RescaleTransferFunctionToDataRange(True, False)
    display.SetScalarBarVisibility(view, True)
    view.CameraPosition = [centre[0], ymin - 3.0 * max(xmax - xmin, zmax - zmin), centre[2]]
    view.CameraFocalPoint = centre
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.ResetCamera()
    return reader, slice_n, line_n, view


def main(argv):
    args = list(argv)
    png = csvfile = None
    time = None
    if "--png" in args:
        k = args.index("--png")
        png = args[k + 1]
        del args[k:k + 2]
    if "--csv" in args:
        k = args.index("--csv")
        csvfile = args[k + 1]
        del args[k:k + 2]
    if "--time" in args:
        k = args.index("--time")
        time = float(args[k + 1])
        del args[k:k + 2]
    parts = args[0] if args else PARTS
    reader, slice_n, line_n, view = build(parts)
    if time is None:
        time = reader.TimestepValues[-1] if reader.TimestepValues else 0.0
    view.ViewTime = time
    if csvfile:
        line_n.UpdatePipeline(time)
        pv.SaveData(csvfile, proxy=line_n, PointDataArrays=["press_shepard", "Shepard Summation"],
                    FieldDelimiter=";")
    if png:
        slice_n.UpdatePipeline(time)
        display = pv.GetDisplayProperties(slice_n, view)
        display.RescaleTransferFunctionToDataRange(False, True)
        view.ResetCamera()
        pv.SaveScreenshot(png, view, ImageResolution=[1200, 600])


if __name__ == "__main__":
    main(sys.argv[1:])
else:  # File > Load State in the GUI
    build(PARTS)
