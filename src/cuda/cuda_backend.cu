// SeaSpring — MIT licence.
/// \file cuda_backend.cu
/// \brief CUDA backend: device arrays, radix sort by (cell, id), gathers, cell ranges, motion,
///        integration (one thread per particle over the shared per-particle functions), the dt
///        reduction, and the wiring of the VCPM solids (cuda_solid.cuh) as in the CPU backend.
#include <cub/device/device_radix_sort.cuh>

#include <string>
#include <vector>

#include "cuda/cuda_arrays.cuh"
#include "cuda/cuda_forces_impl.cuh"
#include "cuda/cuda_gauges.cuh"
#include "cuda/cuda_solid.cuh"
#include "cuda/device_buffer.cuh"

namespace seaspring::cuda {

physics::DtMaxima cudaForces_wendland(const solver::PhysicsChoice&, DeviceArrays&, std::uint32_t,
                                      std::uint32_t, const physics::FluidConstants&,
                                      const physics::CellGrid&);
physics::DtMaxima cudaForces_cubic(const solver::PhysicsChoice&, DeviceArrays&, std::uint32_t,
                                   std::uint32_t, const physics::FluidConstants&,
                                   const physics::CellGrid&);

void cudaHydroForces_wendland(const solver::PhysicsChoice&, DeviceArrays&, const std::uint32_t*, std::uint32_t,
                             physics::Double3*, const physics::FluidConstants&, const physics::CellGrid&);
void cudaHydroForces_cubic(const solver::PhysicsChoice&, DeviceArrays&, const std::uint32_t*, std::uint32_t,
                          physics::Double3*, const physics::FluidConstants&, const physics::CellGrid&);

physics::DtMaxima cudaComputeForces(const solver::PhysicsChoice& choice, DeviceArrays& a,
                                    std::uint32_t nbound, std::uint32_t nfluid,
                                    const physics::FluidConstants& c, const physics::CellGrid& g) {
    if (choice.kernel == physics::KernelType::Wendland)
        return cudaForces_wendland(choice, a, nbound, nfluid, c, g);
    return cudaForces_cubic(choice, a, nbound, nfluid, c, g);
}

namespace {

constexpr int kThreads = 256;
inline unsigned blocksFor(std::uint64_t n) { return unsigned((n + kThreads - 1) / kThreads); }

__global__ void sortKeysKernel(std::uint32_t b, std::uint32_t e, physics::ParticleView v, physics::CellGrid g) {
    const std::uint32_t i = b + blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= e) return;
    v.keys[i] = physics::sortKeyAt(i, v, g);
    v.perm[i] = i;
}

template <typename T>
__global__ void gatherKernel(std::uint32_t b, std::uint32_t e, const std::uint32_t* perm, const T* src, T* dst) {
    const std::uint32_t i = b + blockIdx.x * blockDim.x + threadIdx.x;
    if (i < e) dst[i] = src[perm[i]];
}

__global__ void cellStartOuterKernel(std::uint32_t nc, std::uint32_t b, std::uint32_t e, const std::uint64_t* keys,
                                     std::uint32_t* cs) {
    const std::uint32_t c = blockIdx.x * blockDim.x + threadIdx.x;
    if (c < nc) physics::cellStartOuterAt(c, b, e, keys, cs);
}
__global__ void cellStartFillKernel(std::uint32_t b, std::uint32_t e, const std::uint64_t* keys, std::uint32_t* cs) {
    const std::uint32_t k = b + blockIdx.x * blockDim.x + threadIdx.x;
    if (k < e) physics::cellStartFillAt(k, b, keys, cs);
}
/// First index in [b, e) whose key is an excluded key (binary search, one thread).
__global__ void activeEndKernel(std::uint32_t b, std::uint32_t e, const std::uint64_t* keys, std::uint32_t* out) {
    std::uint32_t lo = b, hi = e;
    const std::uint64_t excluded_from = physics::kExcludedCell << 32;
    while (lo < hi) {
        const std::uint32_t mid = lo + (hi - lo) / 2;
        if (keys[mid] < excluded_from) lo = mid + 1;
        else hi = mid;
    }
    *out = lo;
}
__global__ void cellOccupiedKernel(std::uint32_t nc, const std::uint32_t* cs, std::uint8_t* occ) {
    const std::uint32_t c = blockIdx.x * blockDim.x + threadIdx.x;
    if (c < nc) physics::cellOccupiedAt(c, cs, occ);
}
__global__ void dilateCellsKernel(std::uint32_t nc, int axis, physics::CellGrid g, const std::uint8_t* in,
                                  std::uint8_t* out) {
    const std::uint32_t c = blockIdx.x * blockDim.x + threadIdx.x;
    if (c < nc) physics::dilateCellsAt(c, axis, g, in, out);
}
__global__ void posCellKernel(std::uint32_t n, physics::ParticleView v, physics::CellGrid g) {
    const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i < n) physics::posCellAt(i, v, g);
}
__global__ void motionKernel(std::uint32_t nbound, physics::ParticleView v, std::uint32_t first, std::uint32_t nmoving,
                             const physics::Double3* pos0, const std::uint16_t* object,
                             const physics::RigidMotionGpu* motions) {
    const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i < nbound) physics::motionAt(i, v, first, nmoving, pos0, object, motions);
}
__global__ void predictorKernel(std::uint32_t n, std::uint32_t nbound, physics::ParticleView v, double dt,
                                physics::StepConstants s) {
    const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i < n) physics::symplecticPredictorAt(i, nbound, v, dt, s);
}
__global__ void correctorKernel(std::uint32_t n, std::uint32_t nbound, physics::ParticleView v, double dt,
                                physics::StepConstants s) {
    const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i < n) physics::symplecticCorrectorAt(i, nbound, v, dt, s);
}
__global__ void verletKernel(std::uint32_t n, std::uint32_t nbound, physics::ParticleView v, double dt, bool euler,
                             physics::StepConstants s) {
    const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i < n) physics::verletAt(i, nbound, v, dt, euler, s);
}

}  // namespace

