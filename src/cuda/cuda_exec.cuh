// SeaSpring — MIT licence.
/// \file cuda_exec.cuh
/// \brief The CUDA execution policy of the solver's engine (solver/engine.h): device memory
///        (DeviceBuffer), passes as kernel launches of one thread per index, the radix sort
///        (CUB), fixed-shape reductions, and the single-block launch of small pass sequences.
///        Everything runs on the default stream, in issue order. A gate (CudaExec::gate) makes
///        the kernels launched under it do nothing when a device word is set.
#pragma once

#include <cub/block/block_reduce.cuh>
#include <cub/device/device_radix_sort.cuh>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "core/device_info.h"
#include "cuda/cuda_check.cuh"
#include "cuda/device_buffer.cuh"

namespace seaspring::cuda {

/// Whether a launch under `gate` is to do nothing (null: no gate; CudaExec::gate).
__device__ inline bool gateClosed(const std::uint32_t* gate) { return gate != nullptr && *gate != 0u; }

/// One thread per index of [b, e).
template <int kThreads, class F>
__global__ void __launch_bounds__(kThreads) forEachKernel(std::uint32_t b, std::uint32_t e, F f,
                                                          const std::uint32_t* gate) {
    if (gateClosed(gate)) return;
    const std::uint32_t i = b + blockIdx.x * blockDim.x + threadIdx.x;
    if (i < e) f(i);
}

/// Two independent passes in one launch: blocks [0, blocks_a) run fa over [ba, ea), the
/// others fb over [bb, eb). On small cases each pass alone leaves most of the GPU idle (one
/// thread per particle, latency-bound): in one launch they run side by side.
template <int kThreads, class FA, class FB>
__global__ void __launch_bounds__(kThreads) forEachTwoKernel(std::uint32_t ba, std::uint32_t ea, FA fa,
                                                             std::uint32_t blocks_a, std::uint32_t bb,
                                                             std::uint32_t eb, FB fb,
                                                             const std::uint32_t* gate) {
    if (gateClosed(gate)) return;
    if (blockIdx.x < blocks_a) {
        const std::uint32_t i = ba + blockIdx.x * blockDim.x + threadIdx.x;
        if (i < ea) fa(i);
    } else {
        const std::uint32_t i = bb + (blockIdx.x - blocks_a) * blockDim.x + threadIdx.x;
        if (i < eb) fb(i);
    }
}

/// The block size a launch's kernel is compiled for (__launch_bounds__): Launch::kGpuBoundThreads
/// where it has one (blocks smaller than the code's bound, solver/launch.h), else kGpuThreads.
template <class Launch, class = void>
constexpr int kBoundThreads = Launch::kGpuThreads;
template <class Launch>
constexpr int kBoundThreads<Launch, std::void_t<decltype(Launch::kGpuBoundThreads)>> = Launch::kGpuBoundThreads;

constexpr int kReduceThreads = 256;
/// Elements per thread below which a reduction takes fewer blocks than its maximum.
constexpr std::uint32_t kReducePerThread = 1;

/// *p read past the L1 cache (ld.global.cg, word by word): what another block wrote before a
/// __threadfence is seen (the CUDA guide's last-block pattern reads through volatile).
template <class T>
__device__ T loadCoherent(const T* p) {
    static_assert(sizeof(T) % sizeof(unsigned) == 0, "a reduction value is a whole number of 32-bit words");
    T r;
    unsigned* dst = reinterpret_cast<unsigned*>(&r);
    const unsigned* src = reinterpret_cast<const unsigned*>(p);
    for (unsigned w = 0; w < sizeof(T) / sizeof(unsigned); ++w) dst[w] = __ldcg(src + w);
    return r;
}

/// Reduction in one launch: each block combines a grid-stride share of [b, e) (CUB's block
/// reduction) into parts[block]; the last block to finish (an integer ticket, `done`, reset for the
/// next call) combines the blocks' results into *out and, when host_out is not null, into
/// *host_out too (pinned host memory, which a kernel writes directly: no copy on the stream
/// after it; the host reads it once the kernel is seen complete). Only exact combines are used
/// (see CudaExec::reduce), so which block comes last changes nothing. Under a closed gate the
/// result is `init` and f is not called.
template <class T, class F, class C>
__global__ void __launch_bounds__(kReduceThreads) reduceKernel(std::uint32_t b, std::uint32_t e, T init, F f,
                                                              C combine, T* parts, unsigned* done, T* out,
                                                              T* host_out, const std::uint32_t* gate) {
    // A block's values combined by CUB (warp shuffles, then the warps' results): a fixed shape,
    // and only exact combines are used, so the result is the same in any order.
    using BlockReduce = cub::BlockReduce<T, kReduceThreads, cub::BLOCK_REDUCE_WARP_REDUCTIONS>;
    __shared__ typename BlockReduce::TempStorage tmp;
    __shared__ bool last;
    T m = init;
    if (gateClosed(gate)) e = b;
    for (std::uint32_t i = b + blockIdx.x * blockDim.x + threadIdx.x; i < e; i += gridDim.x * blockDim.x)
        m = combine(m, f(i));
    m = BlockReduce(tmp).Reduce(m, combine);  // valid in thread 0
    if (threadIdx.x == 0) {
        parts[blockIdx.x] = m;
        __threadfence();  // the part is visible to every block before the ticket is taken
        last = atomicAdd(done, 1u) == gridDim.x - 1;
    }
    __syncthreads();
    if (!last) return;
    __threadfence();
    T r = init;
    for (std::uint32_t k = threadIdx.x; k < gridDim.x; k += blockDim.x) r = combine(r, loadCoherent(parts + k));
    r = BlockReduce(tmp).Reduce(r, combine);  // tmp is free again: the barrier above follows its last use
    if (threadIdx.x == 0) {
        *out = r;
        if (host_out != nullptr) *host_out = r;
        *done = 0u;
    }
}

/// stayersFirst's gather, check and count: keys_out[i] = keys[perm_out[i]]; words[1] = 1 when
/// two consecutive stayers (the first words[0] entries from b) do not ascend; words[2] += 1 for
/// each key >= at_least (an integer count: the same in any order).
__global__ void stayerKeysKernel(std::uint32_t b, std::uint32_t e, const std::uint64_t* keys,
                                 const std::uint32_t* perm_out, std::uint64_t* keys_out, std::uint64_t at_least,
                                 std::uint32_t* words);

/// First index in [b, e) whose key is >= value (binary search, one thread).
__global__ void lowerBoundKernel(std::uint32_t b, std::uint32_t e, const std::uint64_t* keys, std::uint64_t value,
                                 std::uint32_t* out);

/// A reduction's result on its way to the host (CudaExec::reduceDeferred): in a device word
/// of its own (device(): what a gate reads) and, written by the same kernel, in pinned host
/// memory, then an event. get() waits for the event; when a later readback has synchronised
/// the device in the meantime, it does not wait at all.
template <class T>
class DeferredValue {
public:
    DeferredValue() {
        SEASPRING_CUDA_CHECK(cudaMallocHost(reinterpret_cast<void**>(&host_), sizeof(T)));
        SEASPRING_CUDA_CHECK(cudaEventCreateWithFlags(&done_, cudaEventDisableTiming));
        dev_.resize(1);
    }
    ~DeferredValue() {
        cudaEventDestroy(done_);
        cudaFreeHost(host_);
    }
    DeferredValue(const DeferredValue&) = delete;
    DeferredValue& operator=(const DeferredValue&) = delete;
    T get() const {
        SEASPRING_CUDA_CHECK(cudaEventSynchronize(done_));
        return *host_;
    }
    /// The value on the device (set when the reduction's kernel ends).
    const T* device() const { return dev_.data(); }

private:
    friend class CudaExec;
    T* host_ = nullptr;
    cudaEvent_t done_ = nullptr;
    DeviceBuffer<T> dev_;
};

/// Threads of the single-block sequence kernel (block-stride loops over the indices).
constexpr int kSequenceBlockThreads = 1024;
/// The narrower variant of it, for sequences whose widest pass needs at most this many threads:
/// compiled for 512 threads, it may use 128 registers per thread, where the 1024-thread kernel
/// has 64 and spills (the solids' sub-cycle did, 156 bytes).
constexpr int kSequenceBlockThreadsNarrow = 512;

/// Runner of a sequence inside one block: each pass is a block-stride loop, then a barrier
/// (which also orders the pass's global-memory writes before the next pass's reads).
struct BlockRun {
    template <class F>
    __device__ void operator()(std::uint32_t n, const F& f) const {
        for (std::uint32_t i = threadIdx.x; i < n; i += blockDim.x) f(i);
        __syncthreads();
    }
};

template <int kThreads, class Body>
__global__ void __launch_bounds__(kThreads, 1) sequenceBlockKernel(Body body, const std::uint32_t* gate) {
    if (gateClosed(gate)) return;
    BlockRun run;
    body(run);
}

/// Default largest `work` (nsolid + nclamp for the solid sub-cycle) that `sequence` runs in
/// one block. Measured on an H200 (tools/device_solid_paths.sh, same hashes on both paths):
/// the Antoci gate (395 solid particles, about 3 sub-steps per fluid step) runs 3,000 coupled
/// steps in 2.68 s in one block against 3.14 s per pass; a 1,250-particle cantilever, 20,000
/// sub-steps in one call, 1.45 s against 1.39 s (even); at 10,000 particles 9.0 s against
/// 1.50 s and at 48,000 4.7 s against 0.14 s for 2,000 sub-steps (one SM cannot keep up). The
/// crossover lies between about 1,300 and 2,000 particles; 2,048 keeps every case within a
/// few percent of the faster path. SEASPRING_SOLID_BLOCK_MAX=N overrides it.
constexpr std::uint32_t kSequenceBlockMaxDefault = 2048;

/// Bond lanes (physics/vcpm_substep.h) of the sub-cycle's passes on the GPU: a solid that runs
/// in one block (above) keeps one thread per particle; one that runs a launch per pass gets
/// the most lanes, up to 8, that keep nsolid x lanes <= kBondLaneThreads. Measured on an H100
/// (tools/device_bondlanes.sh, docs/performance-solids.md): the Antoci gate (395 particles, one block)
/// 1.08x slower with 2 lanes, 1.25x with 4; FlexStruc Liao 2D (one block) 0.97-1.06x; in
/// launches per pass, the FlexStruc Liao 3D plate (12,250) 0.82x with 2, 0.73x with 4, 0.70x
/// with 8; a 3D bar of 6,169 particles 0.73x / 0.59x / 0.56x; one of 48,625 0.87x with 2,
/// 1.37x with 4. SEASPRING_BOND_LANES=N (1, 2, 4, 8) overrides the rule.
constexpr std::uint32_t kBondLaneThreads = 98304;
constexpr std::uint32_t kMaxBondLaneShift = 3;

class CudaExec {
public:
    template <typename T>
    using Buffer = DeviceBuffer<T>;
    /// One thread per pair lane of a fluid particle walks its candidates directly
    /// (physics::fluidPairsInRow; solver::FluidLanesPass).
    static constexpr bool kCompactPairs = false;

