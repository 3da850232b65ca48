// SeaSpring — MIT licence.
/// \file grid_origin.cpp
/// \brief latticeCentredGridOrigin (grid_origin.h).
#include "solver/grid_origin.h"

#include <cmath>
#include <cstddef>

namespace seaspring::solver {

namespace {

double coord(const Vec3d& p, int axis) { return axis == 0 ? p.x : (axis == 1 ? p.y : p.z); }

}  // namespace

GridOrigin latticeCentredGridOrigin(const SolverCase& c, double cellsize) {
    GridOrigin o;
    const double lo[3] = {c.domain_min.x, c.domain_min.y, c.domain_min.z};
    for (int a = 0; a < 3; ++a) o.min[a] = lo[a];
    const double dp = c.constants.dp;
    const std::size_t first = std::size_t(c.nfixed) + c.nmoving + c.nsolid;
    const std::size_t np = c.particles.pos.size();
    if (!(dp > 0.0) || c.nfluid == 0 || first >= np) return o;
    const double spacings = cellsize / dp;  // lattice spacings per cell
    const double m = std::nearbyint(spacings);
    if (m < 1.0) return o;
    const double hi[3] = {c.domain_max.x, c.domain_max.y, c.domain_max.z};
    for (int a = 0; a < 3; ++a) {
        if (a == 1 && c.constants.dimensions == 2) continue;
        // The planes drift against the faces by |m - spacings| dp per cell: at most kMaxLatticeDrift spacings
        // over the domain (a coefh written to six digits, e.g. 0.866025 for h = 1.5 dp).
        if (std::fabs(spacings - m) * (hi[a] - lo[a] + cellsize) / cellsize > kMaxLatticeDrift) continue;
        const double x0 = coord(c.particles.pos[first], a);
        std::size_t on = 0;
        for (std::size_t i = first; i < np; ++i) {
            const double f = (coord(c.particles.pos[i], a) - x0) / dp;
            if (std::fabs(f - std::nearbyint(f)) <= 1e-3) ++on;
        }
        if (double(on) < 0.9 * double(np - first)) continue;
        const double face = x0 + 0.5 * dp;  // a cell face half a spacing from the lattice
        double g = face + std::floor((lo[a] - face) / cellsize) * cellsize;
        if (g > lo[a]) g -= cellsize;
        o.min[a] = g;
        o.centred[a] = true;
    }
    return o;
}

}  // namespace seaspring::solver
