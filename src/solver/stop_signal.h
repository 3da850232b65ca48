// SeaSpring — MIT licence.
/// \file stop_signal.h
/// \brief SIGINT and SIGTERM ask the run to stop: the handler only records the signal; the time
///        loop looks at it after every step and ends the run cleanly (last state written,
///        run.json with the reason, the log flushed); the program then exits with 128 + the
///        signal number (130, 143), as a shell reports a process killed by it.
#pragma once

namespace seaspring::solver {

/// Installs the handlers (once per process; later calls do nothing).
void installStopSignals();
/// The signal that asked the run to stop, 0 when none.
int stopSignal();
/// "SIGINT", "SIGTERM" or "signal N".
const char* stopSignalName(int sig);
/// For tests: records `sig` as if it had been received (0 clears it).
void setStopSignalForTest(int sig);

}  // namespace seaspring::solver