__global__ void pressureKernel(std::uint32_t np, physics::ParticleView v, physics::FluidConstants c) {
    const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i < np) physics::pressureAt(i, v, c);
}

__global__ void spsTauKernel(std::uint32_t nbound, std::uint32_t np, physics::ParticleView v, float smag, float blin) {
    const std::uint32_t i = nbound + blockIdx.x * blockDim.x + threadIdx.x;
    if (i < np) physics::spsTauAt(i, v, smag, blin);
}

__global__ void dtMaximaBlocksKernel(std::uint32_t nbound, std::uint32_t np, physics::ParticleView v,
                                     bool all_particles, physics::DtMaxima* out) {
    __shared__ physics::DtMaxima sh[kReduceThreads];
    physics::DtMaxima m;
    for (std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x; i < np; i += gridDim.x * blockDim.x)
        m = physics::combineDtMaxima(m, physics::dtMaximaAt(i, nbound, v, all_particles));
    sh[threadIdx.x] = m;
    __syncthreads();
    for (unsigned s = blockDim.x / 2; s > 0; s >>= 1) {
        if (threadIdx.x < s) sh[threadIdx.x] = physics::combineDtMaxima(sh[threadIdx.x], sh[threadIdx.x + s]);
        __syncthreads();
    }
    if (threadIdx.x == 0) out[blockIdx.x] = sh[0];
}

__global__ void dtMaximaFinalKernel(std::uint32_t nblocks, const physics::DtMaxima* in, physics::DtMaxima* out) {
    __shared__ physics::DtMaxima sh[kReduceThreads];
    physics::DtMaxima m;
    for (std::uint32_t i = threadIdx.x; i < nblocks; i += blockDim.x) m = physics::combineDtMaxima(m, in[i]);
    sh[threadIdx.x] = m;
    __syncthreads();
    for (unsigned s = blockDim.x / 2; s > 0; s >>= 1) {
        if (threadIdx.x < s) sh[threadIdx.x] = physics::combineDtMaxima(sh[threadIdx.x], sh[threadIdx.x + s]);
        __syncthreads();
    }
    if (threadIdx.x == 0) *out = sh[0];
}

