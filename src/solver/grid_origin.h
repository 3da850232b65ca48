// SeaSpring — MIT licence.
/// \file grid_origin.h
/// \brief Where the cell grid of the neighbour search starts: at the simulation domain's minimum,
///        or up to one cell below it so that the planes of the fluid's initial particle lattice
///        lie half a spacing from the cell faces.
///
/// Why: gencase puts particles on a lattice of spacing dp, and DualSPHysics' default domain
/// starts at the lowest particle, so with cells of a whole number of spacings (h/2 for h = 2 dp,
/// SPHERIC Test 2's choice) every lattice plane lies exactly on a cell face, and which cell a
/// particle lands in depends on the last bit of its coordinate: cells hold 0, 1, 2, 4 or 8
/// particles instead of one each. The threads of a warp (consecutive particles) then find their
/// neighbours at different candidate steps and idle while the others evaluate a pair. With the
/// planes between the faces every cell holds the same number of particles, away from its faces,
/// for as long as the fluid keeps its lattice (docs/performance-large.md, seventeenth session).
/// Results change only by the rounding of the cell-relative positions (PosCell).
#pragma once

#include "solver/solver_case.h"

namespace seaspring::solver {

struct GridOrigin {
    double min[3] = {0, 0, 0};             ///< the grid's first corner [m], at or below the domain's
    bool centred[3] = {false, false, false};  ///< axes moved to centre the fluid lattice
    bool any() const { return centred[0] || centred[1] || centred[2]; }
};

/// How far, in lattice spacings, the lattice planes may drift against the cell faces over the
/// domain for the cells to count as a whole number of spacings (latticeCentredGridOrigin): the
/// planes then stay at least 0.4 spacings from the faces.
constexpr double kMaxLatticeDrift = 0.1;

/// The grid origin of case `c` for cells of `cellsize`. Per axis (2D: x and z): when the cell
/// size is a whole number m of spacings (the planes drifting by at most kMaxLatticeDrift
/// spacings against the faces over the domain's extent on that axis) and at least 90% of the fluid
/// particles lie within 1e-3 dp of the planes x0 + k dp (x0: the first fluid particle's
/// coordinate), the largest x0 + dp/2 + n cellsize not above the domain's minimum; otherwise the
/// domain's minimum. Computed from the case's particles (a restart reads the same case, so the
/// same grid), in double arithmetic without library functions beyond floor and nearbyint, so
/// every backend and machine gets the same origin.
GridOrigin latticeCentredGridOrigin(const SolverCase& c, double cellsize);

}  // namespace seaspring::solver