    /// host_threads <= 0: every core (std::thread::hardware_concurrency).
    CudaExec(int device, int host_threads);
    std::string name() const { return "gpu"; }
    std::string deviceName() const { return name_; }
    int threads() const { return 1; }
    int hostThreads() const { return host_threads_; }
    /// The bytes the process's device arrays hold and held at most since this policy was made
    /// (core/device_memory.h), and the device's memory.
    DeviceMemoryUse deviceMemory() const;

    template <class Launch, class F>
    void forEach(std::uint32_t b, std::uint32_t e, const F& f) const {
        if (e <= b) return;
        constexpr int kT = Launch::kGpuThreads;
        forEachKernel<kBoundThreads<Launch>, F><<<unsigned((std::uint64_t(e - b) + kT - 1) / kT), kT>>>(b, e, f, gate_);
        SEASPRING_CUDA_LAUNCH_CHECK();
    }

    /// Two independent passes: one launch (forEachTwoKernel, the second pass's blocks first)
    /// when both use the same block size and neither is empty, else two.
    template <class LaunchA, class LaunchB, class FA, class FB>
    void forEachIndependent(std::uint32_t ba, std::uint32_t ea, const FA& fa, std::uint32_t bb, std::uint32_t eb,
                            const FB& fb) const {
        constexpr int kT = LaunchA::kGpuThreads;
        if constexpr (kT == LaunchB::kGpuThreads && kBoundThreads<LaunchA> == kBoundThreads<LaunchB>) {
            if (ea > ba && eb > bb) {
                const std::uint32_t blocks_b = std::uint32_t((std::uint64_t(eb - bb) + kT - 1) / kT);
                const std::uint32_t blocks_a = std::uint32_t((std::uint64_t(ea - ba) + kT - 1) / kT);
                forEachTwoKernel<kBoundThreads<LaunchA>, FB, FA>
                    <<<blocks_a + blocks_b, kT>>>(bb, eb, fb, blocks_b, ba, ea, fa, gate_);
                SEASPRING_CUDA_LAUNCH_CHECK();
                return;
            }
        }
        forEach<LaunchA>(ba, ea, fa);
        forEach<LaunchB>(bb, eb, fb);
    }

