// SeaSpring — MIT licence.
/// \file host_exec.h
/// \brief The OpenMP execution policy of the solver's engine (solver/engine.h): host memory
///        (std::vector), passes as OpenMP loops, the sort, and fixed-order reductions.
#pragma once

#include <omp.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/device_info.h"
#include "solver/buffers.h"

namespace seaspring::cpu {

class HostExec {
public:
    template <typename T>
    using Buffer = std::vector<T>;
    /// The pair loops take the host's batched form (physics::PairBatch): same bits, SIMD lanes;
    /// one call forms all pair lanes of a fluid particle (solver::FluidForcesPass).
    static constexpr bool kCompactPairs = true;

    /// `threads` <= 0: OpenMP's default. Every parallel region names its thread count, so
    /// engines of different thread counts can live in one process (the typed tests do).
    explicit HostExec(int threads) : threads_(threads > 0 ? threads : omp_get_max_threads()) {}
    std::string name() const { return "cpu"; }
    std::string deviceName() const;
    int threads() const { return threads_; }
    int hostThreads() const { return threads_; }
    /// No device: the arrays are in the host's memory.
    DeviceMemoryUse deviceMemory() const { return {}; }

    /// f(i) for i in [b, e), spread as Launch says (launch.h).
    template <class Launch, class F>
    void forEach(std::uint32_t b, std::uint32_t e, const F& f) const {
        if (gateClosed()) return;
        if constexpr (Launch::kCpuChunk == 0) {
#pragma omp parallel for num_threads(threads_) schedule(static)
            for (std::int64_t i = b; i < std::int64_t(e); ++i) f(std::uint32_t(i));
        } else {
#pragma omp parallel for num_threads(threads_) schedule(dynamic, Launch::kCpuChunk)
            for (std::int64_t i = b; i < std::int64_t(e); ++i) f(std::uint32_t(i));
        }
    }

    /// Two independent passes (neither reads what the other writes): fa over [ba, ea), then fb
    /// over [bb, eb), in one parallel region whose threads move on to the second pass as they
    /// finish their share of the first (no barrier between them).
    template <class LaunchA, class LaunchB, class FA, class FB>
    void forEachIndependent(std::uint32_t ba, std::uint32_t ea, const FA& fa, std::uint32_t bb, std::uint32_t eb,
                            const FB& fb) const {
        if (gateClosed()) return;
        static_assert(LaunchA::kCpuChunk > 0 && LaunchB::kCpuChunk > 0, "dynamic schedules only");
#pragma omp parallel num_threads(threads_)
        {
#pragma omp for schedule(dynamic, LaunchA::kCpuChunk) nowait
            for (std::int64_t i = ba; i < std::int64_t(ea); ++i) fa(std::uint32_t(i));
#pragma omp for schedule(dynamic, LaunchB::kCpuChunk)
            for (std::int64_t i = bb; i < std::int64_t(eb); ++i) fb(std::uint32_t(i));
        }
    }

    /// combine(..., f(i)) over [b, e) from `init`. `combine` must be exact, commutative and
    /// associative (max, min, integer sums), so the grouping of the partial results, which
    /// depends on the thread count, cannot change the result.
    template <class T, class F, class C>
    T reduce(std::uint32_t b, std::uint32_t e, T init, const F& f, const C& combine) const {
        if (gateClosed()) return init;
        T total = init;
#pragma omp parallel num_threads(threads_)
        {
            T local = init;
#pragma omp for schedule(static) nowait
            for (std::int64_t i = b; i < std::int64_t(e); ++i) local = combine(local, f(std::uint32_t(i)));
#pragma omp critical
            total = combine(total, local);
        }
        return total;
    }

    /// A reduction's result that the host takes later (reduceDeferred): here it is computed at
    /// once.
    template <class T>
    struct Deferred {
        T value{};
        T get() const { return value; }
        const T* device() const { return &value; }  ///< what a gate reads
    };
    /// reduce() into `out`, for out.get() later (the GPU's version does not wait for it).
    template <class T, class F, class C>
    void reduceDeferred(std::uint32_t b, std::uint32_t e, T init, const F& f, const C& combine, Deferred<T>& out) const {
        out.value = reduce(b, e, init, f, combine);
    }

    /// One thread per solid particle in the sub-cycle (solver::BondLanes): the host's threads
    /// are few and each walks a particle's bonds with no latency to hide.
    std::uint32_t bondLaneShift(std::uint64_t /*work*/, std::uint32_t /*nsolid*/) const { return 0; }

    /// Runs `body(run)` with a runner run(n, pass) = pass(i) for i < n, all threads of one
    /// parallel region sharing each pass (`omp for`, whose implied barrier orders the passes).
    template <class Body>
    void sequence(std::uint64_t /*work*/, std::uint32_t /*widest*/, const Body& body) const {
        if (gateClosed()) return;
#pragma omp parallel num_threads(threads_)
        {
            TeamRun run;
            body(run);
        }
    }

