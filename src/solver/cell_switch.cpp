// SeaSpring — MIT licence.
/// \file cell_switch.cpp
/// \brief resolveCellSwitch (cell_switch.h).
#include "solver/cell_switch.h"

#include <cmath>

#include "physics/cell_grid.h"
#include "solver/grid_origin.h"
#include "solver/simulation.h"

namespace seaspring::solver {

double resolveCellSwitch(const SolverCase& c, int cell_div, double fraction) {
    if (!(fraction > 0.0) || cell_div != 0 || c.constants.dimensions != 3 || c.nfluid == 0) return 0.0;
    const int mode = resolveCellDiv(c, 0);
    const double h = c.constants.h, dp = c.constants.dp;
    if (mode != 3 && mode != physics::kCellDivSpacing) return 0.0;
    const double cellsize = physics::cellSizeOfMode(h, dp, mode);
    if (std::fabs(cellsize - dp) > 1e-3 * dp) return 0.0;  // cells of one spacing only
    if (!latticeCentredGridOrigin(c, cellsize).any()) return 0.0;
    physics::CellGrid g;
    if (!physics::makeCellGrid(c.domain_min.x, c.domain_min.y, c.domain_min.z, c.domain_max.x, c.domain_max.y,
                               c.domain_max.z, h, 2, g, 0.0, dp))
        return 0.0;
    return fraction;
}

}  // namespace seaspring::solver