    template <typename T>
    using Deferred = DeferredValue<T>;

    /// combine(..., f(i)) over [b, e) from `init` in one launch (reduceKernel: up to 4 blocks
    /// per SM, fewer for short ranges, the last block combining the blocks' results); `combine`
    /// must be exact, commutative and associative, so the shape changes no result. Synchronises
    /// (the kernel writes the result into pinned memory).
    template <class T, class F, class C>
    T reduce(std::uint32_t b, std::uint32_t e, T init, const F& f, const C& combine) const {
        static_assert(sizeof(T) <= kReadbackBytes, "a reduction value fits the pinned readback");
        launchReduce(b, e, init, f, combine, static_cast<T*>(nullptr), static_cast<T*>(readback_.get()));
        SEASPRING_CUDA_CHECK(cudaStreamSynchronize(0));
        T r;
        std::memcpy(&r, readback_.get(), sizeof r);
        return r;
    }

    /// reduce() without waiting: the result goes to out.device() and, from the same kernel, to
    /// the host (out.get() waits for the kernel).
    template <class T, class F, class C>
    void reduceDeferred(std::uint32_t b, std::uint32_t e, T init, const F& f, const C& combine, Deferred<T>& out) const {
        launchReduce(b, e, init, f, combine, out.dev_.data(), out.host_);
        SEASPRING_CUDA_CHECK(cudaEventRecord(out.done_));
    }