physics::DtMaxima finishForces(bool sps, DeviceArrays& a, std::uint32_t nbound, std::uint32_t np,
                               const physics::FluidConstants& c) {
    if (sps && np > nbound) {
        spsTauKernel<<<blocksFor(np - nbound), kThreads>>>(nbound, np, a.v, c.sps_smag, c.sps_blin);
        SEASPRING_CUDA_LAUNCH_CHECK();
    }
    dtMaximaBlocksKernel<<<a.reduce_blocks, kReduceThreads>>>(nbound, np, a.v, c.dt_all_particles != 0,
                                                              a.block_maxima);
    SEASPRING_CUDA_LAUNCH_CHECK();
    dtMaximaFinalKernel<<<1, kReduceThreads>>>(a.reduce_blocks, a.block_maxima, a.maxima);
    SEASPRING_CUDA_LAUNCH_CHECK();
    physics::DtMaxima m;
    SEASPRING_CUDA_CHECK(cudaMemcpy(&m, a.maxima, sizeof m, cudaMemcpyDeviceToHost));
    return m;
}

namespace {

class CudaBackend final : public solver::Backend {
public:
    explicit CudaBackend(int device) : device_(device) {
        SEASPRING_CUDA_CHECK(cudaSetDevice(device));
        cudaDeviceProp prop{};
        SEASPRING_CUDA_CHECK(cudaGetDeviceProperties(&prop, device));
        name_ = prop.name;
        sms_ = prop.multiProcessorCount;
    }
    std::string name() const override { return "gpu"; }
    std::string deviceName() const override { return name_; }
    int threads() const override { return 1; }

    void init(const solver::BackendSetup& s) override {
        setup_ = s;
        nbound_ = s.nbound;
        nfluid_ = s.nfluid;
        const std::size_t np = std::size_t(s.nbound) + s.nfluid;
        np_ = np;
        std::vector<std::uint32_t> ids(np);
        for (std::size_t i = 0; i < np; ++i) ids[i] = std::uint32_t(i);
        id_.upload(ids);
        pos_.upload(s.pos);
        velrho_.upload(s.velrho);
        excl_.upload(std::vector<std::uint8_t>(np, physics::kActive));
        poscell_.resize(np);
        press_ovrho_.resize(np);
        pos_pre_.upload(s.pos);
        velrho_pre_.upload(s.velrho);
        acear_.upload(std::vector<physics::Float4>(np, physics::Float4{0, 0, 0, 0}));
        visc_.upload(std::vector<float>(np, 0.f));
        if (s.physics.visco == physics::Viscosity::LaminarSps) {
            tau_.upload(std::vector<physics::SymTensor>(np, physics::SymTensor{0, 0, 0, 0, 0, 0}));
            gradvel_.upload(std::vector<physics::SymTensor>(np, physics::SymTensor{0, 0, 0, 0, 0, 0}));
            scratch_t_.resize(np);
        }
        keys_.resize(np);
        keys_alt_.resize(np);
        perm_.resize(np);
        perm_alt_.resize(np);
        scratch_u32_.resize(np);
        scratch_d3_.resize(np);
        scratch_f4_.resize(np);
        scratch_u8_.resize(np);
        const std::size_t nc = std::size_t(s.grid.cellCount()) + 1;
        cs_bound_.resize(nc);
        cs_fluid_.resize(nc);
        bound_near_.resize(nc - 1);
        near_tmp_.resize(nc - 1);
        moving_pos0_.upload(s.moving_pos0);
        moving_object_.upload(s.moving_object);
        motions_.resize(s.motion_objects > 0 ? s.motion_objects : 1);
        reduce_blocks_ = std::uint32_t(sms_) * 4u;
        block_maxima_.resize(reduce_blocks_);
        maxima_.resize(1);
        active_end_.resize(1);
        std::size_t temp = 0;
        cub::DeviceRadixSort::SortPairs(nullptr, temp, keys_.data(), keys_alt_.data(), perm_.data(),
                                        perm_alt_.data(), int(np));
        sort_temp_.resize(temp > 0 ? temp : 1);
        if (!s.solid.empty()) solid_.init(s.solid, s.step);
        sortRange(0, nbound_, cs_bound_.data(), true);
        boundNear();
        solid_.updateSlots(id_.data(), nbound_);
    }

    void divide(bool keep_step_start) override {
        const bool pre = !setup_.symplectic || keep_step_start;
        // Solid particles move inside the boundary block: re-sort it, and find them again.
        if (setup_.nmoving > 0 || !solid_.empty()) {
            sortRange(0, nbound_, cs_bound_.data(), pre);
            boundNear();
            solid_.updateSlots(id_.data(), nbound_);
        }
        nfluid_ = sortRange(nbound_, nbound_ + nfluid_, cs_fluid_.data(), pre) - nbound_;
        const std::uint32_t n = nbound_ + nfluid_;
        if (n > 0) {
            posCellKernel<<<blocksFor(n), kThreads>>>(n, view(), setup_.grid);
            SEASPRING_CUDA_LAUNCH_CHECK();
        }
    }

