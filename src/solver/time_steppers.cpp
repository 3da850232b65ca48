// SeaSpring — MIT licence.
/// \file time_steppers.cpp
/// \brief The time-step schemes (see time_steppers.h).
#include "solver/time_steppers.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace seaspring::solver {

namespace {

/// The end of a fluid step [time, time + dt] once the fluid is integrated: the solid's
/// sub-cycle (with solids), the moving boundaries placed at time + dt with their velocity over
/// `motion_interval` (the coming step's dt where known), and the division; with the next force
/// evaluation launched at once where the window allows (StepWindow::ahead_before).
StepResult endFluidStep(StepContext& ctx, double time, double dt, double motion_interval, const StepWindow& window) {
    PhaseTimers& timers = ctx.timers();
    if (ctx.hasSolids()) {
        timers.time(PhaseTimers::Solid, [&] {
            ctx.advanceSolid(time, dt);
            ctx.backend().startSolidsCheck();  // its result comes back with the division's
        });
    }
    const double t = time + dt;
    timers.time(PhaseTimers::Motion, [&] { ctx.placeMoving(t, motion_interval); });
    timers.time(PhaseTimers::Divide, [&] {
        if (ctx.forcesAheadAllowed() && t < window.ahead_before) ctx.backend().divideThenForces(false);
        else ctx.backend().divide(false);
    });
    return StepResult{t, dt, 1};
}

}  // namespace

SymplecticStepper::SymplecticStepper(StepContext& ctx, bool midpoint)
    : ctx_(ctx), midpoint_(midpoint), dt_next_(initialDt(ctx.solverCase())) {}

StepResult SymplecticStepper::advance(double time, const StepWindow& window) {
    Backend& b = ctx_.backend();
    PhaseTimers& timers = ctx_.timers();
    const double dt_fixed = ctx_.params().dt_fixed;
    const double dt = dt_fixed > 0 ? dt_fixed : dt_next_;
    const double dt_predictor = ctx_.forcesDt();
    if (midpoint_) {
        timers.time(PhaseTimers::Solid, [&] {
            b.solidSave();
            ctx_.advanceSolid(time, 0.5 * dt, false);
        });
    }
    timers.time(PhaseTimers::Integrate, [&] { b.symplecticPredictor(dt); });
    timers.time(PhaseTimers::Divide, [&] {  // the corrector's evaluation follows at once
        if (ctx_.forcesAheadAllowed()) b.divideThenForces(true);
        else b.divide(true);
    });
    const double dt_corrector = ctx_.forcesDt();
    if (midpoint_) timers.time(PhaseTimers::Solid, [&] { b.solidRestore(); });
    timers.time(PhaseTimers::Integrate, [&] { b.symplecticCorrector(dt); });
    dt_next_ = std::min(dt_predictor, dt_corrector);
    return endFluidStep(ctx_, time, dt, dt_fixed > 0 ? dt_fixed : dt_next_, window);
}

VerletStepper::VerletStepper(StepContext& ctx) : ctx_(ctx) {}

StepResult VerletStepper::advance(double time, const StepWindow& window) {
    Backend& b = ctx_.backend();
    PhaseTimers& timers = ctx_.timers();
    const SolverParameters& p = ctx_.params();
    const double dt_forces = ctx_.forcesDt();
    const double dt = p.dt_fixed > 0 ? p.dt_fixed : dt_forces;
    const bool euler = ++steps_since_euler_ >= p.verlet_steps;
    if (euler) steps_since_euler_ = 0;
    timers.time(PhaseTimers::Integrate, [&] { b.verletStep(dt, euler); });
    return endFluidStep(ctx_, time, dt, dt, window);
}

SolidOnlyStepper::SolidOnlyStepper(StepContext& ctx) : ctx_(ctx) {
    const SolverParameters& p = ctx.params();
    const SolidSetup& solid = ctx.setup().solid;
    dt_ = p.dt_fixed > 0 ? std::min(p.dt_fixed, solid.dt) : solid.dt;
    for (std::int16_t o : solid.clamp_object) clamp_moves_ = clamp_moves_ || o >= 0;
}

StepResult SolidOnlyStepper::advance(double time, const StepWindow& window) {
    const double dt = dt_;
    long long n = std::max(1LL, (long long)std::ceil((window.until - time) / dt - 1e-9));
    if (clamp_moves_) n = 1;
    if (window.steps_left >= 0) n = std::min(n, window.steps_left);
    const SolidSetup& solid = ctx_.setup().solid;
    if (solid.contact_on) {
        // Contact lists are made from the boundary block's cells: sort it at the solids' positions
        // and take no more sub-steps than the lists' margin allows (physics::contactChunk).
        ctx_.backend().divide(false);
        const physics::StepConstants& sc = ctx_.setup().step;
        const double g = std::sqrt(sc.gx * sc.gx + sc.gy * sc.gy + sc.gz * sc.gz);
        n = physics::contactChunk(ctx_.backend().solidMaxSpeed(), g, dt, solid.contact, n);
    }
    ctx_.timers().time(PhaseTimers::Integrate, [&] {
        double t = time;
        for (long long left = n; left > 0;) {  // Backend::solidSteps takes an int count
            const int chunk = int(std::min<long long>(left, 1 << 30));
            ctx_.backend().solidSteps(t, dt, chunk, ctx_.motionsOver(t, dt * chunk), true);
            t += dt * chunk;
            left -= chunk;
        }
    });
    const double t = time + double(n) * dt;
    ctx_.placeMoving(t, dt);
    return StepResult{t, dt, n};
}

std::unique_ptr<TimeStepper> makeTimeStepper(StepContext& ctx) {
    const bool solids = ctx.hasSolids();
    if (solids && ctx.solverCase().nfluid == 0) return std::make_unique<SolidOnlyStepper>(ctx);
    if (ctx.params().step_algorithm == 2)
        return std::make_unique<SymplecticStepper>(ctx, solids && ctx.params().vcpm_coupling == 2);
    return std::make_unique<VerletStepper>(ctx);
}

}  // namespace seaspring::solver
