// SeaSpring — MIT licence.
/// \file particle_extraction.h
/// \brief Turns the drawn lattice into the ordered particle arrays.
#pragma once

#include <array>
#include <vector>

#include "core/particle_set.h"
#include "core/vec3.h"
#include "gencase/lattice_grid.h"

namespace seaspring::gencase {

/// Type of every global MK (index = MK). MKs never drawn may hold any value.
using MkTypes = std::array<ParticleType, 65536>;

/// Particles ordered by type block (fixed, moving, solid, fluid), then MK, then lattice order
/// (x fastest, then y, then z); ids 0..n-1 in that order. Velocity 0; density, mass left 0.
/// When `lattice` is not null it receives each particle's lattice index.
ParticleSet extractParticles(const LatticeGrid& grid, const MkTypes& types,
                             std::vector<Vec3i>* lattice);

/// Hydrostatic initial density of the fluid (rhopgradient 2: depth below the top of the
/// contiguous fluid column above the particle; 3: depth below the highest fluid particle;
/// 1: rho0), rho0 elsewhere. Gravity is taken along z with magnitude |gz|. Fluid MKs are
/// 1..fluid_mk_max.
void setInitialDensity(ParticleSet& p, const LatticeGrid& grid, const std::vector<Vec3i>& lattice,
                       int rhopgradient, double rho0, double b, double gamma, double gz,
                       std::uint16_t fluid_mk_max);

}  // namespace seaspring::gencase