    void applyMotion(const std::vector<physics::RigidMotionGpu>& motions) override {
        if (setup_.nmoving == 0 || nbound_ == 0) return;
        SEASPRING_CUDA_CHECK(cudaMemcpy(motions_.data(), motions.data(),
                                        motions.size() * sizeof(physics::RigidMotionGpu), cudaMemcpyHostToDevice));
        motionKernel<<<blocksFor(nbound_), kThreads>>>(nbound_, view(), setup_.first_moving, setup_.nmoving,
                                                        moving_pos0_.data(), moving_object_.data(), motions_.data());
        SEASPRING_CUDA_LAUNCH_CHECK();
    }

    physics::DtMaxima computeForces() override {
        DeviceArrays a = arrays();
        return cudaComputeForces(setup_.physics, a, nbound_, nfluid_, setup_.fluid, setup_.grid);
    }

    void symplecticPredictor(double dt) override {
        const std::uint32_t n = nbound_ + nfluid_;
        if (n == 0) return;
        predictorKernel<<<blocksFor(n), kThreads>>>(n, nbound_, view(), dt, setup_.step);
        SEASPRING_CUDA_LAUNCH_CHECK();
    }
    void symplecticCorrector(double dt) override {
        const std::uint32_t n = nbound_ + nfluid_;
        if (n == 0) return;
        correctorKernel<<<blocksFor(n), kThreads>>>(n, nbound_, view(), dt, setup_.step);
        SEASPRING_CUDA_LAUNCH_CHECK();
    }
    void verletStep(double dt, bool euler) override {
        const std::uint32_t n = nbound_ + nfluid_;
        if (n == 0) return;
        verletKernel<<<blocksFor(n), kThreads>>>(n, nbound_, view(), dt, euler, setup_.step);
        SEASPRING_CUDA_LAUNCH_CHECK();
    }

    void solidHydroForces() override {
        if (!solid_.empty()) hydroForces(solid_.slots(), solid_.size(), solid_.fluidForce());
    }
    void solidSteps(double t0, double dt, int n, const std::vector<physics::RigidMotionGpu>& motions,
                    bool ledger) override {
        if (solid_.empty()) return;
        solid_.steps(t0, dt, n, motions);
        solid_.toBoundary(dt * n, ledger, pos_.data(), velrho_.data());
    }
    void solidSave() override { solid_.save(); }
    void solidRestore() override {
        if (solid_.empty()) return;
        solid_.restore();
        solid_.toBoundary(0.0, false, pos_.data(), velrho_.data());
    }

    void boundaryForces(std::vector<physics::Double3>& out) override {
        out.assign(nbound_, physics::Double3{0, 0, 0});
        if (nbound_ == 0) return;
        const std::uint32_t np = nbound_ + nfluid_;
        pressureKernel<<<blocksFor(np), kThreads>>>(np, view(), setup_.fluid);
        SEASPRING_CUDA_LAUNCH_CHECK();
        DeviceBuffer<physics::Double3> force(nbound_);  // output times only
        hydroForces(nullptr, nbound_, force.data());
        std::vector<physics::Double3> sorted;
        std::vector<std::uint32_t> ids;
        force.download(sorted);
        id_.download(ids);
        for (std::uint32_t i = 0; i < nbound_; ++i) out[ids[i]] = sorted[i];
    }

    void setGauges(const solver::GaugeQueries& q) override { gauges_.set(q, nbound_); }
    void gauges(solver::GaugeResults& out) override {
        gauges_.evaluate(setup_.physics, arrays(), nbound_, setup_.fluid, setup_.grid, out);
    }

    std::uint32_t activeFluid() const override { return nfluid_; }
    void synchronize() override { SEASPRING_CUDA_CHECK(cudaDeviceSynchronize()); }

