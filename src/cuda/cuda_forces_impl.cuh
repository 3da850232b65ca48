// SeaSpring — MIT licence.
/// \file cuda_forces_impl.cuh
/// \brief The CUDA force driver for one option set: one thread per particle calling the
///        shared per-particle interaction, the SPS stress, and a two-stage max reduction of
///        the dt maxima (exact, so deterministic); and the hydrodynamic force on VCPM solid
///        particles (one thread per solid particle, physics/solid_coupling.h).
#pragma once

#include "cuda/cuda_arrays.cuh"
#include "cuda/cuda_check.cuh"
#include "physics/fluid_interaction.h"
#include "physics/solid_coupling.h"

namespace seaspring::cuda {

constexpr int kForceThreads = 128;

__global__ void pressureKernel(std::uint32_t np, physics::ParticleView v, physics::FluidConstants c);

template <class Opt>
__global__ void __launch_bounds__(kForceThreads)
fluidForcesKernel(std::uint32_t nbound, std::uint32_t np, physics::InteractionInputs in,
                  physics::FluidConstants c, physics::CellGrid g, physics::ParticleView v) {
    const std::uint32_t i = nbound + blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= np) return;
    const physics::FluidAccum acc = physics::fluidParticleForces<Opt>(i, in, c, g);
    v.acear[i] = physics::Float4{acc.ax, acc.ay, acc.az, acc.ar};
    v.visc[i] = acc.visc;
    if (Opt::sps) v.gradvel[i] = acc.gradvel;
}

template <class Opt>
__global__ void __launch_bounds__(kForceThreads)
boundForcesKernel(std::uint32_t nbound, physics::InteractionInputs in, physics::FluidConstants c,
                  physics::CellGrid g, physics::ParticleView v) {
    const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= nbound) return;
    float ar, visc;
    physics::boundParticleForces<Opt>(i, in, c, g, ar, visc);
    v.acear[i] = physics::Float4{0.f, 0.f, 0.f, ar};
    v.visc[i] = visc;
}

__global__ void spsTauKernel(std::uint32_t nbound, std::uint32_t np, physics::ParticleView v, float smag,
                             float blin);
__global__ void dtMaximaBlocksKernel(std::uint32_t nbound, std::uint32_t np, physics::ParticleView v, bool all_particles,
                                     physics::DtMaxima* out);
__global__ void dtMaximaFinalKernel(std::uint32_t nblocks, const physics::DtMaxima* in, physics::DtMaxima* out);

/// Everything after the pair loops (shared by all option sets; cuda_backend.cu).
physics::DtMaxima finishForces(bool sps, DeviceArrays& a, std::uint32_t nbound, std::uint32_t np,
                               const physics::FluidConstants& c);

/// What the pair loops read (device pointers); `tau` only with SPS.
inline physics::InteractionInputs interactionInputs(const DeviceArrays& a, bool sps) {
    physics::InteractionInputs in;
    in.poscell = a.v.poscell;
    in.velrho = a.v.velrho;
    in.cell_start_bound = a.cell_start_bound;
    in.cell_start_fluid = a.cell_start_fluid;
    in.tau = sps ? a.v.tau : nullptr;
    in.press_ovrho = a.v.press_ovrho;
    in.bound_near = a.bound_near;
    return in;
}

template <class Opt>
__global__ void __launch_bounds__(kForceThreads)
hydroForcesKernel(std::uint32_t n, const std::uint32_t* slot, physics::InteractionInputs in,
                  physics::FluidConstants c, physics::CellGrid g, physics::Double3* out) {
    const std::uint32_t s = blockIdx.x * blockDim.x + threadIdx.x;
    if (s < n) out[s] = physics::hydroForceOnBoundary<Opt>(slot ? slot[s] : s, in, c, g);
}

/// The hydrodynamic force on boundary particles: out[s] for sorted index slot[s] (the solid
/// particles), or for sorted index s when `slot` is null (the whole boundary block [0, n)),
/// as cpu::cpuHydroForcesFor.
template <class Opt>
void cudaHydroForcesFor(DeviceArrays& a, const std::uint32_t* slot, std::uint32_t n, physics::Double3* out,
                        const physics::FluidConstants& c, const physics::CellGrid& g) {
    if (n == 0) return;
    hydroForcesKernel<Opt><<<(n + kForceThreads - 1) / kForceThreads, kForceThreads>>>(
        n, slot, interactionInputs(a, Opt::sps), c, g, out);
    SEASPRING_CUDA_LAUNCH_CHECK();
}

template <class Opt>
physics::DtMaxima cudaForcesFor(DeviceArrays& a, std::uint32_t nbound, std::uint32_t nfluid,
                                const physics::FluidConstants& c, const physics::CellGrid& g) {
    const physics::InteractionInputs in = interactionInputs(a, Opt::sps);
    const std::uint32_t np = nbound + nfluid;
    if (np > 0) {
        pressureKernel<<<(np + 255) / 256, 256>>>(np, a.v, c);
        SEASPRING_CUDA_LAUNCH_CHECK();
    }
    if (nfluid > 0) {
        fluidForcesKernel<Opt><<<(nfluid + kForceThreads - 1) / kForceThreads, kForceThreads>>>(
            nbound, np, in, c, g, a.v);
        SEASPRING_CUDA_LAUNCH_CHECK();
    }
    if (nbound > 0) {
        boundForcesKernel<Opt><<<(nbound + kForceThreads - 1) / kForceThreads, kForceThreads>>>(
            nbound, in, c, g, a.v);
        SEASPRING_CUDA_LAUNCH_CHECK();
    }
    return finishForces(Opt::sps, a, nbound, np, c);
}

}  // namespace seaspring::cuda