    /// Runs `body(run)`: in ONE single-block kernel when work <= the block limit (`widest`:
    /// the largest pass, which sets the block's threads), else launching one grid per pass.
    template <class Body>
    void sequence(std::uint64_t work, std::uint32_t widest, const Body& body) const {
        if (work <= block_max_) {
            // Only as many warps as the widest pass needs: the barriers then wait for fewer warps.
            const unsigned threads = unsigned(std::min<std::uint32_t>(kSequenceBlockThreads, (widest + 31u) / 32u * 32u));
            if (threads <= unsigned(kSequenceBlockThreadsNarrow))
                sequenceBlockKernel<kSequenceBlockThreadsNarrow, Body><<<1, threads > 0 ? threads : 32u>>>(body, gate_);
            else
                sequenceBlockKernel<kSequenceBlockThreads, Body><<<1, threads>>>(body, gate_);
            SEASPRING_CUDA_LAUNCH_CHECK();
            return;
        }
        GridRun run{this};
        body(run);
    }

    /// log2 of the bond lanes per solid particle of a sub-cycle of `work` indices (as
    /// `sequence` takes it) over `nsolid` particles (solver::BondLanes; kBondLaneThreads).
    std::uint32_t bondLaneShift(std::uint64_t work, std::uint32_t nsolid) const {
        if (bond_lane_shift_ >= 0) return std::uint32_t(bond_lane_shift_);
        if (work <= block_max_) return 0;
        std::uint32_t s = 0;
        while (s < kMaxBondLaneShift && (std::uint64_t(nsolid) << (s + 1)) <= kBondLaneThreads) ++s;
        return s;
    }