    void download(solver::HostState& out) override {
        SEASPRING_CUDA_CHECK(cudaDeviceSynchronize());
        std::vector<std::uint32_t> ids;
        std::vector<physics::Double3> pos;
        std::vector<physics::Float4> vr;
        std::vector<std::uint8_t> ex;
        id_.download(ids);
        pos_.download(pos);
        velrho_.download(vr);
        excl_.download(ex);
        out.pos.resize(np_);
        out.velrho.resize(np_);
        out.excl.resize(np_);
        for (std::size_t i = 0; i < np_; ++i) {
            out.pos[ids[i]] = pos[i];
            out.velrho[ids[i]] = vr[i];
            out.excl[ids[i]] = ex[i];
        }
        if (!solid_.empty()) solid_.download(out);
    }

private:
    /// The hydrodynamic force on boundary particles slot[0..n) (null: the block [0, n)).
    void hydroForces(const std::uint32_t* slot, std::uint32_t n, physics::Double3* out) {
        DeviceArrays a = arrays();
        if (setup_.physics.kernel == physics::KernelType::Wendland)
            cudaHydroForces_wendland(setup_.physics, a, slot, n, out, setup_.fluid, setup_.grid);
        else
            cudaHydroForces_cubic(setup_.physics, a, slot, n, out, setup_.fluid, setup_.grid);
    }

    /// What the force drivers read and write (device pointers).
    DeviceArrays arrays() {
        DeviceArrays a;
        a.v = view();
        a.cell_start_bound = cs_bound_.data();
        a.cell_start_fluid = cs_fluid_.data();
        a.bound_near = bound_near_.data();
        a.block_maxima = block_maxima_.data();
        a.maxima = maxima_.data();
        a.reduce_blocks = reduce_blocks_;
        return a;
    }

    physics::ParticleView view() {
        physics::ParticleView v;
        v.id = id_.data();
        v.pos = pos_.data();
        v.velrho = velrho_.data();
        v.excl = excl_.data();
        v.poscell = poscell_.data();
        v.press_ovrho = press_ovrho_.data();
        v.pos_pre = pos_pre_.data();
        v.velrho_pre = velrho_pre_.data();
        v.acear = acear_.data();
        v.visc = visc_.data();
        v.tau = tau_.empty() ? nullptr : tau_.data();
        v.gradvel = gradvel_.empty() ? nullptr : gradvel_.data();
        v.keys = keys_.data();
        v.perm = perm_.data();
        return v;
    }

    template <typename T>
    void gather(DeviceBuffer<T>& arr, DeviceBuffer<T>& scratch, std::uint32_t b, std::uint32_t e) {
        if (arr.empty()) return;
        gatherKernel<T><<<blocksFor(e - b), kThreads>>>(b, e, perm_.data(), arr.data(), scratch.data());
        SEASPRING_CUDA_LAUNCH_CHECK();
        SEASPRING_CUDA_CHECK(cudaMemcpyAsync(arr.data() + b, scratch.data() + b, std::size_t(e - b) * sizeof(T),
                                             cudaMemcpyDeviceToDevice));
    }

    /// The "near" flags of the block with cell ranges `cs` (physics::cellOccupiedAt and
    /// dilateCellsAt).
    void blockNear(const std::uint32_t* cs, std::uint8_t* near) {
        const std::uint32_t nc = setup_.grid.cellCount();
        std::uint8_t* t = near_tmp_.data();
        cellOccupiedKernel<<<blocksFor(nc), kThreads>>>(nc, cs, near);
        SEASPRING_CUDA_LAUNCH_CHECK();
        dilateCellsKernel<<<blocksFor(nc), kThreads>>>(nc, 0, setup_.grid, near, t);
        SEASPRING_CUDA_LAUNCH_CHECK();
        dilateCellsKernel<<<blocksFor(nc), kThreads>>>(nc, 1, setup_.grid, t, near);
        SEASPRING_CUDA_LAUNCH_CHECK();
        dilateCellsKernel<<<blocksFor(nc), kThreads>>>(nc, 2, setup_.grid, near, t);
        SEASPRING_CUDA_LAUNCH_CHECK();
        SEASPRING_CUDA_CHECK(cudaMemcpyAsync(near, t, nc, cudaMemcpyDeviceToDevice));
    }
    void boundNear() { blockNear(cs_bound_.data(), bound_near_.data()); }

