// SeaSpring — MIT licence.
/// \file cuda_solid.cu
/// \brief Kernels of the VCPM sub-cycle (see cuda_solid.cuh). Every kernel maps particles to
///        threads and calls one function of physics/vcpm.h or physics/solid_coupling.h, as the
///        OpenMP loops of cpu_solid.cpp do; each thread writes only its own particle's entries
///        (sums, bond states of its own slots, position, velocity), so there are no atomics and
///        the result does not depend on the launch configuration.
#include "cuda/cuda_solid.cuh"

#include <algorithm>
#include <cstdlib>

#include "cuda/cuda_check.cuh"
#include "physics/solid_coupling.h"

namespace seaspring::cuda {

namespace {

constexpr int kThreads = 256;
inline unsigned blocksFor(std::uint64_t n) { return unsigned((n + kThreads - 1) / kThreads); }

/// The arguments of physics::clampMotionAt (ClampNodes exposes the positions read-only).
struct ClampMotion {
    const physics::Double3* pos_initial = nullptr;
    const std::int16_t* object = nullptr;
    const physics::RigidMotionGpu* motions = nullptr;
    physics::Double3* pos_start = nullptr;
    physics::Double3* pos_end = nullptr;
};

__global__ void slotKernel(std::uint32_t nbound, const std::uint32_t* id, std::uint32_t first, std::uint32_t n,
                           std::uint32_t* slot) {
    const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i < nbound) physics::solidSlotAt(i, id, first, n, slot);
}

__global__ void toBoundaryKernel(std::uint32_t n, const std::uint32_t* slot, const physics::Double3* pos,
                                 const physics::Double3* vel, const physics::Double3* fluid_force, double dt,
                                 physics::Double3* impulse, double* work, bool ledger, physics::Double3* bpos,
                                 physics::Float4* bvelrho) {
    const std::uint32_t s = blockIdx.x * blockDim.x + threadIdx.x;
    if (s < n) physics::solidToBoundaryAt(s, slot, pos, vel, fluid_force, dt, impulse, work, ledger, bpos, bvelrho);
}

// ---- One kernel per pass (large solids) ---------------------------------------------------

__global__ void clampMotionKernel(std::uint32_t nclamp, ClampMotion cm) {
    const std::uint32_t c = blockIdx.x * blockDim.x + threadIdx.x;
    if (c < nclamp) physics::clampMotionAt(c, cm.pos_initial, cm.object, cm.motions, cm.pos_start, cm.pos_end);
}

__global__ void solidSumsKernel(const physics::Double3* ep, physics::SolidState st, physics::SolidBonds b,
                                physics::ClampNodes cn, double f) {
    const std::uint32_t s = blockIdx.x * blockDim.x + threadIdx.x;
    if (s < b.n) st.sum[s] = physics::solidSumAt(s, ep, st, b, cn, f);
}

__global__ void clampSumsKernel(const physics::Double3* ep, physics::SolidBonds b, physics::ClampNodes cn, double f) {
    const std::uint32_t c = blockIdx.x * blockDim.x + threadIdx.x;
    if (c < cn.n) cn.sum[c] = physics::clampSumAt(c, ep, b, cn, f);
}

__global__ void solidPredictorKernel(physics::SolidState st, physics::SolidBonds b, physics::ClampNodes cn, double f,
                                     double dt, double gx, double gy, double gz) {
    const std::uint32_t s = blockIdx.x * blockDim.x + threadIdx.x;
    if (s < b.n) physics::solidPredictorAt(s, st, b, cn, f, dt, gx, gy, gz);
}

__global__ void solidCorrectorKernel(physics::SolidState st, physics::SolidBonds b, physics::ClampNodes cn, double f,
                                     double dt, double gx, double gy, double gz) {
    const std::uint32_t s = blockIdx.x * blockDim.x + threadIdx.x;
    if (s < b.n) physics::solidCorrectorAt(s, st, b, cn, f, dt, gx, gy, gz);
}

// ---- The whole sub-cycle in one block (small solids) --------------------------------------

/// The two sum passes of an evaluation at `ep`, block-stride. The barrier between them is the
/// one the per-pass path gets from the kernel boundary: clamp sums read bond states that the
/// solid sums of this evaluation may have just set to broken.
__device__ void blockSums(const physics::Double3* ep, const physics::SolidState& st, const physics::SolidBonds& b,
                          const physics::ClampNodes& cn, double f) {
    for (std::uint32_t s = threadIdx.x; s < b.n; s += blockDim.x) st.sum[s] = physics::solidSumAt(s, ep, st, b, cn, f);
    __syncthreads();
    for (std::uint32_t c = threadIdx.x; c < cn.n; c += blockDim.x) cn.sum[c] = physics::clampSumAt(c, ep, b, cn, f);
    __syncthreads();
}

/// Clamp motion, then n sub-steps. The fractions are computed as in CpuSolid::steps (IEEE
/// division and product, no contraction), so they have the host's bits. __syncthreads() also
/// orders the global-memory writes of a pass before the reads of the next within the block.
__global__ void __launch_bounds__(kSolidBlockThreads, 1)
solidStepsBlockKernel(physics::SolidState st, physics::SolidBonds b, physics::ClampNodes cn, ClampMotion cm, int n,
                      double dt, double gx, double gy, double gz) {
    for (std::uint32_t c = threadIdx.x; c < cn.n; c += blockDim.x)
        physics::clampMotionAt(c, cm.pos_initial, cm.object, cm.motions, cm.pos_start, cm.pos_end);
    __syncthreads();
    const double inv_n = 1.0 / double(n);
    for (int m = 0; m < n; ++m) {
        const double f0 = double(m) * inv_n, fh = (double(m) + 0.5) * inv_n;
        blockSums(st.pos, st, b, cn, f0);
        for (std::uint32_t s = threadIdx.x; s < b.n; s += blockDim.x)
            physics::solidPredictorAt(s, st, b, cn, f0, dt, gx, gy, gz);
        __syncthreads();
        blockSums(st.pos_half, st, b, cn, fh);
        for (std::uint32_t s = threadIdx.x; s < b.n; s += blockDim.x)
            physics::solidCorrectorAt(s, st, b, cn, fh, dt, gx, gy, gz);
        __syncthreads();
    }
}

/// Threshold override from the environment (a positive integer), else the default.
std::uint32_t blockPathMax() {
    const char* env = std::getenv("SEASPRING_SOLID_BLOCK_MAX");
    if (env == nullptr || *env == '\0') return kSolidBlockMaxDefault;
    char* end = nullptr;
    const unsigned long v = std::strtoul(env, &end, 10);
    return (*end == '\0') ? std::uint32_t(std::min<unsigned long>(v, 0xffffffffUL)) : kSolidBlockMaxDefault;
}

}  // namespace

