// SeaSpring — MIT licence.
/// \file warp_lanes.cuh
/// \brief The lane group of physics/fluid_pair_queue.h on the GPU: one warp, each lane's slots of
///        neighbour indices in shared memory (slot-major, so the lanes of a warp touch
///        consecutive words: no bank conflicts).
#pragma once

#include <cstdint>
#include <type_traits>

namespace seaspring::cuda {

/// Neighbours each lane collects before its warp evaluates pairs (docs/performance.md,
/// "Lane queue").
constexpr unsigned kLaneBatch = 16;

template <int kThreads>
struct WarpLanes {
    static constexpr unsigned kBatch = kLaneBatch;
    std::uint32_t* slots;  ///< kBatch * kThreads words of shared memory
    __device__ bool any(bool p) const { return __any_sync(0xffffffffu, p); }
    __device__ void put(unsigned slot, std::uint32_t j) { slots[slot * kThreads + threadIdx.x] = j; }
    __device__ std::uint32_t get(unsigned slot) const { return slots[slot * kThreads + threadIdx.x]; }
};

/// Passes with `static constexpr bool kLaneQueued = true` and a member
/// `template <class Lanes> queued(i, valid, lanes)` run through the lane queue: every thread of
/// every warp calls it (valid = i inside the range).
template <class F, class = void>
struct IsLaneQueued : std::false_type {};
template <class F>
struct IsLaneQueued<F, std::void_t<decltype(F::kLaneQueued)>> : std::bool_constant<F::kLaneQueued> {};

/// Runs pass f for index i of [b, e) from a kernel of kThreads threads per block (a whole
/// number of warps): through the lane queue when the pass has one, else f(i) for i < e.
template <int kThreads, class F>
__device__ __forceinline__ void runIndex(std::uint32_t i, std::uint32_t e, const F& f) {
    if constexpr (IsLaneQueued<F>::value) {
        static_assert(kThreads % 32 == 0, "lane queues need whole warps");
        __shared__ std::uint32_t slots[kLaneBatch * kThreads];
        WarpLanes<kThreads> lanes{slots};
        f.queued(i, i < e, lanes);
    } else {
        if (i < e) f(i);
    }
}

}  // namespace seaspring::cuda
