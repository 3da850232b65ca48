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

/// Symmetric 3x3 tensor of floats (SPS stress and velocity gradient). Aligned to 8 bytes (its
/// size stays 24), so that the GPU loads a neighbour's stress in three 8-byte loads, not six.
struct alignas(8) SymTensor {
    float xx, xy, xz, yy, yz, zz;
};
static_assert(sizeof(SymTensor) == 24, "SymTensor: six floats, no padding");

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

/// A pair's term formed as the product v w and added to its particle's sum as fma32(v, w, sum):
/// one rounding, and one instruction, less than forming the product first (fluid_pair_terms.h).
struct ProductTerm {
    float v = 0, w = 0;
    SEASPRING_HD float value() const { return v * w; }
    SEASPRING_HD float addTo(float sum) const { return fma32(v, w, sum); }
};

/// The range of sqrtNormalRange: [2^-100, 2^126).
constexpr float kSqrtNormalRangeMin = 7.88860905e-31f;  // 2^-100
constexpr float kSqrtNormalRangeEnd = 8.50705917e37f;   // 2^126

/// sqrtf(x), the same bits, for x in [kSqrtNormalRangeMin, kSqrtNormalRangeEnd): for a
/// neighbour pair's r^2, which isNeighbour keeps in [kAlmostZero, (2h)^2]. On the GPU it is the
/// fast path of CUDA's IEEE square root alone, without the range check and the branch around
/// it (5 of the 93 instructions of a fluid pair): an approximate reciprocal square root r
/// (MUFU.RSQ), s = x r, then s + (x - s^2) r/2 with the residual exact in one fma. For x in the
/// range that sequence is correctly rounded; `deviceSqrtNormalRangeMismatches` (core/device_math_check.h)
/// compares it with sqrtf on the device for every float in the range (test
/// DeviceMath.SqrtNormalRangeIsSqrtfForEveryFloatInRange). Outside the range the results differ
/// (0 gives NaN): callers with r = 0 (mDBC's ghost node) use sqrtf. On the host: sqrtf.
SEASPRING_HD_INLINE float sqrtNormalRange(float x) {
#if defined(__CUDA_ARCH__)
    float y;
    asm("{\n\t"
        ".reg .f32 r, s, h, e;\n\t"
        "rsqrt.approx.ftz.f32 r, %1;\n\t"
        "mul.ftz.f32 s, %1, r;\n\t"
        "mul.ftz.f32 h, r, 0f3F000000;\n\t"
        "neg.f32 e, s;\n\t"
        "fma.rn.f32 e, e, s, %1;\n\t"
        "fma.rn.f32 %0, e, h, s;\n\t"
        "}"
        : "=f"(y)
        : "f"(x));
    return y;
#else
    return sqrtf(x);
#endif
}

/// Where reciprocalNormalRange is 1/x: |x| in [2^-126, 2^126].
constexpr float kReciprocalNormalRangeMin = 1.17549435e-38f;  // 2^-126
constexpr float kReciprocalNormalRangeMax = 8.50705917e37f;   // 2^126

/// reciprocalNormalRange's values, the definition on both backends: 1.f / x (IEEE, correctly
/// rounded) for |x| in [2^-126, 2^126]; +-0 (x's sign) for finite |x| above 2^126, where 1/x is
/// subnormal; NaN (bits 0x7fffffff) for 0, subnormals, infinities and NaN. The host evaluates
/// this; `deviceReciprocalNormalRangeMismatches` (core/device_math_check.h) checks, for every one of
/// the 2^32 floats, that the GPU's sequence gives these bits.
SEASPRING_HD_INLINE float reciprocalNormalRangeSpec(float x) {
    const float ax = fabsf(x);
    if (ax >= kReciprocalNormalRangeMin && ax <= kReciprocalNormalRangeMax) return 1.f / x;
    if (ax > kReciprocalNormalRangeMax && ax <= 3.40282347e38f) return x > 0.f ? 0.f : -0.f;
    return uintBitsToFloat(0x7fffffffu);
}

/// 1/x for the pair loops, whose arguments ((r^2 + eta^2)(rho_a + rho_b), r^2 + eta^2) lie far
/// inside [2^-126, 2^126] in any run with finite positive densities: reciprocalNormalRangeSpec's
/// bits on both backends. On the GPU it is the fast path of CUDA's IEEE reciprocal alone, without
/// its range check and the branch around it: an approximate reciprocal r (MUFU.RCP, subnormal
/// results flushed to 0), then r + r (1 - x r) with the residual exact in one fma; outside the
/// range that sequence gives the spec's NaN and zeros. On the host: the spec.
SEASPRING_HD_INLINE float reciprocalNormalRange(float x) {
#if defined(__CUDA_ARCH__)
    float y;
    asm("{\n\t"
        ".reg .f32 r, e;\n\t"
        "rcp.approx.ftz.f32 r, %1;\n\t"
        "neg.f32 e, %1;\n\t"
        "fma.rn.f32 e, e, r, 0f3F800000;\n\t"
        "fma.rn.f32 %0, r, e, r;\n\t"
        "}"
        : "=f"(y)
        : "f"(x));
    return y;
#else
    return reciprocalNormalRangeSpec(x);
#endif
}

SEASPRING_HD inline int maxi(int a, int b) { return a > b ? a : b; }
SEASPRING_HD inline int mini(int a, int b) { return a < b ? a : b; }

}  // namespace seaspring::physics
