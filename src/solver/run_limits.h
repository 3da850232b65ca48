// SeaSpring — MIT licence.
/// \file run_limits.h
/// \brief What a run must fit in before it starts: the host memory for its particle arrays, and a
///        VCPM sub-step that reaches TimeMax in a bounded number of sub-steps (E = 1e300 gives a
///        1e-151 s sub-step: the run would never end) without stepping past it at once
///        (E = 1e-300: one sub-step of 1e149 s).
#pragma once

#include "solver/solid_setup.h"
#include "solver/solver_case.h"

namespace seaspring::solver {

/// The most VCPM sub-steps a run may need to reach TimeMax.
constexpr double kMaxSolidSubsteps = 1e12;

/// Host memory per particle of a run [bytes]: the case's particles, the backend's initial data,
/// the CPU backend's arrays and the state copies of the outputs and the blow-up check.
constexpr double kRunBytesPerParticle = 400;

/// Throws seaspring::Error (memory_budget.h) when the run's particle arrays would not fit.
void checkRunMemory(const SolverCase& c);

/// Throws seaspring::Error naming the solid's line and youngmod when TimeMax needs more than
/// kMaxSolidSubsteps sub-steps, or, without fluid, when one sub-step is longer than TimeMax.
void checkSolidSubstep(const SolverCase& c, const SolidSetup& s);

}  // namespace seaspring::solver
