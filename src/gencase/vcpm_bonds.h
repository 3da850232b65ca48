// SeaSpring — MIT licence.
/// \file vcpm_bonds.h
/// \brief Builds the VCPM bond network (first and second lattice neighbours, plus
///        clamp bonds to boundary particles) once, in the preprocessor.
///
/// Solid particles sit on a Simple Cubic lattice of spacing dp (2D: square lattice in
/// the x-z plane). Each solid particle bonds to the lattice sites listed by
/// latticeOffsets() that hold either a solid particle of the same MK or a particle of
/// one of that solid's clamp MKs (see reference notes sph-vcpm-method.md §2.1).
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <vector>

#include "core/particle_set.h"
#include "core/vec3.h"

namespace seaspring::gencase {

/// Lattice offsets in the fixed slot order: first neighbours then second neighbours,
/// each in lexicographic (dz, dy, dx) order. 3D: 6+12; 2D: 4+4 (dy == 0).
const std::vector<Vec3i>& latticeOffsets(bool two_d);

/// Number of first-neighbour offsets at the front of latticeOffsets() (3D: 6, 2D: 4).
std::size_t firstNeighbourCount(bool two_d);

struct BondBuildInput {
    bool two_d = false;
    double dp = 0.0;                                ///< lattice spacing [m]
    const std::vector<Vec3i>* lattice = nullptr;    ///< lattice index of every particle (same order as ids)
    const ParticleSet* particles = nullptr;
    /// Solid global MK -> clamp global MKs (every solid MK has an entry, possibly empty).
    std::map<std::uint16_t, std::vector<std::uint16_t>> clamp_mks;
};

struct BondStats {
    std::size_t solid_particles = 0;
    std::size_t bonds = 0;               ///< solid-solid pairs, each counted once
    std::size_t clamp_bonds = 0;         ///< solid-clamp bonds (stored on the solid side only)
    std::size_t surface_particles = 0;   ///< fewer than 18 (3D) / 8 (2D) bonds incl. clamp bonds
    std::size_t isolated_particles = 0;  ///< no bond at all
    std::map<std::uint16_t, std::size_t> particles_per_mk;  ///< solid MK -> particle count
};

/// Builds the bond network. Rows are in solid-id order, slots in latticeOffsets() order;
/// rest_length = dp or sqrt(2)*dp, kind = BondFirst/BondSecond (| BondClampFlag).
/// Throws seaspring::Error if: an MK holds particles of two types, a solid MK of
/// `clamp_mks` has no particles, a solid particle's MK has no entry, a clamp MK has no
/// particles or is not a fixed/moving boundary MK, solid particles are not contiguous,
/// two solid/clamp particles share a lattice site, or a solid particle has no bond at all. `stats` (may be null) is filled
/// before the isolated-particle check, so it is valid when that error is thrown.
/// Positions being on the lattice is checked by the caller.
BondNetwork buildBondNetwork(const BondBuildInput& in, BondStats* stats);

}  // namespace seaspring::gencase
