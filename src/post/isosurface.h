// SeaSpring — MIT licence.
/// \file isosurface.h
/// \brief `seaspring-post isosurface`: the free surface of each part file as VTK polydata
///        (DualSPHysics' IsoSurface).
///
/// Two steps. (1) Here: the kernel sums of the in-run gauges (physics::gaugeSampleAt, through
/// measurePart) at the nodes of a regular grid over the fluid: `mass` = sum_j V_j W_j m_j (the
/// SWL gauge's mass: about the particle mass inside the fluid, falling to 0 across the surface)
/// and `wsum` = sum_j V_j W_j (about 1 inside); written as VTK ImageData PREFIX_NNNN.vti
/// (io/vti_writer.h). (2) ParaView's pvpython runs tools/isosurface.py, which contours the
/// chosen array at the level with VTK's vtkFlyingEdges3D (vtkContourFilter on a 2D grid: lines)
/// and writes PREFIX_NNNN.vtp (vtkXMLPolyDataWriter). The default level is the SWL gauge's
/// mass limit (0.5 m_fluid in 3D, 0.4 m_fluid in 2D; physics::swlMassLimitCoef), or 0.5 for
/// wsum. Without pvpython the subcommand stops before computing anything, unless -gridonly.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "io/part_output.h"
#include "io/vti_writer.h"

namespace seaspring::post {

struct IsosurfaceOptions {
    std::string dirin;
    int first = -1, last = -1;
    std::string var = "mass";  ///< "mass" or "wsum": the array contoured
    double level = -1;         ///< < 0: the default above
    double distnode = 0;       ///< node spacing [m]; 0: distnode_dp * dp
    double distnode_dp = 1;
    std::vector<double> limits;  ///< xmin,ymin,zmin,xmax,ymax,zmax (default: the fluid's box grown by 2h + a node)
    std::string savevtk;         ///< output prefix: PREFIX_NNNN.vti and PREFIX_NNNN.vtp
    bool gridonly = false;       ///< write the .vti files only (no pvpython needed)
    std::string pvpython;        ///< default: $SEASPRING_PVPYTHON, else pvpython on the PATH
    std::string script;          ///< default: $SEASPRING_TOOLS/isosurface.py, else the sources' tools/
};

/// The grid and its arrays (mass, wsum) for one part file. Throws (naming `what`) as
/// measurePart, and for a grid of more than 2^28 nodes.
struct IsoGrid {
    io::ImageGrid grid;
    std::vector<io::VtiArray> arrays;  ///< "mass" [kg], "wsum"
    double massfluid = 0;              ///< 0 when the part has no active fluid
    int dim = 3;
};
IsoGrid isosurfaceGrid(const io::PartData& d, const IsosurfaceOptions& o, const std::string& what);

/// The level contoured for `o` on a part with fluid particle mass `massfluid`.
double isosurfaceLevel(const IsosurfaceOptions& o, double massfluid, int dim);

/// pvpython's path (o.pvpython, $SEASPRING_PVPYTHON, the PATH), or "" when none is found.
std::string findPvpython(const IsosurfaceOptions& o);

/// Runs the isosurface subcommand; returns the part files done.
int runIsosurface(const IsosurfaceOptions& o, std::ostream& log);

}  // namespace seaspring::post