    /// Sorts [b, e) by (cell, id), excluded last; rebuilds `cs` for the active part. `pre`:
    /// reorder the step-start state too (Backend::divide). Returns the end of the active part.
    std::uint32_t sortRange(std::uint32_t b, std::uint32_t e, std::uint32_t* cs, bool pre) {
        const std::uint32_t nc = setup_.grid.cellCount() + 1;
        if (e > b) {
            sortKeysKernel<<<blocksFor(e - b), kThreads>>>(b, e, view(), setup_.grid);
            SEASPRING_CUDA_LAUNCH_CHECK();
            std::size_t temp = sort_temp_.size();
            SEASPRING_CUDA_CHECK(cub::DeviceRadixSort::SortPairs(
                sort_temp_.data(), temp, keys_.data() + b, keys_alt_.data() + b, perm_.data() + b,
                perm_alt_.data() + b, int(e - b)));
            std::swap(keys_, keys_alt_);
            std::swap(perm_, perm_alt_);
            // keys_/perm_ now hold the sorted range; outside [b, e) they are stale (unused).
            gather(id_, scratch_u32_, b, e);
            gather(pos_, scratch_d3_, b, e);
            gather(velrho_, scratch_f4_, b, e);
            gather(excl_, scratch_u8_, b, e);
            if (setup_.symplectic && pre) gather(pos_pre_, scratch_d3_, b, e);
            if (pre) gather(velrho_pre_, scratch_f4_, b, e);
            gather(tau_, scratch_t_, b, e);
            activeEndKernel<<<1, 1>>>(b, e, keys_.data(), active_end_.data());
            SEASPRING_CUDA_LAUNCH_CHECK();
        }
        std::uint32_t active_end = b;
        if (e > b)
            SEASPRING_CUDA_CHECK(cudaMemcpy(&active_end, active_end_.data(), sizeof active_end, cudaMemcpyDeviceToHost));
        cellStartOuterKernel<<<blocksFor(nc), kThreads>>>(nc, b, active_end, keys_.data(), cs);
        SEASPRING_CUDA_LAUNCH_CHECK();
        if (active_end > b) {
            cellStartFillKernel<<<blocksFor(active_end - b), kThreads>>>(b, active_end, keys_.data(), cs);
            SEASPRING_CUDA_LAUNCH_CHECK();
        }
        return active_end;
    }

    int device_;
    std::string name_;
    int sms_ = 1;
    solver::BackendSetup setup_;
    std::uint32_t nbound_ = 0, nfluid_ = 0;
    std::size_t np_ = 0;
    std::uint32_t reduce_blocks_ = 1;
    DeviceBuffer<std::uint32_t> id_, perm_, perm_alt_, scratch_u32_, cs_bound_, cs_fluid_, active_end_;
    DeviceBuffer<physics::Double3> pos_, pos_pre_, scratch_d3_, moving_pos0_;
    DeviceBuffer<physics::Float4> velrho_, velrho_pre_, poscell_, acear_, scratch_f4_;
    DeviceBuffer<std::uint8_t> excl_, scratch_u8_, sort_temp_, bound_near_, near_tmp_;
    DeviceBuffer<float> visc_;
    DeviceBuffer<physics::Float2> press_ovrho_;
    DeviceBuffer<physics::SymTensor> tau_, gradvel_, scratch_t_;
    DeviceBuffer<std::uint64_t> keys_, keys_alt_;
    DeviceBuffer<std::uint16_t> moving_object_;
    DeviceBuffer<physics::RigidMotionGpu> motions_;
    DeviceBuffer<physics::DtMaxima> block_maxima_, maxima_;
    CudaSolid solid_;
    CudaGauges gauges_;
};

}  // namespace

}  // namespace seaspring::cuda

namespace seaspring::solver {
std::unique_ptr<Backend> makeCudaBackend(int device, std::string& why) {
    int count = 0;
    const cudaError_t err = cudaGetDeviceCount(&count);
    if (err != cudaSuccess || count == 0) {
        why = err != cudaSuccess ? std::string("no CUDA device: ") + cudaGetErrorString(err)
                                 : std::string("no CUDA device found");
        return nullptr;
    }
    if (device < 0 || device >= count) {
        why = "CUDA device " + std::to_string(device) + " does not exist (devices: 0.." +
              std::to_string(count - 1) + ")";
        return nullptr;
    }
    return std::make_unique<cuda::CudaBackend>(device);
}
}  // namespace seaspring::solver