void CudaSolid::init(const solver::SolidSetup& s, const physics::StepConstants& step) {
    step_ = step;
    block_max_ = blockPathMax();
    a_.init(s);
}

void CudaSolid::updateSlots(const std::uint32_t* id, std::uint32_t nbound) {
    if (a_.n == 0 || nbound == 0) return;
    slotKernel<<<blocksFor(nbound), kThreads>>>(nbound, id, a_.first, a_.n, a_.slot.data());
    SEASPRING_CUDA_LAUNCH_CHECK();
}

void CudaSolid::steps(double t0, double dt, int n, const std::vector<physics::RigidMotionGpu>& motions) {
    if (a_.n == 0 || n <= 0) return;
    a_.t0 = t0;
    a_.span = dt * double(n);
    ClampMotion cm;
    cm.pos_initial = a_.clamp_pos_initial.data();
    cm.object = a_.clamp_object.data();
    cm.pos_start = a_.clamp_start.data();
    cm.pos_end = a_.clamp_end.data();
    if (a_.nclamp > 0 && !motions.empty()) {
        // Synchronous, as in applyMotion: the caller's vector is a temporary, and the time step
        // drains the queue at its dt readback anyway, so waiting here costs little.
        motions_.resize(motions.size());
        SEASPRING_CUDA_CHECK(cudaMemcpy(motions_.data(), motions.data(),
                                        motions.size() * sizeof(physics::RigidMotionGpu), cudaMemcpyHostToDevice));
        cm.motions = motions_.data();
    }
    const double gx = step_.gx, gy = step_.gy, gz = step_.gz;
    if (std::uint64_t(a_.n) + a_.nclamp <= block_max_) {
        // Only as many warps as the larger pass needs: the barriers then wait for fewer warps.
        const std::uint32_t widest = std::max(a_.n, a_.nclamp);
        const unsigned threads = unsigned(std::min<std::uint32_t>(kSolidBlockThreads, (widest + 31u) / 32u * 32u));
        solidStepsBlockKernel<<<1, threads>>>(a_.state(), a_.bonds(), a_.clamps(), cm, n, dt, gx, gy, gz);
        SEASPRING_CUDA_LAUNCH_CHECK();
        return;
    }
    if (a_.nclamp > 0) {
        clampMotionKernel<<<blocksFor(a_.nclamp), kThreads>>>(a_.nclamp, cm);
        SEASPRING_CUDA_LAUNCH_CHECK();
    }
    stepsPerPass(dt, n);
}

/// The per-pass path: the kernel boundaries are the barriers of CpuSolid::steps' `omp for`s.
void CudaSolid::stepsPerPass(double dt, int n) {
    const physics::SolidState st = a_.state();
    const physics::SolidBonds b = a_.bonds();
    const physics::ClampNodes cn = a_.clamps();
    const double gx = step_.gx, gy = step_.gy, gz = step_.gz;
    const unsigned sb = blocksFor(a_.n), cb = blocksFor(a_.nclamp);
    auto sums = [&](const physics::Double3* ep, double f) {
        solidSumsKernel<<<sb, kThreads>>>(ep, st, b, cn, f);
        SEASPRING_CUDA_LAUNCH_CHECK();
        if (a_.nclamp == 0) return;
        clampSumsKernel<<<cb, kThreads>>>(ep, b, cn, f);
        SEASPRING_CUDA_LAUNCH_CHECK();
    };
    const double inv_n = 1.0 / double(n);
    for (int m = 0; m < n; ++m) {
        const double f0 = double(m) * inv_n, fh = (double(m) + 0.5) * inv_n;
        sums(st.pos, f0);
        solidPredictorKernel<<<sb, kThreads>>>(st, b, cn, f0, dt, gx, gy, gz);
        SEASPRING_CUDA_LAUNCH_CHECK();
        sums(st.pos_half, fh);
        solidCorrectorKernel<<<sb, kThreads>>>(st, b, cn, fh, dt, gx, gy, gz);
        SEASPRING_CUDA_LAUNCH_CHECK();
    }
}

void CudaSolid::toBoundary(double dt, bool ledger, physics::Double3* bpos, physics::Float4* bvelrho) {
    if (a_.n == 0) return;
    toBoundaryKernel<<<blocksFor(a_.n), kThreads>>>(a_.n, a_.slot.data(), a_.pos.data(), a_.vel.data(),
                                                   a_.fluid_force.data(), dt, a_.impulse.data(), a_.work.data(),
                                                   ledger, bpos, bvelrho);
    SEASPRING_CUDA_LAUNCH_CHECK();
}

}  // namespace seaspring::cuda
