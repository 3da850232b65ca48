// SeaSpring — MIT licence.
/// \file flow.h
/// \brief `seaspring-post flow`: the fluid mass and volume that cross a plane section between
///        consecutive part files (DualSPHysics' FlowTool counts particles in this way).
///
/// A fluid particle (active in both parts, matched by id) that moved from p0 (earlier part) to
/// p1 (later part) crosses the section when physics::sectionCrossing says so: +1 along the
/// normal, -1 against it, judged on the straight line p0 -> p1, the crossing point inside the
/// `-limits` box. Its mass m (the part file's /mass) and volume m/rho (rho of the later part)
/// count with that sign. Particles that cross twice between two parts (there and back) count
/// zero: save parts often enough that a particle moves less than about dp between them. In 2D
/// the masses and volumes are per metre of width (kg/m, m^2).
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "io/part_output.h"
#include "physics/gauges.h"

namespace seaspring::post {

/// What crossed the section between two parts.
struct FlowCount {
    long long npos = 0, nneg = 0;  ///< particles that crossed along / against the normal
    double mass = 0;               ///< net mass along the normal [kg] (2D: kg/m)
    double volume = 0;             ///< net volume along the normal [m^3] (2D: m^2)
};

/// The section of `-plane x,y,z,nx,ny,nz` (the normal is normalised) and `-limits
/// xmin,ymin,zmin,xmax,ymax,zmax` (empty: the whole plane). Throws seaspring::Error naming the
/// option for a wrong count, a zero normal or an empty box.
physics::PlaneSection makeSection(const std::vector<double>& plane, const std::vector<double>& limits);

/// What crossed between parts `a` and `b` (b later; the same particles, in id order). Throws
/// (naming `what`) when their particle counts differ or b has no /mass.
FlowCount flowBetween(const physics::PlaneSection& s, const io::PartData& a, const io::PartData& b,
                      const std::string& what);

struct FlowOptions {
    std::string dirin;
    int first = -1, last = -1;
    std::vector<double> plane, limits;
    std::string savecsv;
};

/// Runs the flow subcommand: `savecsv` (';'-separated, one header line
/// `part;time;npos;nneg;mass;volume;massflow;volumeflow;masstotal;volumetotal`, one row per part
/// file after the first: what crossed since the previous part, its rate (divided by the time
/// between the two parts) and the running totals since the first part). Returns the rows.
int runFlow(const FlowOptions& o, std::ostream& log);

}  // namespace seaspring::post
