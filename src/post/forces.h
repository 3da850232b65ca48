// SeaSpring — MIT licence.
/// \file forces.h
/// \brief `seaspring-post forces`: the fluid's force on boundary or solid MKs from the saved
///        part files (DualSPHysics' ComputeForces), with the in-run force gauge's function.
///
/// The case (`-filexml`, the resolved NAME.xml that gencase wrote and the run read) gives what
/// the part files do not carry: the viscosity (treatment, value, boundary factor), the speed of
/// sound, the particle masses, the simulation domain and the MK blocks. From it
/// solver::makeBackendSetup builds the run's own constants and cell grid (cells of 2h/celldiv,
/// no skin). For each part file the boundary particles (fixed, moving, solid) and the active
/// fluid are sorted by (cell, id) as the solver's divide sorts them (sorted_block.h), the
/// pressure of every particle comes from physics::pressureAt, and the force on each selected
/// boundary particle from physics::hydroForceOnBoundary, the function of the in-run force gauge
/// and of the VCPM coupling (F = -sum_j m_j a_j<-i); the selection's total is summed in id order,
/// as the gauge sums it. With the run's cell size and -skin:0 the values are the gauge's bit for
/// bit (tests/solver/test_post_forces.cpp).
/// Not supported (stops with a message): mDBC cases (the boundary takes its ghost node's
/// density for the force: the part files do not hold the ghost vectors' state), and
/// laminar+SPS viscosity (the SPS stress is not saved; -viscolam:V computes without it).
#pragma once

#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "io/part_output.h"
#include "physics/sph_types.h"

namespace seaspring::post {

struct ForcesOptions {
    std::string dirin;     ///< the run's OUTDIR (holds data/part_NNNN.h5)
    std::string filexml;   ///< the resolved case (OUTDIR/NAME.xml of gencase, or NAME)
    int first = -1, last = -1;
    std::vector<int> onlymk;   ///< absolute MKs (DualSPHysics' -onlymk: mkbound + mkboundfirst)
    std::vector<int> mkbound;  ///< or local mkbound numbers (as the gauges' <target mkbound>)
    int cell_div = 0;          ///< the run's -cellmode: 0 auto (solver::resolveCellDiv), 1..4, 5 dp
    int visco_treatment = 0;   ///< 0: the case's; 1 artificial, 3 laminar (-viscoart / -viscolam)
    double visco = -1;         ///< with visco_treatment
    double visco_bound_factor = -1;  ///< < 0: the case's
    std::string savecsv;
};

/// The run's constants and the selection, ready for forcesOfPart (opaque: forces.cpp).
struct ForceModel;
struct ForceModelDeleter {
    void operator()(ForceModel* m) const;
};

/// Loads the case and builds the model; throws seaspring::Error naming the case file, or the
/// option, for an unknown MK, an mDBC or SPS case, a bad override.
std::unique_ptr<ForceModel, ForceModelDeleter> makeForceModel(const ForcesOptions& o, std::ostream& log);

/// The total force [N] on the selection in one part file (checked against the case: particle
/// count, h, dp, kernel, rhop0, dimension, Tait B; errors name `what`).
physics::Double3 forcesOfPart(const ForceModel& m, const io::PartData& d, const std::string& what);

/// Runs the forces subcommand: writes `savecsv` (';'-separated, one header line
/// `part;time;forcex;forcey;forcez`, one row per part file; [s], [N]). Returns the rows written.
int runForces(const ForcesOptions& o, std::ostream& log);

}  // namespace seaspring::post
