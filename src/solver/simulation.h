// SeaSpring — MIT licence.
/// \file simulation.h
/// \brief The time loop: symplectic or Verlet steps with the variable dt, moving boundaries,
///        outputs at every TimeOut, progress lines, and the run summary (run.json).
#pragma once

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <memory>
#include <string>

#include "solver/backend.h"
#include "solver/run_options.h"
#include "solver/solver_case.h"

namespace seaspring::solver {

/// What run.json reports.
struct RunSummary {
    std::string case_name, backend, device;
    int threads = 1;
    std::uint32_t np = 0, nfixed = 0, nmoving = 0, nsolid = 0, nfluid = 0;
    std::uint32_t fluid_active = 0;
    std::uint32_t excluded_position = 0, excluded_density = 0, excluded_not_finite = 0;
    long long steps = 0;
    long long dtmin_hits = 0;
    double physical_time = 0, wall_time = 0, loop_time = 0;
    double ns_per_particle_step = 0;
    double dt_last = 0;
    int outputs = 0;
    std::string stop_reason;
    std::string state_hash;
    std::string options;  ///< physics options, one line
};

/// Builds the backend's initial data from the case (particles in id order).
BackendSetup makeBackendSetup(const SolverCase& c, int cell_div);

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
    void placeMoving(double time, double interval);
    double limitDt(double dt);

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
    OutputObserver observer_;
};

/// One-line description of the physics options ("symplectic, Wendland, artificial 0.1, ...").
std::string describePhysics(const SolverParameters& p, int dim, int cell_div);

}  // namespace seaspring::solver
