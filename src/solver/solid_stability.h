// SeaSpring — MIT licence.
/// \file solid_stability.h
/// \brief The solid sub-step's margin for the surface-corrected lattice: Gershgorin's bound on
///        the largest eigenvalue of the lattice's stiffness matrix, per body, against the plain
///        bulk lattice's that VcpmDtCoef is calibrated for (physics/vcpm_surface.h).
#pragma once

#include <vector>

namespace seaspring::solver {

struct SolidSetup;

/// Per body, the factor (<= 1) of its sub-step: sqrt(R_bulk / R_max) where the corrected
/// lattice's largest Gershgorin row sum R_max (with s.kfac and s.vw) exceeds the plain bulk
/// site's R_bulk, else 1.
std::vector<double> correctedSubStepScales(const SolidSetup& s);

}  // namespace seaspring::solver
