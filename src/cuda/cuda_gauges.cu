// SeaSpring — MIT licence.
/// \file cuda_gauges.cu
/// \brief CUDA driver of the gauge measurements (see cuda_gauges.cuh).
#include "cuda/cuda_gauges.cuh"

#include <vector>

#include "physics/sph_kernels.h"

namespace seaspring::cuda {

namespace {

constexpr int kThreads = 128;
inline unsigned blocksFor(std::uint64_t n) { return unsigned((n + kThreads - 1) / kThreads); }

template <class Kernel, int kDim>
__global__ void samplesKernel(std::uint32_t n, const physics::Float4* pts, const std::uint32_t* cs,
                              const physics::Float4* poscell, const physics::Float4* velrho,
                              physics::FluidConstants c, physics::CellGrid g, physics::GaugeSample* out) {
    const std::uint32_t k = blockIdx.x * blockDim.x + threadIdx.x;
    if (k < n) out[k] = physics::gaugeSampleAt<Kernel, kDim>(pts[k], cs, poscell, velrho, c, g);
}

template <int kDim>
__global__ void maxzKernel(std::uint32_t n, const physics::MaxzRow* rows, const std::uint32_t* cs,
                           const physics::Double3* pos, double* out) {
    const std::uint32_t k = blockIdx.x * blockDim.x + threadIdx.x;
    if (k < n) out[k] = physics::maxzRowAt<kDim>(rows[k], cs, pos);
}

__global__ void positionsKernel(std::uint32_t nbound, const std::uint32_t* id, const physics::Double3* pos,
                                const std::uint32_t* slot_of_id, physics::Double3* out) {
    const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i < nbound) physics::gaugePositionAt(i, id, pos, slot_of_id, out);
}

template <class Kernel, int kDim>
void launch(std::uint32_t np, std::uint32_t nr, const DeviceBuffer<physics::Float4>& pts,
            const DeviceBuffer<physics::MaxzRow>& rows, const DeviceArrays& a, const physics::FluidConstants& c,
            const physics::CellGrid& g, DeviceBuffer<physics::GaugeSample>& samples, DeviceBuffer<double>& maxz) {
    if (np > 0) {
        samplesKernel<Kernel, kDim><<<blocksFor(np), kThreads>>>(np, pts.data(), a.cell_start_fluid, a.v.poscell,
                                                                 a.v.velrho, c, g, samples.data());
        SEASPRING_CUDA_LAUNCH_CHECK();
    }
    if (nr > 0) {
        maxzKernel<kDim><<<blocksFor(nr), kThreads>>>(nr, rows.data(), a.cell_start_fluid, a.v.pos, maxz.data());
        SEASPRING_CUDA_LAUNCH_CHECK();
    }
}

}  // namespace

void CudaGauges::set(const solver::GaugeQueries& q, std::uint32_t nbound) {
    points_.upload(q.points);
    rows_.upload(q.maxz_rows);
    samples_.resize(q.points.size());
    maxz_.resize(q.maxz_rows.size());
    nids_ = q.ids.size();
    positions_.resize(nids_);
    if (nids_ > 0) slot_of_id_.upload(solver::gaugeSlotsOfIds(q.ids, nbound));
}

void CudaGauges::evaluate(const solver::PhysicsChoice& choice, const DeviceArrays& a, std::uint32_t nbound,
                          const physics::FluidConstants& c, const physics::CellGrid& g,
                          solver::GaugeResults& out) {
    const std::uint32_t np = std::uint32_t(points_.size()), nr = std::uint32_t(rows_.size());
    const bool wendland = choice.kernel == physics::KernelType::Wendland;
    if (choice.dim == 3) {
        if (wendland) launch<physics::WendlandKernel, 3>(np, nr, points_, rows_, a, c, g, samples_, maxz_);
        else launch<physics::CubicKernel, 3>(np, nr, points_, rows_, a, c, g, samples_, maxz_);
    } else {
        if (wendland) launch<physics::WendlandKernel, 2>(np, nr, points_, rows_, a, c, g, samples_, maxz_);
        else launch<physics::CubicKernel, 2>(np, nr, points_, rows_, a, c, g, samples_, maxz_);
    }
    if (nids_ > 0 && nbound > 0) {
        positionsKernel<<<blocksFor(nbound), kThreads>>>(nbound, a.v.id, a.v.pos, slot_of_id_.data(), positions_.data());
        SEASPRING_CUDA_LAUNCH_CHECK();
    }
    samples_.download(out.samples);
    maxz_.download(out.maxz);
    positions_.download(out.positions);
}

}  // namespace seaspring::cuda
