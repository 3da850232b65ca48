// SeaSpring — MIT licence.
/// \file cuda_arrays.cuh
/// \brief Device arrays of the CUDA backend (sorted order) and the force driver entry point.
#pragma once

#include <cstdint>

#include "physics/particle_updates.h"
#include "solver/backend.h"

namespace seaspring::cuda {

/// Raw device pointers (owned by the backend).
struct DeviceArrays {
    physics::ParticleView v;                  ///< per-particle arrays
    std::uint32_t* cell_start_bound = nullptr;
    std::uint32_t* cell_start_fluid = nullptr;
    std::uint8_t* bound_near = nullptr;        ///< per cell: boundary "near" flags (physics::dilateCellsAt)
    physics::DtMaxima* block_maxima = nullptr; ///< one per block of the reduction
    physics::DtMaxima* maxima = nullptr;       ///< the final maxima (device)
    std::uint32_t reduce_blocks = 0;
};

/// Force evaluation on the device for one option set; returns the dt maxima (synchronises).
physics::DtMaxima cudaComputeForces(const solver::PhysicsChoice& choice, DeviceArrays& a,
                                    std::uint32_t nbound, std::uint32_t nfluid,
                                    const physics::FluidConstants& c, const physics::CellGrid& g);

constexpr int kReduceThreads = 256;

}  // namespace seaspring::cuda
