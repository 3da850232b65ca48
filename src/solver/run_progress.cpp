// SeaSpring — MIT licence.
/// \file run_progress.cpp
/// \brief Loop clock and progress lines (see run_progress.h).
#include "solver/run_progress.h"

#include <cstdio>
#include <ostream>

namespace seaspring::solver {

namespace {
double seconds(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
}
}  // namespace

RunProgress::RunProgress(std::ostream& log, double interval, double tmax, std::uint32_t np, double t0,
                         long long step0)
    : log_(log), interval_(interval), tmax_(tmax), np_(double(np)), t0_(t0), step0_(step0), start_(Clock::now()),
      last_line_(start_) {}

void RunProgress::afterStep(double t, long long step, double dt, std::uint32_t active_fluid,
                            long long dtmin_hits) {
    if (interval_ <= 0) return;
    const Clock::time_point now = Clock::now();
    if (seconds(last_line_, now) < interval_) return;
    last_line_ = now;
    const double el = seconds(start_, now);
    const long long steps = step - step0_;  // of this run (a restart continues at step0_)
    const double sps = steps / el;
    const double ns = steps > 0 ? el * 1e9 / (double(steps) * np_) : 0;
    const double eta = t > t0_ ? el * (tmax_ - t) / (t - t0_) : 0;
    char line[256];
    std::snprintf(line, sizeof line,
                  "t=%.5f/%.4g s  steps=%lld  dt=%.3e  %.1f steps/s  %.2f ns/particle/step  "
                  "fluid=%u  dtmin-hits=%lld  ETA %.3g s\n",
                  t, tmax_, step, dt, sps, ns, active_fluid, dtmin_hits, eta);
    log_ << line << std::flush;
}

double RunProgress::elapsed() const { return seconds(start_, Clock::now()); }

}  // namespace seaspring::solver
