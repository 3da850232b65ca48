// SeaSpring — MIT licence.
/// \file cuda_solid.cuh
/// \brief CUDA driver of the VCPM solids, the mirror of cpu::CpuSolid: the same arrays
///        (solid-index order, slot-major bonds) in device memory, and kernels that call the
///        same functions of physics/vcpm.h and physics/solid_coupling.h, pass by pass, in the
///        same order, so both backends give the same bits.
///
/// A sub-step is six passes (sums at r^m, clamp sums, predictor, sums at r^{m+1/2}, clamp sums,
/// corrector), each needing the previous one complete. A solid sub-cycle may have tens of
/// sub-steps per fluid step, so:
///  - small solids (nsolid + nclamp <= kSolidBlockMaxDefault) run the whole sub-cycle, clamp
///    motion included, in ONE single-block kernel with __syncthreads() between the passes: one
///    launch per steps() call instead of 1 + 6 n;
///  - large solids launch one grid-wide kernel per pass (clamp motion, then 4 or 6 per sub-step),
///    to use every SM.
/// The two paths compute the same per-particle calls in the same pass order, so they agree bit
/// for bit (and with the CPU); `SEASPRING_SOLID_BLOCK_MAX=N` in the environment moves the
/// threshold, to compare or time the two paths on one case.
#pragma once

#include <cstdint>
#include <vector>

#include "cuda/device_buffer.cuh"
#include "physics/particle_updates.h"
#include "physics/time_integration.h"
#include "physics/vcpm.h"
#include "solver/backend.h"
#include "solver/solid_arrays.h"

namespace seaspring::cuda {

/// Threads of the single-block sub-cycle kernel (block-stride loops over the particles).
constexpr int kSolidBlockThreads = 1024;

/// Default largest nsolid + nclamp run by the single-block kernel. Measured on an H200
/// (tools/device_solid_paths.sh, same hashes on both paths): the Antoci gate (395 solid
/// particles, about 3 sub-steps per fluid step) runs 3,000 coupled steps in 2.68 s with the
/// block kernel against 3.14 s per pass; a 1,250-particle cantilever, 20,000 sub-steps in one
/// call, 1.45 s against 1.39 s (even); at 10,000 particles 9.0 s against 1.50 s and at 48,000
/// 4.7 s against 0.14 s for 2,000 sub-steps (one SM cannot keep up). The crossover lies
/// between about 1,300 and 2,000 particles; 2,048 keeps every case within a few percent of the
/// faster path. Small solids stay latency-bound either way (about 70 us per sub-step: each
/// thread walks its 18 bonds one dependent load after another).
constexpr std::uint32_t kSolidBlockMaxDefault = 2048;

class CudaSolid {
public:
    void init(const solver::SolidSetup& s, const physics::StepConstants& step);
    bool empty() const { return a_.n == 0; }
    std::uint32_t size() const { return a_.n; }

    /// slot[s] = sorted index of solid particle s, from the sorted ids (device) of the boundary
    /// block [0, nbound).
    void updateSlots(const std::uint32_t* id, std::uint32_t nbound);
    const std::uint32_t* slots() const { return a_.slot.data(); }
    physics::Double3* fluidForce() { return a_.fluid_force.data(); }

    /// n sub-steps of dt from time t0 (clamp nodes moved by `motions` over the whole interval).
    void steps(double t0, double dt, int n, const std::vector<physics::RigidMotionGpu>& motions);
    /// Positions and velocities into the boundary block (sorted device arrays) after a
    /// sub-cycle of length dt; `ledger`: accumulate the impulse and work of the hydrodynamic
    /// force, as CpuSolid::toBoundary.
    void toBoundary(double dt, bool ledger, physics::Double3* bpos, physics::Float4* bvelrho);
    /// Device-to-device snapshot of positions, velocities and bond states, and back.
    void save() { a_.save(); }
    void restore() { a_.restore(); }
    /// solid_vel, solid_force, bond_broken, solid_impulse, solid_work (the CPU's layouts).
    void download(solver::HostState& out) const { a_.download(out); }

private:
    void stepsPerPass(double dt, int n);

    std::uint32_t block_max_ = kSolidBlockMaxDefault;
    physics::StepConstants step_;
    solver::SolidArrays<DeviceBuffer> a_;
    DeviceBuffer<physics::RigidMotionGpu> motions_;  ///< the poses of the current steps() call
};

}  // namespace seaspring::cuda
