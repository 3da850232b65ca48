// SeaSpring — MIT licence.
/// \file particle_set.h
/// \brief Host-side particle arrays and the bond network, as produced by gencase
///        and read by the solver.
///
/// Particle order (and so the id) is: fixed boundary, moving boundary, VCPM solid,
/// fluid; inside each block by MK, then by lattice position (x fastest, then y, z).
#pragma once

#include <cstdint>
#include <vector>

#include "core/vec3.h"

namespace seaspring {

/// Particle roles. The numeric values are stored in files: never renumber.
enum class ParticleType : std::uint8_t {
    Fixed = 0,   ///< fixed boundary (DBC)
    Moving = 1,  ///< boundary with prescribed motion
    Solid = 2,   ///< VCPM lattice-solid particle (boundary MK declared in <vcpmsolids>)
    Fluid = 3,   ///< fluid
};

const char* particleTypeName(ParticleType t);

/// Structure of arrays, one entry per particle.
struct ParticleSet {
    std::vector<std::uint32_t> id;
    std::vector<ParticleType> type;
    std::vector<std::uint16_t> mk;  ///< global MK (fluid: mkfluid+1; boundary: mkbound+fluidcount+1)
    std::vector<Vec3d> pos;         ///< position [m]
    std::vector<Vec3f> vel;         ///< velocity [m/s]
    std::vector<float> rhop;        ///< density [kg/m^3]
    std::vector<float> mass;        ///< mass [kg]

    /// mDBC ghost vector of each boundary particle [m]: the vector from the particle to
    /// its ghost node, i.e. 2 x (nearest point of the boundary interface - position).
    /// Either empty (the case has no normals) or exactly one entry per non-fluid
    /// particle (ids 0..nbound-1, which come first); zero where a particle has no
    /// interface within reach. Not touched by reserve()/resize(): those size the
    /// per-particle arrays only; whoever fills `normal` sizes it to the boundary count.
    std::vector<Vec3f> normal;

    std::size_t size() const { return id.size(); }
    /// Number of non-fluid particles (fixed, moving, solid), counted from `type`.
    std::size_t boundaryCount() const;
    void reserve(std::size_t n);
    void resize(std::size_t n);
};

/// Bond kinds (bit flags, stored in files).
enum BondKind : std::uint8_t {
    BondFirst = 0,        ///< first neighbour, rest length dp
    BondSecond = 1,       ///< second neighbour (face diagonal), rest length sqrt(2)*dp
    BondClampFlag = 2,    ///< the other end is a clamp (boundary) particle
};

/// Bonds of the VCPM solid particles in CSR form. Row r belongs to solid particle
/// `first_solid + r` (solid particles are contiguous). Both ends of a solid-solid bond
/// store it; a clamp bond is stored on the solid side only. Slot order inside a row is
/// the fixed lattice-offset order (see gencase/vcpm_bonds.h), so it is deterministic.
struct BondNetwork {
    std::uint32_t first_solid = 0;        ///< id of the first solid particle
    std::vector<std::uint32_t> offset;    ///< size n_solid+1
    std::vector<std::uint32_t> neighbour; ///< particle id of the other end
    std::vector<double> rest_length;      ///< [m]
    std::vector<std::uint8_t> kind;       ///< BondKind flags

    std::size_t solidCount() const { return offset.empty() ? 0 : offset.size() - 1; }
    std::size_t bondSlots() const { return neighbour.size(); }
};

}  // namespace seaspring
