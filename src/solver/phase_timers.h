// SeaSpring — MIT licence.
/// \file phase_timers.h
/// \brief SEASPRING_TIMERS=1: the wall time of each phase of the time loop (divide, forces,
///        integrate, motion, solid), the device synchronised after each phase, and the
///        per-step report at the end of a run.
#pragma once

#include <chrono>
#include <iosfwd>
#include <type_traits>

namespace seaspring::solver {

class Backend;

class PhaseTimers {
    using Clock = std::chrono::steady_clock;

public:
    enum Phase { Divide, Forces, Integrate, Motion, Solid, kPhases };

    /// Timing is on when the environment sets SEASPRING_TIMERS; `backend` is synchronised
    /// after each timed phase (so that its queued work counts in that phase).
    explicit PhaseTimers(Backend& backend);

    /// Runs `fn` and returns what it returns; with timing on, adds its wall time (up to the
    /// device synchronisation that follows it) to `phase`.
    template <class F>
    auto time(Phase phase, F&& fn) {
        if (!enabled_) return fn();
        const Clock::time_point start = Clock::now();
        if constexpr (std::is_void_v<decltype(fn())>) {
            fn();
            stop(phase, start);
        } else {
            auto result = fn();
            stop(phase, start);
            return result;
        }
    }

    bool enabled() const { return enabled_; }

    /// "phase times per step [ms]: divide ..." when timing is on and `steps` > 0.
    void report(std::ostream& log, long long steps) const;

private:
    void stop(Phase phase, Clock::time_point start);

    Backend& backend_;
    bool enabled_ = false;
    double seconds_[kPhases] = {};
};

}  // namespace seaspring::solver
