// SeaSpring — MIT licence.
/// \file stop_signal.cpp
/// \brief SIGINT/SIGTERM recorded for the time loop (see stop_signal.h).
#include "solver/stop_signal.h"

#include <csignal>

namespace seaspring::solver {

namespace {
volatile std::sig_atomic_t g_signal = 0;
extern "C" void onStopSignal(int sig) { g_signal = sig; }
}  // namespace

void installStopSignals() {
    static bool installed = false;
    if (installed) return;
    installed = true;
    std::signal(SIGINT, onStopSignal);
    std::signal(SIGTERM, onStopSignal);
}

int stopSignal() { return int(g_signal); }

const char* stopSignalName(int sig) {
    if (sig == SIGINT) return "SIGINT";
    if (sig == SIGTERM) return "SIGTERM";
    return "a signal";
}

void setStopSignalForTest(int sig) { g_signal = sig; }

}  // namespace seaspring::solver
