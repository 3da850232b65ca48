// SeaSpring — MIT licence.
/// \file run_progress.h
/// \brief The wall clock of the time loop and its progress lines
///        ("t=0.01234/1 s  steps=...  dt=...  steps/s  ns/particle/step  fluid=...  ETA ... s").
#pragma once

#include <chrono>
#include <cstdint>
#include <iosfwd>

namespace seaspring::solver {

class RunProgress {
    using Clock = std::chrono::steady_clock;

public:
    /// Starts the loop clock at simulated time `t0` and step `step0` (both 0, or where -restart
    /// continues the run). A progress line at most every `interval` seconds of wall time (none
    /// when `interval` is 0); `tmax` and `np` (particles) give the ETA and the cost per particle.
    /// Rates and the ETA count only the steps and simulated time of this run.
    RunProgress(std::ostream& log, double interval, double tmax, std::uint32_t np, double t0 = 0,
                long long step0 = 0);

    /// After each pass of the loop: prints a line when `interval` has passed since the last one
    /// (or since the start).
    void afterStep(double t, long long step, double dt, std::uint32_t active_fluid, long long dtmin_hits);

    /// Wall seconds since the loop started.
    double elapsed() const;

private:
    std::ostream& log_;
    double interval_, tmax_, np_, t0_;
    long long step0_;
    Clock::time_point start_, last_line_;
};

}  // namespace seaspring::solver
