// SeaSpring — MIT licence.
/// \file step_context.h
/// \brief What every time-step scheme (time_steppers.h) works with: the backend, the case,
///        the phase timers, and the services the schemes share (moving boundaries, the dt of a
///        force evaluation, the VCPM solid sub-cycle) with the counters they keep for run.json.
#pragma once

#include <vector>

#include "solver/backend.h"
#include "solver/phase_timers.h"
#include "solver/solver_case.h"

namespace seaspring::solver {

/// What the steps count for the run summary.
struct StepCounters {
    long long dtmin_hits = 0;      ///< dt raised to DtMin
    long long solid_substeps = 0;  ///< solid sub-steps of the fluid steps' sub-cycles
    int omega_max = 0;             ///< most solid sub-steps in one fluid step
};

/// The first dt: DtIni, or h / c0 when the case gives none (a case without fluid and without a
/// speed of sound: TimeOut / 1000; it only sets the first velocity of moving walls).
double initialDt(const SolverCase& c);

class StepContext {
public:
    /// `solid_substeps`: -vcpmsubsteps (0: automatic).
    StepContext(Backend& backend, const SolverCase& c, const BackendSetup& setup, int solid_substeps,
                PhaseTimers& timers);

    Backend& backend() const { return backend_; }
    const SolverCase& solverCase() const { return case_; }
    const SolverParameters& params() const { return case_.params; }
    const BackendSetup& setup() const { return setup_; }
    PhaseTimers& timers() const { return timers_; }
    /// Whether steps may launch the next force evaluation with their divide
    /// (Backend::divideThenForces): not with the phase timers on (each phase is timed up to
    /// a synchronisation), nor with SEASPRING_FORCES_AHEAD=0 in the environment (for
    /// measurements; the bits are the same either way).
    bool forcesAheadAllowed() const { return ahead_allowed_; }
    const StepCounters& counters() const { return counters_; }
    /// The counters into and out of a restart file ("counters/").
    void saveCounters(CheckpointData& d) const;
    void loadCounters(const CheckpointData& d);
    bool hasSolids() const { return !setup_.solid.empty(); }

    /// Motion objects' poses at `time` and `time + interval`.
    std::vector<physics::RigidMotionGpu> motionsOver(double time, double interval) const;
    /// Places the moving boundaries: pose at `time`, velocity over the coming `interval`
    /// (no-op without moving boundaries).
    void placeMoving(double time, double interval);
    /// One force evaluation (timed as "forces") and the dt it allows: the CFL condition
    /// (physics::variableDt) through limitDt.
    double forcesDt();
    /// `dt` raised to DtMin (counted in dtmin_hits); throws seaspring::Error when it is not finite.
    double limitDt(double dt);
    /// The solid sub-cycle of one fluid step [time, time + dt_fluid] (no-op without solids):
    /// -vcpmsubsteps or physics::solidSubsteps sub-steps; `ledger`: see Backend::solidSteps.
    void advanceSolid(double time, double dt_fluid, bool ledger = true);

private:
    Backend& backend_;
    const SolverCase& case_;
    const BackendSetup& setup_;
    int solid_substeps_;
    PhaseTimers& timers_;
    bool ahead_allowed_;
    StepCounters counters_;
};

}  // namespace seaspring::solver
