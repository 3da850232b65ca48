// SeaSpring — MIT licence.
/// \file sph_types.h
/// \brief Plain per-particle value types shared by the CPU and CUDA drivers (16-byte aligned
///        so that the GPU loads them in one instruction), and exact float/uint bit casts.
#pragma once

#include <cstdint>
#include <cmath>
#include <cstring>

#include "core/host_device.h"

namespace seaspring::physics {

/// Four floats in one 16-byte word: (x, y, z, w).
struct alignas(16) Float4 {
    float x, y, z, w;
};

/// Two floats in one 8-byte word.
struct alignas(8) Float2 {
    float x, y;
};

/// A double-precision position.
struct Double3 {
    double x, y, z;
};

/// Symmetric 3x3 tensor of floats (SPS stress and velocity gradient).
struct SymTensor {
    float xx, xy, xz, yy, yz, zz;
};

/// The bits of `v` as a float (no conversion).
SEASPRING_HD inline float uintBitsToFloat(std::uint32_t v) {
#if defined(__CUDA_ARCH__)
    return __uint_as_float(v);
#else
    float f;
    std::memcpy(&f, &v, sizeof f);
    return f;
#endif
}

/// The bits of `f` as an unsigned integer (no conversion).
SEASPRING_HD inline std::uint32_t floatBitsToUint(float f) {
#if defined(__CUDA_ARCH__)
    return __float_as_uint(f);
#else
    std::uint32_t v;
    std::memcpy(&v, &f, sizeof v);
    return v;
#endif
}

/// max(a, b) that ignores a NaN in b (a is never NaN where used: it starts at 0).
SEASPRING_HD inline float maxf(float a, float b) { return b > a ? b : a; }
/// a*b + c with a single rounding (IEEE fused multiply-add): the same bits on the CPU (hardware
/// FMA, or glibc's exact fmaf) and the GPU. Used where we want a fused operation, explicitly,
/// since contraction is otherwise off on both sides.
SEASPRING_HD inline float fma32(float a, float b, float c) { return fmaf(a, b, c); }

SEASPRING_HD inline int maxi(int a, int b) { return a > b ? a : b; }
SEASPRING_HD inline int mini(int a, int b) { return a < b ? a : b; }

}  // namespace seaspring::physics