    /// Sorts keys[b, e) ascending, carrying perm[b, e) along; keys are unique, so the order is
    /// the only sorted order. The *_alt arrays are not needed here. The result is in keys and perm.
    void sortPairs(std::uint64_t* keys, std::uint64_t* /*keys_alt*/, std::uint32_t* perm, std::uint32_t* /*perm_alt*/,
                   std::uint32_t b, std::uint32_t e) const {
        ungated("sortPairs");
        pairs_.resize(e > b ? e - b : 0);
        for (std::uint32_t i = b; i < e; ++i) pairs_[i - b] = {keys[i], perm[i]};
        std::sort(pairs_.begin(), pairs_.end());
        for (std::uint32_t i = b; i < e; ++i) {
            keys[i] = pairs_[i - b].first;
            perm[i] = pairs_[i - b].second;
        }
    }
    /// As CudaExec::stayersFirst: perm_out[b, e) = the entries of perm[b, e) whose stays is set,
    /// in order, then the others; keys_out[i] = keys[perm_out[i]]; n_at_least = the number of
    /// keys >= at_least. Returns the number of stayers when their keys ascend, else 0.
    std::uint32_t stayersFirst(const std::uint64_t* keys, const std::uint32_t* perm, const std::uint8_t* stays,
                               std::uint64_t* keys_out, std::uint32_t* perm_out, std::uint32_t b, std::uint32_t e,
                               std::uint64_t at_least, std::uint32_t& n_at_least) const {
        ungated("stayersFirst");
        n_at_least = 0;
        for (std::uint32_t i = b; i < e; ++i) n_at_least += keys[i] >= at_least ? 1u : 0u;
        std::uint32_t o = b;
        for (std::uint32_t i = b; i < e; ++i)
            if (stays[i] != 0) perm_out[o++] = perm[i];
        const std::uint32_t nstay = o - b;
        for (std::uint32_t i = b; i < e; ++i)
            if (stays[i] == 0) perm_out[o++] = perm[i];
        for (std::uint32_t i = b; i < e; ++i) keys_out[i] = keys[perm_out[i]];
        for (std::uint32_t i = b + 1; i < b + nstay; ++i)
            if (keys_out[i - 1] >= keys_out[i]) return 0;
        return nstay;
    }
    /// Merges the ascending keys [b, m) and [m, e) (perm carried along) into keys_out and
    /// perm_out [b, e); keys are unique.
    void mergePairs(const std::uint64_t* keys, const std::uint32_t* perm, std::uint32_t b, std::uint32_t m,
                    std::uint32_t e, std::uint64_t* keys_out, std::uint32_t* perm_out) const {
        ungated("mergePairs");
        std::uint32_t i = b, j = m, o = b;
        while (i < m && j < e) {
            const std::uint32_t k = keys[j] < keys[i] ? j++ : i++;
            keys_out[o] = keys[k];
            perm_out[o++] = perm[k];
        }
        for (; i < m; ++i, ++o) keys_out[o] = keys[i], perm_out[o] = perm[i];
        for (; j < e; ++j, ++o) keys_out[o] = keys[j], perm_out[o] = perm[j];
    }
    /// Size the sort's scratch for n keys (nothing to do on the host).
    void prepareSort(std::size_t) {}

    /// First index in [b, e) of sorted keys whose key is >= value.
    std::uint32_t lowerBound(const std::uint64_t* keys, std::uint32_t b, std::uint32_t e, std::uint64_t value) const {
        ungated("lowerBound");
        return std::uint32_t(std::lower_bound(keys + b, keys + e, value) - keys);
    }

    template <typename T>
    void copy(T* dst, const T* src, std::size_t n) const {
        ungated("copy");
        std::copy(src, src + n, dst);
    }
    void synchronize() const {}

    /// As CudaExec::gate: the passes run under a set gate do nothing when *g is non-zero (read
    /// when each pass starts, as the GPU's kernels do).
    void gate(const std::uint32_t* g) { gate_ = g; }

private:
    mutable std::vector<std::pair<std::uint64_t, std::uint32_t>> pairs_;  ///< sortPairs' scratch
    bool gateClosed() const { return gate_ != nullptr && *gate_ != 0u; }
    void ungated(const char* what) const {
        if (gate_ != nullptr) throw std::logic_error(std::string("HostExec: ") + what + " run under a gate");
    }
    struct TeamRun {
        template <class F>
        void operator()(std::uint32_t n, const F& f) const {
#pragma omp for schedule(static)
            for (std::int64_t i = 0; i < std::int64_t(n); ++i) f(std::uint32_t(i));
        }
    };
    int threads_;
    const std::uint32_t* gate_ = nullptr;
};

}  // namespace seaspring::cpu