    void prepareSort(std::size_t n);
    /// Sorts keys[b, e) ascending carrying perm[b, e) (CUB radix sort, the *_alt arrays as its
    /// second buffers); the result is in keys and perm.
    void sortPairs(std::uint64_t* keys, std::uint64_t* keys_alt, std::uint32_t* perm, std::uint32_t* perm_alt,
                   std::uint32_t b, std::uint32_t e) const;
    /// perm_out[b, e) = the entries of perm[b, e) whose stays is set, in their order (CUB's
    /// stable partition), then the others; keys_out[i] = keys[perm_out[i]]; n_at_least = the
    /// number of keys >= at_least. Returns the number of stayers when their keys ascend, else 0
    /// (one kernel checks and counts while it gathers; synchronises once).
    std::uint32_t stayersFirst(const std::uint64_t* keys, const std::uint32_t* perm, const std::uint8_t* stays,
                               std::uint64_t* keys_out, std::uint32_t* perm_out, std::uint32_t b, std::uint32_t e,
                               std::uint64_t at_least, std::uint32_t& n_at_least) const;
    /// Merges the ascending keys [b, m) and [m, e) (perm carried along) into keys_out and
    /// perm_out [b, e) (CUB's merge; keys are unique).
    void mergePairs(const std::uint64_t* keys, const std::uint32_t* perm, std::uint32_t b, std::uint32_t m,
                    std::uint32_t e, std::uint64_t* keys_out, std::uint32_t* perm_out) const;
    /// First index in [b, e) of sorted keys whose key is >= value (synchronises).
    std::uint32_t lowerBound(const std::uint64_t* keys, std::uint32_t b, std::uint32_t e, std::uint64_t value) const;

    template <typename T>
    void copy(T* dst, const T* src, std::size_t n) const {
        ungated("copy");
        if (n > 0) SEASPRING_CUDA_CHECK(cudaMemcpyAsync(dst, src, n * sizeof(T), cudaMemcpyDeviceToDevice));
    }
    void synchronize() const { SEASPRING_CUDA_CHECK(cudaDeviceSynchronize()); }

    /// From now on, until gate(nullptr), every forEach, forEachIndependent, reduce and sequence
    /// launch does nothing when *g (a device word, e.g. a Deferred's device()) is non-zero when
    /// it runs; a reduction then gives `init`. Copies, sorts and searches cannot be gated:
    /// they throw while a gate is set.
    void gate(const std::uint32_t* g) { gate_ = g; }

private:
    /// Throws when a gate is set (what cannot be gated).
    void ungated(const char* what) const;
    /// Launches the reduction; its result goes to `out` on the device (the scratch's last slot
    /// when null) and to `host_out` in pinned host memory (none when null).
    template <class T, class F, class C>
    void launchReduce(std::uint32_t b, std::uint32_t e, T init, const F& f, const C& combine, T* out,
                      T* host_out) const {
        const std::uint64_t per_block = std::uint64_t(kReduceThreads) * kReducePerThread;
        const unsigned blocks = unsigned(std::max<std::uint64_t>(
            1, std::min<std::uint64_t>(reduce_blocks_, (std::uint64_t(e > b ? e - b : 0) + per_block - 1) / per_block)));
        const std::size_t need = sizeof(T) * (blocks + 1);
        if (reduce_scratch_.size() < need) reduce_scratch_.resize(need);
        T* parts = reinterpret_cast<T*>(reduce_scratch_.data());
        if (out == nullptr) out = parts + blocks;
        reduceKernel<T, F, C>
            <<<blocks, kReduceThreads>>>(b, e, init, f, combine, parts, reduce_done_.data(), out, host_out, gate_);
        SEASPRING_CUDA_LAUNCH_CHECK();
    }

    struct GridRun {
        const CudaExec* exec;
        template <class F>
        void operator()(std::uint32_t n, const F& f) const {
            exec->forEach<Launch256>(0u, n, f);
        }
    };
    struct Launch256 {
        static constexpr int kGpuThreads = 256;
    };

    static constexpr std::size_t kReadbackBytes = 64;
    std::string name_;
    int host_threads_ = 1;
    std::uint32_t reduce_blocks_ = 1;
    struct FreeHost {
        void operator()(void* p) const { cudaFreeHost(p); }
    };
    std::unique_ptr<void, FreeHost> readback_;  ///< pinned host memory for the readbacks (kReadbackBytes)
    std::uint32_t block_max_ = kSequenceBlockMaxDefault;
    int bond_lane_shift_ = -1;  ///< SEASPRING_BOND_LANES's log2; -1: the rule
    const std::uint32_t* gate_ = nullptr;  ///< see gate()
    mutable DeviceBuffer<std::uint8_t> reduce_scratch_, sort_temp_;
    DeviceBuffer<unsigned> reduce_done_;  ///< reduceKernel's ticket (0 between reductions)
    mutable DeviceBuffer<std::uint32_t> lower_bound_;
    mutable DeviceBuffer<std::uint32_t> stayers_;  ///< stayersFirst's counts and order check
};

}  // namespace seaspring::cuda
