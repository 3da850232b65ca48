// SeaSpring — MIT licence.
/// \file host_device.h
/// \brief SEASPRING_HD marks functions compiled for host and device alike.
#pragma once

#include <cstdint>

#if defined(__CUDACC__)
#define SEASPRING_HD __host__ __device__
#else
#define SEASPRING_HD
#endif

/// SEASPRING_HD, always inlined: for the small helpers of the innermost loops, which the host
/// compiler would otherwise sometimes leave as calls (the row walk's helpers did: 13% of a CPU step).
/// Inlining changes no result (no contraction, no reassociation on either side).
#if defined(__CUDACC__)
#define SEASPRING_HD_INLINE __host__ __device__ __forceinline__
#elif defined(__GNUC__)
#define SEASPRING_HD_INLINE inline __attribute__((always_inline))
#else
#define SEASPRING_HD_INLINE inline
#endif

/// On a host-only compile: inline everything a function calls (GCC's flatten), for the bodies of
/// the pair-loop passes, so that the accumulators the neighbour visitor's lambdas update stay in
/// registers. Inlining changes no result. Nothing under nvcc (its device code inlines anyway).
#if !defined(__CUDACC__) && defined(__GNUC__)
#define SEASPRING_HOST_FLATTEN __attribute__((flatten))
#else
#define SEASPRING_HOST_FLATTEN
#endif

/// Device code: makes `x` a value computed here, so that the compiler keeps it in a register
/// rather than recomputing it where it is used (NVVM sank the row frame of the pair loops into
/// the candidate loop, 8 instructions per candidate). Changes no value; nothing on the host.
#if defined(__CUDA_ARCH__)
#define SEASPRING_MATERIALIZE(x) asm volatile("" : "+f"(x))
#else
#define SEASPRING_MATERIALIZE(x) ((void)0)
#endif

/// The index of the lowest set bit of x != 0 (bit scans of the pair loops' hit masks).
SEASPRING_HD_INLINE int lowestSetBit(std::uint32_t x) {
#if defined(__CUDA_ARCH__)
    return __ffs(int(x)) - 1;
#else
    return __builtin_ctz(x);
#endif
}
