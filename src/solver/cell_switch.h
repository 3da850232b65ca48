// SeaSpring — MIT licence.
/// \file cell_switch.h
/// \brief When a 3D run's cells switch from one particle spacing to h (BackendSetup::cell_switch;
///        the engine's switchCellsIfDue does it).
///
/// Cells of one spacing, centred on the fluid's lattice (solver/grid_origin.h), hold one particle
/// each while the fluid keeps its lattice: the threads of a warp then find their neighbours at
/// the same candidate steps, and this grid tests the fewest candidates. Once a violent flow has
/// broken the fluid up, the threads' neighbour counts in each row of cells differ, and the pair
/// launch runs on about half its lanes; cells of h (rows 1.5 to 1.7 spacings wide, five a side
/// instead of seven) hold more of a thread's neighbours per row, so the counts differ less, and
/// particles sort less often. NVIDIA H200, the 3D sluice gate at dp 3 mm (748,455 particles,
/// h = 1.5 dp), cells of h against the first cells per step, windows of 0.01 s from restart
/// files: 1.11-1.15 at t = 0.02 s, 1.05-1.10 at 0.05-0.1 s, 1.02-1.05 at 0.15-0.2 s, 0.97-1.00
/// at 0.3 s, 0.93-0.97 from 0.45 s on (docs/performance-large.md, thirty-first session).
///
/// The rule reads only the state: after a sort of the fluid block in the first cells, the
/// active fluid particles that share their cell with another are counted
/// (physics::sharesItsCell; none on the lattice), and above `fraction` of the active fluid the
/// cells switch, once. In the sluice that share grows steadily with the flow's violence (0.03 at
/// t = 0.05 s, 0.12 at 0.1, 0.22 at 0.2, 0.30 at 0.3, 0.38 at 0.45, 0.43 at 0.9), through 0.3
/// where the two cells cost the same: the default. (The share of particles more than a quarter
/// cell from their cells' centres, tried first, reaches 0.75 by t = 0.1 s and says nothing
/// after.) An integer count of identical cell ranges: every backend and thread count switches
/// at the same divide, so runs keep one state hash.
#pragma once

#include "solver/solver_case.h"

namespace seaspring::solver {

/// The default share of the active fluid that shares its cell with another fluid particle, above
/// which the cells switch (-cellswitch).
constexpr double kCellSwitchFraction = 0.3;

/// The fraction the switch of case `c` takes (> 0), or 0 where it does not apply: `fraction`
/// (-cellswitch; 0 turns it off), for a 3D case whose cell mode is the automatic one
/// (`cell_div` 0) and resolves to cells one particle spacing wide (2h/3 with h = 1.5 dp, or
/// physics::kCellDivSpacing) centred on the fluid's lattice, with a grid of cells of h that fits.
double resolveCellSwitch(const SolverCase& c, int cell_div, double fraction);

}  // namespace seaspring::solver
