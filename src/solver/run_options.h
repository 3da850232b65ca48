// SeaSpring — MIT licence.
/// \file run_options.h
/// \brief The solver's command line, DualSPHysics style:
///        seaspring [-gpu[:ID]|-cpu] [-threads:N] [-tmax:T] [-tout:T] [-sv:h5,vtk] OUTDIR/NAME OUTDIR
///        plus physics overrides (-symplectic, -verlet, -wendland, -cubic, -viscoart:A, ...).
#pragma once

#include <optional>
#include <string>

#include "solver/solver_case.h"

namespace seaspring::solver {

struct RunOptions {
    enum class Backend { Auto, Gpu, Cpu };
    Backend backend = Backend::Auto;
    int gpu_id = 0;
    int threads = 0;  ///< 0 = all cores
    std::string case_path, outdir;
    bool save_h5 = true, save_vtk = false;
    std::optional<double> tmax, tout, visco, visco_bound_factor, ddt_value, cfl, dt_fixed;
    std::optional<int> step_algorithm, verlet_steps, kernel, visco_treatment, ddt;
    std::optional<long long> nsteps;
    int cell_div = 2;  ///< 1: cells of 2h (-cellmode:full), 2: cells of h (-cellmode:h)
    double progress_interval = 1.0;
    bool quiet = false, help = false, version = false;
};

/// Parses argv; throws seaspring::Error with a one-line message naming the bad argument.
RunOptions parseRunOptions(int argc, const char* const* argv);
/// The --help text.
std::string runOptionsHelp();
/// Command-line values win over the case's parameters.
void applyOverrides(const RunOptions& o, SolverParameters& p);

}  // namespace seaspring::solver
