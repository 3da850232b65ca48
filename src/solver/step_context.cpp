// SeaSpring — MIT licence.
/// \file step_context.cpp
/// \brief Services the time-step schemes share (see step_context.h).
#include "solver/step_context.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/error.h"
#include "physics/vcpm.h"
#include "solver/blowup_check.h"
#include "solver/motion_player.h"

namespace seaspring::solver {

double initialDt(const SolverCase& c) {
    if (!(c.constants.speedsound > 0))  // no fluid, no speed of sound: only moving walls use it
        return c.params.dt_ini > 0 ? c.params.dt_ini : 1e-3 * c.params.time_out;
    return physics::initialDt(c.params.dt_ini, c.constants.h, c.constants.speedsound);
}

StepContext::StepContext(Backend& backend, const SolverCase& c, const BackendSetup& setup, int solid_substeps,
                         PhaseTimers& timers)
    : backend_(backend), case_(c), setup_(setup), solid_substeps_(solid_substeps), timers_(timers) {
    const char* env = std::getenv("SEASPRING_FORCES_AHEAD");
    ahead_allowed_ = !timers.enabled() && !(env != nullptr && std::string(env) == "0");
}

std::vector<physics::RigidMotionGpu> StepContext::motionsOver(double time, double interval) const {
    return motionPosesOver(case_.motion, time, interval);
}

void StepContext::placeMoving(double time, double interval) {
    if (setup_.nmoving == 0) return;
    backend_.applyMotion(motionsOver(time, interval));
}

double StepContext::forcesDt() {
    const physics::DtMaxima m = timers_.time(PhaseTimers::Forces, [&] { return backend_.computeForces(); });
    return limitDt(physics::variableDt(m, case_.constants.h, case_.constants.speedsound, case_.params.cfl_number));
}

double StepContext::limitDt(double dt) {
    const double dtmin = physics::minimumDt(case_.params.dt_min, case_.params.coef_dt_min, case_.constants.h,
                                            case_.constants.speedsound);
    if (!std::isfinite(dt)) {
        char v[64];
        std::snprintf(v, sizeof v, "%g", dt);
        throw NonFiniteStep("the time step is not finite (dt = " + std::string(v) +
                            "): the forces diverged");
    }
    if (dt < dtmin) {
        ++counters_.dtmin_hits;
        return dtmin;
    }
    return dt;
}

void StepContext::advanceSolid(double time, double dt_fluid, bool ledger) {
    if (setup_.solid.empty()) return;
    const int omega = solid_substeps_ > 0 ? solid_substeps_ : physics::solidSubsteps(dt_fluid, setup_.solid.dt);
    backend_.solidSteps(time, dt_fluid / omega, omega, motionsOver(time, dt_fluid), ledger);
    counters_.solid_substeps += omega;
    counters_.omega_max = std::max(counters_.omega_max, omega);
}

void StepContext::saveCounters(CheckpointData& d) const {
    d.ints["counters/dtmin_hits"] = counters_.dtmin_hits;
    d.ints["counters/solid_substeps"] = counters_.solid_substeps;
    d.ints["counters/omega_max"] = counters_.omega_max;
}

void StepContext::loadCounters(const CheckpointData& d) {
    counters_.dtmin_hits = d.integer("counters/dtmin_hits");
    counters_.solid_substeps = d.integer("counters/solid_substeps");
    counters_.omega_max = int(d.integer("counters/omega_max"));
}

}  // namespace seaspring::solver
