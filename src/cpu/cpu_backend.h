// SeaSpring — MIT licence.
/// \file cpu_backend.h
/// \brief The OpenMP backend: particle arrays in host memory, loops over the shared
///        per-particle functions of src/physics.
#pragma once

#include <cstdint>
#include <vector>

#include "solver/backend.h"

namespace seaspring::cpu {

/// Arrays of the CPU backend (sorted order), and the force driver's entry point.
struct CpuArrays {
    std::vector<std::uint32_t> id;
    std::vector<physics::Double3> pos, pos_pre;
    std::vector<physics::Float4> velrho, velrho_pre, poscell, acear;
    std::vector<physics::Float2> press_ovrho;
    std::vector<std::uint8_t> excl;
    std::vector<float> visc;
    std::vector<physics::SymTensor> tau, gradvel;
    std::vector<std::uint64_t> keys;
    std::vector<std::uint32_t> perm;
    std::vector<std::uint32_t> cell_start_bound, cell_start_fluid;
    /// Per cell: a boundary particle in its search box (physics::dilateCellsAt).
    std::vector<std::uint8_t> bound_near;

    physics::ParticleView view();
};

/// Force evaluation over [0, nbound + nfluid) for one option set (cpu_forces_*.cpp).
physics::DtMaxima cpuComputeForces(const solver::PhysicsChoice& choice, CpuArrays& a,
                                   std::uint32_t nbound, std::uint32_t nfluid,
                                   const physics::FluidConstants& c, const physics::CellGrid& g);

}  // namespace seaspring::cpu
