// SeaSpring — MIT licence.
/// \file lane_group.h
/// \brief Values exchanged across a group of consecutive GPU threads: combined in a fixed tree
///        (the pair lanes of one fluid particle, physics/fluid_interaction.h) or taken from one
///        thread (the bond lanes of one solid particle, physics/vcpm_substep.h). No physics,
///        only the order.
#pragma once

#include <cstdint>
#include <cstring>

#include "core/host_device.h"

namespace seaspring {

/// The mask of the caller's aligned group of `lanes` consecutive threads in its warp (GPU).
#if defined(__CUDA_ARCH__)
__device__ inline unsigned laneGroupMask(std::uint32_t lanes) {
    const unsigned me = threadIdx.x & 31u;
    return lanes >= 32u ? 0xffffffffu : ((1u << lanes) - 1u) << (me & ~(lanes - 1u));
}
#endif

/// On the GPU: the threads of each aligned group of `lanes` consecutive threads of a warp (lanes a
/// power of two <= 32; every thread of the group calls this) combine their values `v` pairwise:
/// at width w = 1, 2, 4, ..., each thread takes the value of thread ^ w and keeps
/// combine(lower thread's, upper thread's). Every thread of the group ends with the tree
/// (v0 + v1) + (v2 + v3) ..., the same bits as physics::combineLanes forms on the host from the
/// same partials. `combine` need not be commutative: the lower thread's value always comes first.
/// On the host (which forms all partials of a particle in one call) it returns v: lanes must be 1.
template <class T, class C>
SEASPRING_HD inline T combineAcrossLanes(T v, std::uint32_t lanes, const C& combine) {
#if defined(__CUDA_ARCH__)
    static_assert(sizeof(T) % sizeof(unsigned) == 0, "a lane value is a whole number of 32-bit words");
    constexpr int kWords = int(sizeof(T) / sizeof(unsigned));
    const unsigned me = threadIdx.x & 31u;
    const unsigned mask = laneGroupMask(lanes);
    for (unsigned w = 1; w < lanes; w <<= 1) {
        unsigned words[kWords];
        std::memcpy(words, &v, sizeof(T));
        for (int k = 0; k < kWords; ++k) words[k] = __shfl_xor_sync(mask, words[k], int(w));
        T other;
        std::memcpy(&other, words, sizeof(T));
        v = (me & w) != 0u ? combine(other, v) : combine(v, other);
    }
#else
    (void)lanes;
    (void)combine;
#endif
    return v;
}

/// On the GPU: thread `src`'s value `v` (0 <= src < lanes; the threads numbered in the caller's
/// aligned group of `lanes` consecutive threads of a warp, lanes a power of two <= 32; every
/// thread of the group calls this, with the same src). On the host: v (lanes must be 1).
template <class T>
SEASPRING_HD inline T valueOfLane(T v, std::uint32_t src, std::uint32_t lanes) {
#if defined(__CUDA_ARCH__)
    static_assert(sizeof(T) % sizeof(unsigned) == 0, "a lane value is a whole number of 32-bit words");
    constexpr int kWords = int(sizeof(T) / sizeof(unsigned));
    if (lanes == 1u) return v;
    const unsigned mask = laneGroupMask(lanes);
    const int from = int((threadIdx.x & 31u & ~(lanes - 1u)) + src);
    unsigned words[kWords];
    std::memcpy(words, &v, sizeof(T));
    for (int k = 0; k < kWords; ++k) words[k] = __shfl_sync(mask, words[k], from);
    std::memcpy(&v, words, sizeof(T));
#else
    (void)src;
    (void)lanes;
#endif
    return v;
}

/// The threads of the caller's group of `lanes` wait for each other, and the global-memory
/// writes of each are seen by the others after it (GPU: __syncwarp on the group's mask; the
/// host: nothing, lanes must be 1).
SEASPRING_HD inline void syncLanes(std::uint32_t lanes) {
#if defined(__CUDA_ARCH__)
    if (lanes > 1u) __syncwarp(laneGroupMask(lanes));
#else
    (void)lanes;
#endif
}

}  // namespace seaspring
