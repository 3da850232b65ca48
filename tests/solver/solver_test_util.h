// SeaSpring — MIT licence.
/// \file solver_test_util.h
/// \brief Helpers for solver tests: generate a case with the gencase binary, run it in-process
///        on the CPU backend with a given thread count, and read back the final state.
#pragma once

#include <functional>
#include <string>

#include "solver/run_options.h"
#include "solver/simulation.h"

namespace seaspring::test {

/// A scratch directory for one test: TempDir()/seaspring_TAG_PID_STARTTIME (the same for every
/// call of this process, new for every run).
std::string scratch(const std::string& tag);
/// SEASPRING_SOURCE_DIR/cases/REL (a case definition shipped with the sources).
std::string caseDef(const std::string& rel);
/// The whole file (empty when it cannot be read).
std::string readFile(const std::string& path);
/// `text` with the one occurrence of `from` replaced (fails the test when it is not there once).
std::string replaceOnce(std::string text, const std::string& from, const std::string& to);

double dist(const physics::Double3& a, const physics::Double3& b);
bool finite(const physics::Double3& a);
/// Broken bond slots of a state (a solid-solid bond counts at both ends).
std::size_t brokenSlots(const solver::HostState& st);

/// Writes `def_xml` to dir/NAME_Def.xml, runs gencase (optionally with -dp) and returns
/// dir/NAME (the path seaspring takes). Fails the test (throws) when gencase fails.
std::string generateCase(const std::string& dir, const std::string& name, const std::string& def_xml,
                         double dp = 0);
/// One of the piston tanks of tests/data/phases (`file`, e.g. PistonTank2D_Def.xml) with
/// `params` in place of its <!--PARAMETERS--> mark, generated as dir/piston.
std::string pistonCase(const std::string& dir, const char* file, const std::string& params);
/// Same for an existing definition file.
std::string generateCaseFile(const std::string& dir, const std::string& name, const std::string& def_path,
                             double dp = 0);

struct SolverRun {
    solver::RunSummary summary;
    solver::HostState state;
    solver::SolverCase kase;
};

/// Runs the case on `backend` (not null); `tweak` edits options (tmax, nsteps, overrides...).
SolverRun runOn(std::unique_ptr<solver::Backend> backend, const std::string& case_path, const std::string& outdir,
                const std::function<void(solver::RunOptions&)>& tweak = {},
                const solver::Simulation::OutputObserver& observe = {});

/// Runs the case on the CPU backend; `tweak` edits options (tmax, nsteps, overrides...).
/// `observe` (optional) sees the state at every output time (TimeOut; saving is off).
SolverRun runCpu(const std::string& case_path, const std::string& outdir, int threads,
                 const std::function<void(solver::RunOptions&)>& tweak = {},
                 const solver::Simulation::OutputObserver& observe = {});

}  // namespace seaspring::test
