// SeaSpring — MIT licence.
/// \file phase_timers.cpp
/// \brief Phase timers of the time loop (see phase_timers.h).
#include "solver/phase_timers.h"

#include <cstdio>
#include <cstdlib>
#include <ostream>

#include "solver/backend.h"

namespace seaspring::solver {

PhaseTimers::PhaseTimers(Backend& backend)
    : backend_(backend), enabled_(std::getenv("SEASPRING_TIMERS") != nullptr) {}

void PhaseTimers::stop(Phase phase, Clock::time_point start) {
    backend_.synchronize();
    seconds_[phase] += std::chrono::duration<double>(Clock::now() - start).count();
}

void PhaseTimers::report(std::ostream& log, long long steps) const {
    if (!enabled_ || steps <= 0) return;
    const double n = double(steps);
    char line[256];
    std::snprintf(line, sizeof line,
                  "phase times per step [ms]: divide %.3f  forces %.3f  integrate %.3f  motion %.3f  solid %.3f\n",
                  1e3 * seconds_[Divide] / n, 1e3 * seconds_[Forces] / n, 1e3 * seconds_[Integrate] / n,
                  1e3 * seconds_[Motion] / n, 1e3 * seconds_[Solid] / n);
    log << line;
}

}  // namespace seaspring::solver
