// SeaSpring — MIT licence.
/// \file shape_set.h
/// \brief GenCase shapes: the faces drawing commands record while
///        `<setactive drawshapes="1"/>` is set, grouped into named sets by `<shapeout>`.
///
/// A shape set is the boundary interface that `<normals>` uses to compute the mDBC ghost
/// vectors (boundary_normals.h). GenCase writes each set as "[CaseName]_X_Actual.vtk";
/// SeaSpring keeps the sets in memory and writes the same files next to its outputs.
///
/// Only `<drawbox>` records faces. A box face is a rectangle placed by the transform of the
/// moment (`move`, `rotate`); its normal points outward of the box, or inward after
/// `<setnormalinvert invert="true"/>`. That normal is the fluid side of the interface: a
/// tank drawn with invert="true" has normals pointing into the fluid, an obstacle drawn with
/// invert="false" normals pointing out of the obstacle.
#pragma once

#include <string>
#include <vector>

#include "core/vec3.h"
#include "gencase/shapes.h"

namespace seaspring::gencase {

/// One rectangular face: the points origin + s*u + t*v for s, t in [0, 1] (u and v
/// orthogonal; one of them may be zero for a degenerate face). `normal` is a unit vector on
/// the fluid side; u, v are ordered so that cross(u, v) points along `normal`.
struct ShapeFace {
    Vec3d origin{0, 0, 0};
    Vec3d u{0, 0, 0};
    Vec3d v{0, 0, 0};
    Vec3d normal{0, 0, 0};
    int line = 0;  ///< line of the drawing command in the case definition
};

/// The faces named by one `<shapeout file="name"/>`.
struct ShapeSet {
    std::string name;
    int line = 0;  ///< line of the <shapeout>
    std::vector<ShapeFace> faces;
};

/// Faces of the box [lo, hi] (in the shape's own coordinates) selected by `faces` (a
/// BoxFaces mask; BoxSolid means all six), placed by `m`. Outward normals, negated when
/// `invert`. Faces of zero area are kept (2D cases use their extent in the x-z plane).
std::vector<ShapeFace> boxShapeFaces(const Affine& m, Vec3d lo, Vec3d hi, unsigned faces, bool invert,
                                     int line);

/// GenCase's file name of a shape set: "CASE_X_Actual.vtk" ("CASE_Actual.vtk" for X = "").
std::string shapeFileName(const std::string& case_name, const std::string& set_name);

/// Writes a shape set as legacy VTK polydata (one quad per face, normals as cell data) for
/// ParaView. Throws seaspring::Error naming `path` when it cannot be written.
void writeShapeVtk(const std::string& path, const ShapeSet& set);

}  // namespace seaspring::gencase
