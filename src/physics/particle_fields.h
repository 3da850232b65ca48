// SeaSpring — MIT licence.
/// \file particle_fields.h
/// \brief The per-particle fields of the solver: ONE table. Everything that handles particles
///        field by field derives from it: the arrays of both backends (solver/particle_store.h),
///        the pointer view the physics functions read (ParticleView, physics/particle_updates.h),
///        the gather after every sort (solver/engine.h, GatherPass), the copy back to the host in id
///        order and the state hash (solver/state_hash.cpp), and what a restart file holds.
///
/// Adding a field is one row: X(name, type, when it exists, flags).
///  - `need`: the runs that allocate it (Always; Sps: only with laminar+SPS viscosity). A field that is not allocated is a null pointer in
///    ParticleView.
///  - flags (FieldFlag):
///      kSorted     reordered by every divide (its value belongs to the particle);
///      kSortedPre  reordered only while the step-start state is still to be read (between the
///                  symplectic predictor and corrector; always with Verlet, whose state at n-1
///                  it holds); the next predictor overwrites it otherwise;
///      kHashed     enters the state hash, in table order, particle by particle (id order);
///      kHost       copied back to the host (HostState, id order) for outputs and reports;
///      kCheckpoint part of the state a restart needs (Backend::saveState, in sorted order);
///      kHalo       read across a subdomain edge by a neighbour's pair loop (multi-GPU);
///      kForceEval  a force evaluation's result: meaningful from the force evaluation until
///                  the next divide, whose sort keeps its keys, permutation and gather scratch
///                  in these fields' memory (solver/engine.h, SortMemory): no second copy of
///                  the particles for the sort.
///    Fields without kSorted are rebuilt before they are read (PosCell by every divide, the
///    force-evaluation fields by every force evaluation). PosCell is still checkpointed: between
///    two sorts it holds the cell each particle was sorted into (the skin, cell_grid.h), which a
///    restart must keep to continue with the same neighbour order.
#pragma once

#include <cstdint>

#include "physics/sph_types.h"

namespace seaspring::physics {

enum FieldFlag : unsigned {
    kSorted = 1u,
    kSortedPre = 2u,
    kHashed = 4u,
    kHost = 8u,
    kCheckpoint = 16u,
    kHalo = 32u,
    kForceEval = 64u,
};

/// The runs that allocate a field.
enum class FieldNeed { Always, Sps };

// clang-format off
#define SEASPRING_PARTICLE_FIELDS(X)                                                                        \
    X(id,          std::uint32_t,            Always,     kSorted | kCheckpoint | kHalo)                     \
    X(pos,         ::seaspring::physics::Double3, Always, kSorted | kHashed | kHost | kCheckpoint | kHalo) \
    X(velrho,      ::seaspring::physics::Float4,  Always, kSorted | kHashed | kHost | kCheckpoint | kHalo) \
    X(excl,        std::uint8_t,             Always,     kSorted | kHashed | kHost | kCheckpoint)          \
    X(poscell,     ::seaspring::physics::Float4,  Always, kCheckpoint | kHalo)                              \
    X(press_ovrho, ::seaspring::physics::Float2,  Always, kForceEval | kHalo)                               \
    X(velrho_pre,  ::seaspring::physics::Float4,  Always, kSortedPre | kCheckpoint)                         \
    X(acear,       ::seaspring::physics::Float4,  Always, kForceEval)                                       \
    X(visc,        float,                    Always,     kForceEval)                                        \
    X(tau,         ::seaspring::physics::SymTensor, Sps,  kSorted | kCheckpoint | kHalo)                    \
    X(gradvel,     ::seaspring::physics::SymTensor, Sps,  kForceEval)
// clang-format on
//  id          particle id (position in the case's id order)
//  pos         position [m] (double)
//  velrho      velocity [m/s] and density [kg/m^3]
//  excl        ExclusionReason (0 active)
//  poscell     cell-relative float position and packed cell (cell_grid.h)
//  press_ovrho force evaluation: (pressure, 1/rho)
//  velrho_pre  symplectic: state at the start of the step; Verlet: state at n-1
//  acear       force evaluation: (ax, ay, az, d rho/dt)
//  visc        force evaluation: viscous dt measure
//  tau         SPS: stress/rho (persistent between evaluations)
//  gradvel     SPS: velocity gradient of the last evaluation
// (The symplectic step-start position is not kept: the corrector moves on from the
// predictor's position, time_integration.h.)

/// Whether a run allocates a field with `need`.
inline bool fieldNeeded(FieldNeed need, bool sps) { return need == FieldNeed::Always || (need == FieldNeed::Sps && sps); }

}  // namespace seaspring::physics
