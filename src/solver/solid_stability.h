// SeaSpring — MIT licence.
/// \file solid_stability.h
/// \brief The solid sub-step's margin for the surface-corrected lattice against the plain bulk
///        lattice, which VcpmDtCoef is calibrated for (VcpmSubStepBound): Gershgorin's bounds
///        on both (the default), or the largest eigenvalue of each body's stiffness matrix
///        (Lanczos with the solver's own force functions) against the bulk's (its Bloch
///        analysis, physics::plainBulkLargestStiffness).
#pragma once

#include <vector>

namespace seaspring::solver {

struct SolidSetup;

/// Lanczos steps of the set-up's estimate, and the margin put on it: the largest Ritz value
/// approaches lambda_max from below; measured on the cantilevers 2 to 8 particles thick
/// (tests/solver/test_solid_stability.cpp), 60 steps come within 0.5% of 400 power iterations.
constexpr int kStiffnessIterations = 60;
constexpr double kStiffnessMargin = 0.02;

/// Per body (material index), the largest eigenvalue of K = -dF/dx of the lattice at rest (the
/// solver's force functions, so every correction the set-up applied is in it; clamp nodes held),
/// from `iterations` Lanczos steps on a fixed-seed start vector: deterministic, at most the true
/// value. Each step costs two force evaluations of the whole solid on the host.
std::vector<double> largestStiffnessPerBody(const SolidSetup& s, int iterations);

/// Per body, the plain bulk lattice's largest eigenvalue for its material
/// (physics::plainBulkLargestStiffness in the case's dimension).
std::vector<double> plainBulkStiffnessPerBody(const SolidSetup& s);

/// Per body, the factor (<= 1) of its sub-step from its largest eigenvalue:
/// sqrt(lambda_bulk / lambda_body) where the body's (largestStiffnessPerBody, times
/// 1 + kStiffnessMargin) exceeds the plain bulk lattice's, else 1 (VcpmSubStepBound 1).
std::vector<double> eigenSubStepScales(const SolidSetup& s);

/// Per body, the factor (<= 1) from Gershgorin's bounds: sqrt(R_bulk / R_max) where the
/// corrected lattice's largest row sum R_max (with s.kfac and s.vw) exceeds the plain bulk
/// site's R_bulk (physics::plainBulkRowBound), else 1 (VcpmSubStepBound 0, the default). Each
/// bound holds, their ratio is not one: on bodies 2 particles thick it is some 13% above the
/// eigenvalue factor (docs/vcpm.md).
std::vector<double> gershgorinSubStepScales(const SolidSetup& s);

/// The factor of VcpmSubStepBound `bound` (0 Gershgorin, 1 eigenvalue).
std::vector<double> correctedSubStepScales(const SolidSetup& s, int bound);

}  // namespace seaspring::solver
