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

/// Host memory per particle of a run on the CPU [bytes]: the case's particles, the CPU backend's
/// arrays, the state copies of the outputs and the blow-up check (the initial state's copy is
/// freed once the backend holds it). Measured at the peak (core/memory_budget.h peakHostMemory,
/// run.json's memory): SPHERIC Test 2 at 2.0 M particles, 2 threads, 405 B with part files
/// (278 B with -sv:none); laminar+SPS adds its stress fields (48 B).
constexpr double kRunBytesPerParticle = 480;
/// The same for a run on the GPU, whose arrays are on the device. Measured on an NVIDIA H200's
/// host (docs/performance-large.md, thirty-second session): SPHERIC Test 2 at 13.3 M particles
/// 259 B with part files (131 B with -sv:none), FlexStruc Liao 3D (VCPM plate, moving walls)
/// 292 B with part files (228 B with -sv:none).
constexpr double kRunBytesPerParticleGpu = 320;

/// Host bytes of the case's particle arrays as read (the check runs after they are).
double loadedCaseBytes(const SolverCase& c);

/// Throws seaspring::Error (memory_budget.h) naming the case file when the run's host memory
/// (kRunBytesPerParticle, or kRunBytesPerParticleGpu for `gpu`, less loadedCaseBytes, which
/// MemAvailable no longer counts) would not fit.
void checkRunMemory(const SolverCase& c, bool gpu);

/// Throws seaspring::Error naming the solid's line and youngmod when TimeMax needs more than
/// kMaxSolidSubsteps sub-steps, or, without fluid, when one sub-step is longer than TimeMax.
void checkSolidSubstep(const SolverCase& c, const SolidSetup& s);

}  // namespace seaspring::solver
