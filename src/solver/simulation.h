// SeaSpring — MIT licence.
/// \file simulation.h
/// \brief A run: the time loop (steps of the case's scheme, time_steppers.h), outputs at every
///        TimeOut, gauges, progress lines, stop rules, and the run summary (run.json).
#pragma once

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "solver/backend.h"
#include "solver/run_options.h"
#include "solver/solver_case.h"

namespace seaspring::solver {

class GaugeSystem;
struct StepCounters;

/// What run.json reports.
struct RunSummary {
    std::string case_name, backend, device;
    int threads = 1;
    std::uint32_t np = 0, nfixed = 0, nmoving = 0, nsolid = 0, nfluid = 0;
    std::uint32_t fluid_active = 0;
    std::uint32_t excluded_position = 0, excluded_density = 0, excluded_not_finite = 0;
    long long steps = 0;
    long long dtmin_hits = 0;
    unsigned long long divides = 0, sorts = 0;  ///< divides, and those that sorted (skin)
    double physical_time = 0, wall_time = 0, loop_time = 0;
    double ns_per_particle_step = 0;
    double dt_last = 0;
    int outputs = 0;
    long long gauge_rows = 0;  ///< CSV rows written by the gauges
    std::string stop_reason;
    std::string state_hash;
    std::string options;  ///< physics options, one line
    // VCPM solids
    long long solid_substeps = 0;   ///< solid sub-steps done
    int omega_max = 0;              ///< most sub-steps in one fluid step
    double solid_dt = 0;            ///< the solid sub-step limit VcpmDtCoef dp / c_S [s]
    std::uint64_t bonds = 0, clamp_bonds = 0, broken_bonds = 0;  ///< bonds counted once
};

/// Builds the backend's initial data from the case (particles in id order); cells of
/// 2h/cell_div (resolveCellDiv) with a skin of `skin` cells (cell_grid.h).
BackendSetup makeBackendSetup(const SolverCase& c, int cell_div, double skin);
/// The skin a run uses: -skin, else physics::kDefaultSkinFraction.
double resolveSkin(const RunOptions& o);
/// The cell division a run uses: `cell_div` (RunOptions), or for 0 (-cellmode:auto) 4 in 3D
/// (cells of h/2: on an H100, SPHERIC Test 2 at 4.4 M particles runs 13% faster than with cells
/// of h) and 2 in 2D, each the finest whose grid fits 32-bit packed cells and at most
/// 16 cells per particle + 2^20 (else the next coarser; 1 at the coarsest).
int resolveCellDiv(const SolverCase& c, int cell_div);

class Simulation {
public:
    Simulation(const SolverCase& c, const RunOptions& o, std::unique_ptr<Backend> backend,
               std::ostream& log);
    /// Runs to TimeMax (or -nsteps), writing outputs; returns the summary (also run.json).
    RunSummary run();
    /// The state at the end of run() (id order).
    const HostState& finalState() const { return final_; }
    /// Called at every output time (t = 0, each TimeOut, the end) with the state in id order,
    /// whatever -sv says: for in-process post-processing (tests, gauges).
    using OutputObserver = std::function<void(double time, long long step, const HostState& state)>;
    void onOutput(OutputObserver f) { observer_ = std::move(f); }

private:
    void output(double time, long long step);
    /// Per-particle solid fields of the part files (zero for other particles).
    void solidFields(const HostState& st, std::vector<float>& disp, std::vector<float>& strain,
                     std::vector<std::uint8_t>& broken, std::vector<float>& damage) const;
    /// Stops the run (seaspring::Error) when a solid position is not finite.
    void checkSolidFinite(const HostState& st, double time) const;
    /// Broken bonds (each solid-solid bond counted once) in `st`.
    std::uint64_t brokenBonds(const HostState& st) const;
    /// After the loop: the last output when none was written, the final state, run.json's counts.
    void finish(double t, long long steps, double loop_time, const StepCounters& counters);

    const SolverCase& case_;
    RunOptions opt_;
    std::unique_ptr<Backend> backend_;
    std::ostream& log_;
    BackendSetup setup_;
    RunSummary sum_;
    HostState final_;
    int out_index_ = 0;
    struct Output;
    std::shared_ptr<Output> out_;
    struct Ledger;
    std::shared_ptr<Ledger> ledger_;
    std::shared_ptr<GaugeSystem> gauges_;  ///< null when the case has no gauges
    OutputObserver observer_;
};

/// One-line description of the physics options ("symplectic, Wendland, artificial 0.1, ...").
std::string describePhysics(const SolverParameters& p, int dim, int cell_div, double skin);

}  // namespace seaspring::solver
