// SeaSpring — MIT licence.
/// \file run_options.h
/// \brief The solver's command line, DualSPHysics style:
///        `seaspring [-gpu[:ID]|-cpu] [-threads:N] [-tmax:T] [-tout:T] [-sv:h5,vtk] OUTDIR/NAME
///        OUTDIR` plus physics overrides (-symplectic, -verlet[:N], -wendland, -cubic, -viscoart:A,
///        ...).
///
/// Options are written `-name` or `-name:value` (DualSPHysics) or `--name`, `--name=value`;
/// runOptionsHelp() lists them all. Values must parse completely and lie in range; an option
/// given twice, two options that contradict each other (-gpu and -cpu, -symplectic and
/// -verlet, -wendland and -cubic, two viscosity choices), an unknown option or a wrong number
/// of positional arguments is a usage error.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "solver/cell_switch.h"
#include "solver/solver_case.h"

namespace seaspring::solver {

/// The cell modes by cell_div (RunOptions::cell_div): 0 auto, 1 full, 2 h, 3 third, 4 quarter,
/// 5 dp (physics::kCellDivSpacing). cellModeName: the -cellmode name; cellSizeLabel: the cell
/// size as the physics line writes it ("cells of h/2"; "?" for auto). Both nullptr outside 0..5.
constexpr int kCellModes = 6;
const char* cellModeName(int cell_div);
const char* cellSizeLabel(int cell_div);

/// The most OpenMP threads -threads accepts (libgomp fails far above the core counts of any
/// machine).
constexpr int kMaxThreads = 1024;

struct RunOptions {
    enum class Backend { Auto, Gpu, Cpu };
    Backend backend = Backend::Auto;  ///< Auto: the GPU when one is usable, else the CPU
    int gpu_id = 0;
    int threads = 0;  ///< OpenMP threads; 0 = all cores; at most kMaxThreads
    std::string case_path, outdir;
    bool save_h5 = true, save_vtk = false;
    std::optional<double> tmax, tout, visco, visco_bound_factor, ddt_value, cfl, dt_fixed;
    std::optional<int> step_algorithm, verlet_steps, kernel, visco_treatment, ddt;
    std::optional<long long> nsteps;  ///< stop after this many steps
    /// Cells of 2h/cell_div: 1 -cellmode:full, 2 h, 3 third, 4 quarter; 5 (physics::kCellDivSpacing)
    /// dp, cells of one particle spacing; 0 auto (resolveCellDiv).
    int cell_div = 0;
    /// -skin:F: the neighbour cells' skin, a fraction 0 <= F <= 0.5 of the cell size (0: sort
    /// at every divide); unset: by the case's size (resolveSkin, solver/simulation.h).
    std::optional<double> skin;
    /// -cellswitch:F: a 3D run in cells of one spacing centred on its lattice switches to cells of
    /// h once more than F of its fluid shares its cells (solver/cell_switch.h); 0: never.
    double cell_switch = kCellSwitchFraction;
    /// -pairlanes:N: pair lanes of the fluid loop, a power of two 1..physics::kMaxPairLanes
    /// (physics/fluid_interaction.h); 0 (auto): resolvePairLanes.
    int pair_lanes = 0;
    int solid_substeps = 0;  ///< -vcpmsubsteps:N: solid sub-steps per fluid step forced to N (0: automatic)
    std::optional<int> vcpm_coupling;  ///< -vcpmcoupling:1|2
    std::optional<double> vcpm_dt_coef;  ///< -vcpmdtcoef:F (VcpmDtCoef), 0 < F <= 2
    /// -blowupcheck:N: scan the whole state for a blow-up every N steps (0: only at outputs);
    /// blowup_check.h.
    long long blowup_check_every = 100;
    /// -blowupkeep:K: download the state and keep it as the last good one at every K-th periodic
    /// scan (the others count non-finite particles on the backend); 0 (auto): resolveKeepEvery.
    long long blowup_keep_every = 0;
    bool overwrite = false;  ///< -overwrite: clear an earlier run's files from OUTDIR (output_dir.h)
    /// -checkpoint:T: write OUTDIR/restart.h5 every T > 0 of simulated time (checkpoint.h);
    /// a stop signal or a TERMINATE file in OUTDIR writes one too. 0: only those.
    double checkpoint_interval = 0;
    /// -restart:FILE (alias -partbegin:FILE): continue the run saved in a restart file.
    std::string restart_file;
    double progress_interval = 1.0;  ///< [s] of wall time between progress lines; 0 = none
    bool quiet = false;
    /// Notes on DualSPHysics options taken as aliases (-sv:binx, -dirdataout, -svpips): what
    /// SeaSpring does instead; the solver prints them with the banner.
    std::vector<std::string> notes;
    bool help = false, version = false;  ///< set alone: the rest is not parsed
};

/// Parses argv (argv[0] is the program). -h/-help/--help or -version/--version anywhere
/// return at once with `help` or `version` set. Throws seaspring::Error with a one-line
/// message naming the offending argument.
RunOptions parseRunOptions(int argc, const char* const* argv);

/// The full --help text: usage, every option with its meaning, outputs and exit codes.
std::string runOptionsHelp();

/// Writes the command-line overrides into the case's parameters (the command line wins):
/// step algorithm, Verlet steps, kernel, viscosity treatment and value, boundary factor,
/// density diffusion and its value, CFL number, fixed dt, TimeMax and TimeOut.
void applyOverrides(const RunOptions& o, SolverParameters& p);

}  // namespace seaspring::solver
