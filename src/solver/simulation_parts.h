// SeaSpring — MIT licence.
/// \file simulation_parts.h
/// \brief The parts of a Simulation that its source files share (simulation.cpp, the loop in
///        simulation_run.cpp, restart files in simulation_checkpoint.cpp): the output series,
///        the ledger file and the blow-up check's state.
#pragma once

#include <string>

#include "io/part_writer.h"
#include "io/xdmf_series.h"
#include "solver/blowup_check.h"
#include "solver/coupling_ledger.h"
#include "solver/simulation.h"

namespace seaspring::solver {

struct Simulation::Output {
    io::XdmfSeries xdmf;
    io::PartWriter parts;  ///< the part files, written behind the run on the GPU (part_writer.h)
    Output(const std::string& dir, bool background) : xdmf(dir), parts(dir, background) {}
};

struct Simulation::Ledger {
    LedgerFile file;
    Ledger(const std::string& dir, long long resume_offset, bool contact) : file(dir, resume_offset, contact) {}
};

struct Simulation::Health {
    BlowupCheck check;
    HostState last_good;      ///< the last state a scan passed
    /// What scans and outputs download into: a good state is swapped with last_good, so the
    /// next download reuses the older one's memory (no copy, no allocation).
    HostState scan;
    std::vector<physics::Double3> solid_pos;  ///< a quick scan's solid positions (solid order)
    double good_time = -1;    ///< its time (-1: none yet)
    long long good_step = 0;
    double written_time = -1; ///< time of the last output written
    std::string written_file; ///< its part file (relative to OUTDIR; "" without -sv:h5)
    double dt = 0;            ///< the last step's dt (for the diagnosis)
    Health(const SolverCase& c, const BackendSetup& s, const RunOptions& o) : check(c, s, o) {}
};

}  // namespace seaspring::solver
