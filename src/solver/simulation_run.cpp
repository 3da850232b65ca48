// SeaSpring — MIT licence.
/// \file simulation_run.cpp
/// \brief The time loop of Simulation::run (see simulation.h): one step of the case's scheme
///        (time_steppers.h), then gauges, warnings, outputs, stop rules and progress; the
///        run summary at the end.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>

#include "core/device_memory.h"
#include "core/memory_budget.h"
#include "solver/gauge_system.h"
#include "solver/phase_timers.h"
#include "solver/run_progress.h"
#include "solver/simulation.h"
#include "solver/simulation_parts.h"
#include "solver/state_hash.h"
#include "solver/step_context.h"
#include "solver/stop_signal.h"
#include "solver/time_steppers.h"

namespace seaspring::solver {

namespace fs = std::filesystem;

namespace {

/// Notes (once) when more than WrnPartsOut % of the fluid is excluded; returns whether it did.
/// Water leaving through an open end of the domain is normal, so this is a note that says what
/// it means, not an alarm: a real loss of the fluid is a blow-up (MinFluidStop, blowup_check.h).
bool warnExcludedFluid(std::ostream& log, const SolverCase& c, std::uint32_t active) {
    if (c.nfluid == 0 || !(double(c.nfluid - active) > c.params.wrn_parts_out / 100.0 * c.nfluid)) return false;
    log << "note: " << (c.nfluid - active) << " fluid particles are excluded, more than WrnPartsOut "
        << c.params.wrn_parts_out << "% of the fluid (they left the domain or their density left [RhopOutMin, "
           "RhopOutMax]; run.json counts each reason). Expected where water leaves the domain; a loss below "
           "MinFluidStop stops the run as a blow-up\n";
    return true;
}

/// The output time after `t`: TimeOut added to `next` until it passes t (the same sums as
/// always); when t is so far ahead that this would take more than a million additions or would
/// stop growing (dt = 1e30, a solid sub-step of 1e149 s), the next multiple of TimeOut after t.
double nextOutputTime(double next, double t, double tout) {
    if ((t - next) / tout < 1e6) {
        while (next <= t + 1e-9 * tout) next += tout;
        return next;
    }
    const double n = std::floor(t / tout) + 1;
    const double k = n * tout;
    return k > t ? k : std::nextafter(t, HUGE_VAL);
}

/// The loop's thresholds (run() and aheadBefore share them): it goes on while t is below
/// endOf(TimeMax); an output is due from outputFrom(next output time), a checkpoint from
/// checkpointFrom(next checkpoint time).
double endOf(double tmax) { return tmax - 1e-12 * tmax; }
double outputFrom(double next_out, double tout) { return next_out - 1e-9 * tout; }
double checkpointFrom(double next_checkpoint, double interval) { return next_checkpoint - 1e-9 * interval; }

}  // namespace

double Simulation::aheadBefore(double next_out, double next_checkpoint) const {
    const SolverParameters& p = case_.params;
    // The loop's thresholds (above; an output is also due at t >= TimeMax, which the first
    // covers). A gauge is due from its next time less 1e-12 max(1, |t|)
    // (GaugeSystem::evaluate): 1e-11 keeps clear of it.
    double before = std::min({endOf(p.time_max), outputFrom(next_out, p.time_out),
                              checkpointFrom(next_checkpoint, opt_.checkpoint_interval)});
    if (gauges_ && std::isfinite(gauges_->nextTime())) {
        const double g = gauges_->nextTime();
        before = std::min(before, g - 1e-11 * std::max(1.0, std::fabs(g)));
    }
    return before;
}

RunSummary Simulation::run() {
    using Clock = std::chrono::steady_clock;
    const Clock::time_point t_start = Clock::now();
    const SolverParameters& p = case_.params;
    const double tmax = p.time_max, tout = p.time_out;
    const long long max_steps = opt_.nsteps ? *opt_.nsteps : -1;
    PhaseTimers timers(*backend_);  // SEASPRING_TIMERS=1
    StepContext ctx(*backend_, case_, setup_, opt_.solid_substeps, timers);

    try {
        backend_->init(setup_);
    } catch (const OutOfDeviceMemory& e) {  // the case is too large for the device: name it
        throw Error(formatLocation(case_.h5_path, 0,
                                   "the run's " + std::to_string(sum_.np) +
                                       " particles do not fit the GPU: " + e.what()));
    }
    // The backend holds the initial state now: its host copy goes (40 bytes per particle).
    std::vector<physics::Double3>().swap(setup_.pos);
    std::vector<physics::Float4>().swap(setup_.velrho);
    const std::unique_ptr<TimeStepper> stepper = makeTimeStepper(ctx);
    LoopState loop;
    if (resume_) {  // -restart: the saved state in place of the start (simulation_checkpoint.cpp)
        loop = resume(*stepper, ctx);
        sum_.restarted_from = resume_->source;
        sum_.restart_time = loop.t;
        if (gauges_) gauges_->attach(*backend_);
        std::error_code ec;
        if (terminateRequested() && fs::remove(fs::path(opt_.outdir) / "TERMINATE", ec))
            log_ << "  removed OUTDIR/TERMINATE, which ended the run this one continues\n";
    } else {
        ctx.placeMoving(0.0, initialDt(case_));
        backend_->divide(false);
        if (gauges_) {
            gauges_->attach(*backend_);
            gauges_->evaluate(0.0, *backend_);
        }
        if (!output(0.0, 0)) {  // a state that is not finite from the start
            finish(0.0, 0, 0.0, ctx.counters());
            return summary();
        }
        loop.next_out = tout;
        loop.next_checkpoint = nextCheckpoint(0.0);
    }
    double t = loop.t, next_out = loop.next_out, next_checkpoint = loop.next_checkpoint;
    long long step = loop.step;
    bool warned_out = loop.warned_out;
    auto loopState = [&] { return LoopState{t, next_out, nextCheckpoint(t), step, warned_out}; };
    const long long step0 = step;  // where this run starts (-restart: the saved step)
    RunProgress progress(log_, opt_.quiet ? 0.0 : opt_.progress_interval, tmax, sum_.np, t, step0);
    // OUTDIR/TERMINATE is looked for after the first step, then at most every 0.2 s of wall
    // time: a file-system call after every step is a measurable share of a small case's step.
    Clock::time_point next_terminate_look = Clock::now();
    // A stop request seen while the next force evaluation was already launched (the state at
    // the step's end then holds that evaluation's writes, Backend::divideThenForces) is acted
    // on one step later, at the end of a step that launched nothing ahead.
    bool terminate_pending = false;
    // The cells' switch (cell_switch.h), said in the log once, when it happens in this run.
    bool switch_said = !setup_.cell_switch.on || backend_->divideCounts().cell_switch_divide != 0;
    sum_.stop_reason = "TimeMax reached";
    while (t < endOf(tmax)) {
        if (max_steps >= 0 && step >= max_steps) {
            sum_.stop_reason = "step limit (-nsteps) reached";
            break;
        }
        const int sig = stopSignal();
        if (sig != 0 && !backend_->forcesAhead()) {  // SIGINT/SIGTERM (stop_signal.h): end cleanly
            sum_.stop_reason = std::string("stopped by ") + stopSignalName(sig);
            sum_.exit_code = 128 + sig;
            saveCheckpoint(loopState(), *stepper, ctx);  // before the extra output: -restart continues the run
            if (lastOutputTime() < t) output(t, step);  // the state it stopped at
            break;
        }
        StepWindow window{std::min({next_out, tmax, gauges_ ? gauges_->nextTime() : tmax}),
                          max_steps >= 0 ? max_steps - step : -1};
        if (sig == 0 && !terminate_pending && (max_steps < 0 || step + 1 < max_steps) && !health_->check.scanDue(step + 1))
            window.ahead_before = aheadBefore(next_out, next_checkpoint);
        StepResult done;
        try {
            done = stepper->advance(t, window);
        } catch (const NonFiniteStep& e) {  // the dt of a force evaluation: a blow-up
            stepFailed(t, step, e.what());
            break;
        }
        t = done.time;
        step += done.steps;
        sum_.dt_last = done.dt;

        if (gauges_) gauges_->evaluate(t, *backend_);
        const std::uint32_t active = backend_->activeFluid();
        const DivideCounts dc = switch_said ? DivideCounts{} : backend_->divideCounts();
        if (dc.cell_switch_divide != 0) {
            switch_said = true;
            sum_.cell_switch_time = t;
            char line[256];
            std::snprintf(line, sizeof line,
                          "  cells of h from divide %llu (step %lld, t=%g s): %llu of %llu fluid particles (%.1f%%) "
                          "shared their cells with another\n",
                          static_cast<unsigned long long>(dc.cell_switch_divide), step, t,
                          static_cast<unsigned long long>(dc.cell_switch_shared),
                          static_cast<unsigned long long>(dc.cell_switch_fluid),
                          100.0 * double(dc.cell_switch_shared) / double(dc.cell_switch_fluid));
            log_ << line;
        }
        if (!warned_out) warned_out = warnExcludedFluid(log_, case_, active);
        const bool output_due = t >= outputFrom(next_out, tout) || t >= tmax;
        if (!checkStep(t, step, done.dt, active, ctx.counters().dtmin_hits, output_due)) break;
        if (output_due) {
            if (!output(t, step)) break;
            next_out = nextOutputTime(next_out, t, tout);
        }
        progress.afterStep(t, step, done.dt, active, ctx.counters().dtmin_hits);
        if (t >= checkpointFrom(next_checkpoint, opt_.checkpoint_interval)) {  // -checkpoint
            saveCheckpoint(loopState(), *stepper, ctx);
            next_checkpoint = nextCheckpoint(t);
        }
        const bool look = !terminate_pending && Clock::now() >= next_terminate_look;
        if (look) next_terminate_look = Clock::now() + std::chrono::milliseconds(200);
        if (look && terminateRequested()) terminate_pending = true;
        if (terminate_pending && !backend_->forcesAhead()) {  // DualSPHysics' TERMINATE file: save, then stop cleanly
            saveCheckpoint(loopState(), *stepper, ctx);
            if (lastOutputTime() < t) output(t, step);
            sum_.stop_reason = "TERMINATE file in OUTDIR";
            break;
        }
    }
    if (out_) {  // the last part file written (inside the loop's time)
        const auto t0 = Clock::now();
        out_->parts.wait();
        sum_.output_time += std::chrono::duration<double>(Clock::now() - t0).count();
    }
    const double loop_time = progress.elapsed();
    timers.report(log_, step - step0);
    sum_.steps_run = step - step0;
    finish(t, step, loop_time, ctx.counters());
    sum_.wall_time = std::chrono::duration<double>(Clock::now() - t_start).count();
    return summary();
}

RunSummary Simulation::summary() const {
    RunSummary s = sum_;
    s.host_bytes_peak = peakHostMemory();
    const DeviceMemoryUse m = backend_->deviceMemory();
    s.gpu_bytes_peak = m.peak;
    s.gpu_bytes_total = m.total;
    return s;
}

void Simulation::finish(double t, long long step, double loop_time, const StepCounters& counters) {
    if ((out_index_ == 0 || sum_.outputs == 0) && !sum_.blowup) output(t, step);
    if (out_) out_->parts.wait();  // every part file written (or its error thrown) before the summary
    if (gauges_) {
        gauges_->flush();
        sum_.gauge_rows = gauges_->rows();
    }
    backend_->download(final_);
    sum_.state_hash = hashHex(stateHash(final_));
    for (std::uint8_t e : final_.excl) {
        if (e == physics::kExcludedPosition) ++sum_.excluded_position;
        if (e == physics::kExcludedDensity) ++sum_.excluded_density;
        if (e == physics::kExcludedNotFinite) ++sum_.excluded_not_finite;
    }
    sum_.fluid_active = backend_->activeFluid();
    sum_.steps = step;
    sum_.physical_time = t;
    sum_.loop_time = loop_time;
    // The loop's cost per step: the steps of this run (-restart continues a run at its step).
    const long long run_steps = sum_.steps_run;
    sum_.ns_per_particle_step = run_steps > 0 ? loop_time * 1e9 / (double(run_steps) * double(sum_.np)) : 0;
    sum_.dtmin_hits = counters.dtmin_hits;
    const DivideCounts dc = backend_->divideCounts();
    sum_.divides = dc.divides;
    sum_.sorts = dc.sorts;
    sum_.boundary_sorts = dc.boundary_sorts;
    sum_.merged_sorts = dc.merged_sorts;
    sum_.cell_switch_divide = dc.cell_switch_divide;
    sum_.solid_substeps = counters.solid_substeps;
    sum_.omega_max = counters.omega_max;
    if (setup_.solid.empty()) return;
    const bool solid_only = case_.nfluid == 0;
    if (solid_only) {
        sum_.solid_substeps = step;  // each step is one solid sub-step
        sum_.omega_max = step > 0 ? 1 : 0;
    }
    sum_.solid_dt = setup_.solid.dt;
    sum_.broken_bonds = brokenBonds(final_);
    if (solid_only && run_steps > 0)
        sum_.ns_per_particle_step = loop_time * 1e9 / (double(run_steps) * double(setup_.solid.nsolid));
}

}  // namespace seaspring::solver
