#!/usr/bin/env pvpython
"""Contours seaspring-post's grids (VTK ImageData, .vti) into surfaces (VTK polydata, .vtp) with
VTK's marching-cubes family under ParaView's pvpython: vtkFlyingEdges3D on a 3D grid (triangles,
with normals), vtkContourFilter on a 2D grid (one layer of nodes: the contour lines of the
free surface).

`seaspring-post isosurface` runs it for you; alone:

    pvpython tools/isosurface.py --array mass --level 3.07e-4 GRID.vti SURFACE.vtp
    pvpython tools/isosurface.py --array mass --jobs PREFIX_isosurface.txt

--jobs names a file with one line per grid: "LEVEL<TAB>GRID.vti<TAB>SURFACE.vtp" (what
seaspring-post writes as PREFIX_isosurface.txt). Every point array of the grid (mass, wsum) is
interpolated onto the surface. Each surface is written under a temporary name and renamed.
Exit code 0, or 2 with a message naming the file on bad input.
"""
import argparse
import os
import sys

from vtkmodules.vtkFiltersCore import vtkContourFilter, vtkFlyingEdges3D
from vtkmodules.vtkIOXML import vtkXMLImageDataReader, vtkXMLPolyDataWriter


def contour(grid_path, surface_path, array, level):
    """Writes the surface of `array` = `level` in GRID to SURFACE; returns (points, cells)."""
    if not os.path.isfile(grid_path):
        raise ValueError(f"{grid_path}: no such file")
    reader = vtkXMLImageDataReader()
    reader.SetFileName(grid_path)
    reader.Update()
    image = reader.GetOutput()
    dims = image.GetDimensions()
    if image.GetNumberOfPoints() == 0:
        raise ValueError(f"{grid_path}: not a VTK ImageData file with points")
    if image.GetPointData().GetArray(array) is None:
        names = [image.GetPointData().GetArrayName(k) for k in range(image.GetPointData().GetNumberOfArrays())]
        raise ValueError(f"{grid_path}: no point array '{array}' (it has {', '.join(names)})")
    flat = sum(1 for d in dims if d > 1) < 3
    f = vtkContourFilter() if flat else vtkFlyingEdges3D()
    f.SetInputConnection(reader.GetOutputPort())
    f.SetInputArrayToProcess(0, 0, 0, 0, array)  # 0: point data
    f.SetValue(0, level)
    if not flat:
        f.ComputeNormalsOn()
        f.InterpolateAttributesOn()
    else:
        f.ComputeScalarsOn()
    f.Update()
    out = f.GetOutput()
    tmp = surface_path + ".tmp"
    w = vtkXMLPolyDataWriter()
    w.SetFileName(tmp)
    w.SetInputData(out)
    w.SetDataModeToAppended()
    w.EncodeAppendedDataOff()
    if w.Write() != 1:
        raise ValueError(f"{surface_path}: cannot write the surface")
    os.replace(tmp, surface_path)
    return out.GetNumberOfPoints(), out.GetNumberOfCells()


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--array", default="mass", help="the grid's point array to contour (mass or wsum)")
    p.add_argument("--level", type=float, help="contour value (with GRID SURFACE)")
    p.add_argument("--jobs", help="file of LEVEL<TAB>GRID<TAB>SURFACE lines")
    p.add_argument("files", nargs="*", help="GRID.vti SURFACE.vtp")
    a = p.parse_args(argv)
    jobs = []
    if a.jobs:
        try:
            with open(a.jobs, encoding="utf-8") as f:
                for n, line in enumerate(f, 1):
                    w = line.rstrip("\n").split("\t")
                    if len(w) != 3:
                        raise ValueError(f"{a.jobs}:{n}: expected LEVEL<TAB>GRID<TAB>SURFACE, found '{line.strip()}'")
                    try:
                        level = float(w[0])
                    except ValueError:
                        raise ValueError(f"{a.jobs}:{n}: level '{w[0]}' is not a number") from None
                    jobs.append((level, w[1], w[2]))
        except OSError as e:
            raise ValueError(f"{a.jobs}: cannot read ({e.strerror})") from None
    if a.files:
        if len(a.files) != 2 or a.level is None:
            raise ValueError("give --level LEVEL GRID.vti SURFACE.vtp, or --jobs FILE")
        jobs.append((a.level, a.files[0], a.files[1]))
    if not jobs:
        raise ValueError("nothing to do: give --jobs FILE or --level LEVEL GRID.vti SURFACE.vtp")
    for level, grid, surface in jobs:
        npts, ncells = contour(grid, surface, a.array, level)
        print(f"isosurface: {surface}: {npts} points, {ncells} cells ({a.array} = {level:g})"
              + ("  (empty: no fluid crosses the level)" if ncells == 0 else ""))
        sys.stdout.flush()
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1:]))
    except ValueError as e:
        print(f"isosurface.py error: {e}", file=sys.stderr)
        sys.exit(2)
