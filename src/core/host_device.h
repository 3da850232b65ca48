// SeaSpring — MIT licence.
/// \file host_device.h
/// \brief SEASPRING_HD marks functions compiled for host and device alike.
#pragma once

#if defined(__CUDACC__)
#define SEASPRING_HD __host__ __device__
#else
#define SEASPRING_HD
#endif

/// SEASPRING_HD, always inlined: for the small helpers of the innermost loops, which the host
/// compiler would otherwise sometimes leave as calls (rowCandidates did: 13% of a CPU step).
/// Inlining changes no result (no contraction, no reassociation on either side).
#if defined(__CUDACC__)
#define SEASPRING_HD_INLINE __host__ __device__ __forceinline__
#elif defined(__GNUC__)
#define SEASPRING_HD_INLINE inline __attribute__((always_inline))
#else
#define SEASPRING_HD_INLINE inline
#endif
