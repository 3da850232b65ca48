// SeaSpring — MIT licence.
/// \file boundary_normals.h
/// \brief mDBC boundary normals: the `<normals>` section and the ghost vector of every
///        boundary particle, computed from a shape set (shape_set.h).
///
/// The ghost vector of a boundary particle p is the vector from p to its ghost node, the
/// mirror image of p across the boundary interface: 2 (q - p), q the nearest interface
/// point. The interface is the faces of one shape set; a face counts only when p lies
/// strictly behind it, on the side opposite its (fluid-side) normal n: (q0 - p) . n > 0 for
/// any point q0 of the face's plane (a tolerance of 1e-9 dp treats points on the plane as
/// not behind it). q is the nearest point of such a face (the projection when it falls
/// inside the face, else the nearest point of its edges), the nearest over all faces, and
/// must lie within distanceh * h of p; otherwise the ghost vector is zero. On equal
/// distances the face recorded first wins.
///
/// 2D cases (pointmin.y == pointmax.y) work in the x-z plane: faces whose normal is along
/// y (front, back) are not part of the interface, the others are segments, and the ghost
/// vector's y component is 0.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

#include <pugixml.hpp>

#include "case/xml_source.h"
#include "core/particle_set.h"
#include "gencase/expression.h"
#include "gencase/shape_set.h"

namespace seaspring::gencase {

using model::XmlSource;

/// `<normals>` as read: active, `<distanceh value>` (default 2) and the shape set that
/// `<geometryfile file>` names.
struct NormalsRequest {
    bool active = false;
    double distanceh = 2.0;
    const ShapeSet* shapes = nullptr;  ///< points into the shape sets passed to readNormals
};

/// Reads `<normals>` (null node: inactive). When active: only `<distanceh>` and
/// `<geometryfile>` are supported (any other child is an error naming it); the geometry file
/// must be a shape set of this case, written "[CaseName]_X_Actual.vtk" (or with the case's
/// name for [CaseName]), whose set X must exist and hold faces. An external VTK file is not
/// supported yet. Errors name the file and line.
NormalsRequest readNormals(const XmlSource& src, pugi::xml_node normals, const ExpressionEvaluator& ev,
                           const std::vector<ShapeSet>& sets, const std::string& case_name);

struct GhostVectorStats {
    std::size_t with_normal = 0;     ///< boundary particles with a non-zero ghost vector
    std::size_t without_normal = 0;  ///< boundary particles without one
    double max_length = 0;           ///< largest |ghost vector| [m]
};

/// Ghost vectors (float, [m]) of the first `nbound` particles of `pos` (the non-fluid
/// particles), from `faces` within `reach` = distanceh * h. `dp` scales the on-plane
/// tolerance. OpenMP over particles; each particle's result is computed alone, so it does
/// not depend on the thread count. Throws seaspring::Error (naming `file` and the face's
/// line) for a face that is neither in nor across the x-z plane of a 2D case.
std::vector<Vec3f> computeGhostVectors(const std::vector<Vec3d>& pos, std::size_t nbound,
                                       const std::vector<ShapeFace>& faces, double reach, double dp,
                                       bool two_d, const std::string& file, GhostVectorStats* stats);

/// The one-line summary gencase prints ("Normals: ...").
void printNormalsSummary(std::ostream& log, const std::string& set_name, const GhostVectorStats& s,
                         double dp);

}  // namespace seaspring::gencase
