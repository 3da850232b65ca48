// SeaSpring — MIT licence.
/// \file time_steppers.h
/// \brief One step of each time-integration scheme: symplectic (both VCPM couplings), Verlet,
///        and solid-only runs. A step advances the backend's state by one step (solid-only: a
///        chunk of solid sub-steps), places the moving boundaries for the next one and divides;
///        outputs, gauges, progress and the stop rules belong to the loop (Simulation::run).
#pragma once

#include <cmath>
#include <memory>

#include "solver/step_context.h"

namespace seaspring::solver {

/// What the loop asks of the next step: where it must stop (solid-only chunks end there;
/// fluid steps take their dt from the CFL condition and ignore it).
struct StepWindow {
    double until = 0;           ///< the next output, gauge measurement or TimeMax
    long long steps_left = -1;  ///< steps left before -nsteps (-1: no limit)
    /// A fluid step that ends before this time launches the next force evaluation with its
    /// divide (Backend::divideThenForces): the loop sets it where nothing reads, writes out or
    /// saves the state at the step's end (no output, gauge, checkpoint, health scan, step limit
    /// or stop request due); -inf (the default): never.
    double ahead_before = -HUGE_VAL;
};

/// What one step did.
struct StepResult {
    double time = 0;      ///< the time reached
    double dt = 0;        ///< the step (solid-only: sub-step) length
    long long steps = 0;  ///< steps done: 1 for a fluid step, the sub-steps of a solid-only chunk
};

class TimeStepper {
public:
    virtual ~TimeStepper() = default;
    /// Advances the state from `time` (particles divided, moving boundaries placed).
    virtual StepResult advance(double time, const StepWindow& window) = 0;
    /// What the scheme carries from one step to the next (restart files, "stepper/").
    virtual void save(CheckpointData&) const {}
    virtual void load(const CheckpointData&) {}
};

/// Symplectic position-Verlet: forces, predictor to n+1/2, divide, forces, corrector; the next
/// dt is the smaller of the two evaluations' (DtFixed when given). With solids, the solid
/// sub-cycles over [t, t+dt] after the corrector with the hydrodynamic force of the corrector's
/// evaluation (VcpmCoupling 1, as seed 000); `midpoint` (VcpmCoupling 2, staggered midpoint):
/// the solid first goes to n+1/2 with the force at n, so that the corrector's evaluation sees
/// fluid and solid at n+1/2, and is then restored to n.
class SymplecticStepper final : public TimeStepper {
public:
    SymplecticStepper(StepContext& ctx, bool midpoint);
    StepResult advance(double time, const StepWindow& window) override;
    void save(CheckpointData& d) const override { d.reals["stepper/dt_next"] = dt_next_; }
    void load(const CheckpointData& d) override { dt_next_ = d.real("stepper/dt_next"); }

private:
    StepContext& ctx_;
    bool midpoint_;
    double dt_next_;  ///< the dt of the coming step
};

/// Verlet with an Euler step every VerletSteps steps: forces (dt from them, or DtFixed), one
/// integration; with solids, the solid sub-cycles over [t, t+dt] with that evaluation's force.
class VerletStepper final : public TimeStepper {
public:
    explicit VerletStepper(StepContext& ctx);
    StepResult advance(double time, const StepWindow& window) override;
    void save(CheckpointData& d) const override { d.ints["stepper/steps_since_euler"] = steps_since_euler_; }
    void load(const CheckpointData& d) override { steps_since_euler_ = int(d.integer("stepper/steps_since_euler")); }

private:
    StepContext& ctx_;
    int steps_since_euler_ = 0;
};

/// No fluid: the solid advances by its own sub-step (DtFixed when smaller), in chunks up to the
/// window's end; one sub-step per chunk when a clamp moves, so that it follows its motion law.
class SolidOnlyStepper final : public TimeStepper {
public:
    explicit SolidOnlyStepper(StepContext& ctx);
    StepResult advance(double time, const StepWindow& window) override;

private:
    StepContext& ctx_;
    double dt_;
    bool clamp_moves_ = false;
};

/// The scheme of the case: solid-only when it has solids and no fluid, else its step algorithm.
std::unique_ptr<TimeStepper> makeTimeStepper(StepContext& ctx);

}  // namespace seaspring::solver
