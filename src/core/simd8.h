// SeaSpring — MIT licence.
/// \file simd8.h
/// \brief Eight float and int lanes (AVX2 and FMA) for the host's pair loops: the same formula,
///        written once for a float (physics/neighbour_rows.h, physics/cell_grid.h), evaluated
///        for eight candidates or eight rows of cells at a time. Each lane's operations are the
///        scalar ones (IEEE subtraction, sum, product, fused multiply-add, square root, floor,
///        exact int-to-float conversion of small integers, ordered comparisons, selects, int
///        sums, products' low bits, minima and maxima), so every lane gives the scalar bits.
///        Only where the host compiler (not nvcc) targets AVX2 and FMA: SEASPRING_SIMD8 is
///        then 1, otherwise the scalar loops run.
#pragma once

#if !defined(__CUDACC__) && defined(__AVX2__) && defined(__FMA__)
#define SEASPRING_SIMD8 1
#include <immintrin.h>

#include <cstdint>

namespace seaspring::simd {

struct Vec8f {
    __m256 v;
    Vec8f() = default;
    Vec8f(__m256 x) : v(x) {}                    // NOLINT: a lane vector is its register
    Vec8f(float s) : v(_mm256_set1_ps(s)) {}     // NOLINT: a scalar operand is broadcast
};
struct Vec8i {
    __m256i v;
    Vec8i() = default;
    Vec8i(__m256i x) : v(x) {}                  // NOLINT: a lane vector is its register
    Vec8i(int s) : v(_mm256_set1_epi32(s)) {}    // NOLINT: a scalar operand is broadcast
};
/// A lane mask from a comparison (all bits set where it holds).
struct Mask8 {
    __m256 v;
    /// Bit k set where lane k holds.
    unsigned bits() const { return unsigned(_mm256_movemask_ps(v)); }
};
/// Lanes k = 0..7 (base + k).
inline Vec8i iota(int base) {
    return _mm256_add_epi32(_mm256_set1_epi32(base), _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7));
}

inline Vec8f operator-(Vec8f a, Vec8f b) { return _mm256_sub_ps(a.v, b.v); }
inline Vec8f operator*(Vec8f a, Vec8f b) { return _mm256_mul_ps(a.v, b.v); }
inline Vec8f fma32(Vec8f a, Vec8f b, Vec8f c) { return _mm256_fmadd_ps(a.v, b.v, c.v); }
inline Vec8f operator+(Vec8f a, Vec8f b) { return _mm256_add_ps(a.v, b.v); }
inline Vec8i operator-(Vec8i a, Vec8i b) { return _mm256_sub_epi32(a.v, b.v); }
inline Vec8i operator+(Vec8i a, Vec8i b) { return _mm256_add_epi32(a.v, b.v); }
/// The low 32 bits of the product, as the scalar (unsigned) int product.
inline Vec8i operator*(Vec8i a, Vec8i b) { return _mm256_mullo_epi32(a.v, b.v); }
inline Vec8i maxi(Vec8i a, Vec8i b) { return _mm256_max_epi32(a.v, b.v); }
inline Vec8i mini(Vec8i a, Vec8i b) { return _mm256_min_epi32(a.v, b.v); }
/// The IEEE square root (correctly rounded, as sqrtf).
inline Vec8f sqrtIeee(Vec8f x) { return _mm256_sqrt_ps(x.v); }
/// int(floorf(x)) of each lane (x finite and in int range; other lanes are left undefined).
inline Vec8i floorToInt(Vec8f x) { return _mm256_cvttps_epi32(_mm256_floor_ps(x.v)); }
/// Exact for |x| < 2^24 (cell coordinates), as float(x).
inline Vec8f toFloat(Vec8i x) { return _mm256_cvtepi32_ps(x.v); }
/// Ordered comparisons: false for a NaN lane, as the scalar <= and >=.
inline Mask8 operator<=(Vec8f a, Vec8f b) { return Mask8{_mm256_cmp_ps(a.v, b.v, _CMP_LE_OQ)}; }
inline Mask8 operator>=(Vec8f a, Vec8f b) { return Mask8{_mm256_cmp_ps(a.v, b.v, _CMP_GE_OQ)}; }
inline Mask8 operator>(Vec8f a, Vec8f b) { return Mask8{_mm256_cmp_ps(a.v, b.v, _CMP_GT_OQ)}; }
inline Mask8 operator>(Vec8i a, Vec8i b) { return Mask8{_mm256_castsi256_ps(_mm256_cmpgt_epi32(a.v, b.v))}; }
inline Mask8 operator<(Vec8i a, Vec8i b) { return b > a; }
inline Mask8 operator<=(Vec8i a, Vec8i b) {
    return Mask8{_mm256_castsi256_ps(_mm256_xor_si256(_mm256_cmpgt_epi32(a.v, b.v), _mm256_set1_epi32(-1)))};
}
/// Lane-wise: both masks hold (no short circuit: both sides are lane masks).
inline Mask8 operator&&(Mask8 a, Mask8 b) { return Mask8{_mm256_and_ps(a.v, b.v)}; }
/// a where m holds, b elsewhere (the scalar m ? a : b).
inline Vec8f choose(Mask8 m, Vec8f a, Vec8f b) { return _mm256_blendv_ps(b.v, a.v, m.v); }
/// The bits of each lane, and the low bits under `mask`.
inline Vec8i bitsAnd(Vec8f x, std::uint32_t mask) {
    return Vec8i{_mm256_and_si256(_mm256_castps_si256(x.v), _mm256_set1_epi32(int(mask)))};
}

/// Eight consecutive 16-byte records (x, y, z, w) as four lane vectors; records k >= cnt are
/// not read (their lanes hold zeros).
struct Quad8 {
    Vec8f x, y, z, w;
};
/// Records k and k + 4 in ak (k = 0..3: low and high halves) as four lane vectors.
inline Quad8 transposeQuads(__m256 a0, __m256 a1, __m256 a2, __m256 a3) {
    const __m256 t0 = _mm256_unpacklo_ps(a0, a1), t1 = _mm256_unpackhi_ps(a0, a1);
    const __m256 t2 = _mm256_unpacklo_ps(a2, a3), t3 = _mm256_unpackhi_ps(a2, a3);
    return Quad8{_mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(1, 0, 1, 0)), _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(3, 2, 3, 2)),
                 _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(1, 0, 1, 0)), _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(3, 2, 3, 2))};
}
inline Quad8 loadQuads(const float* p, int cnt) {
    __m128 q[8];
    for (int k = 0; k < 8; ++k) {
        const __m128i m = _mm_set1_epi32(k < cnt ? -1 : 0);
        q[k] = _mm_maskload_ps(p + 4 * k, m);  // masked lanes do not fault
    }
    const __m256 a0 = _mm256_set_m128(q[4], q[0]), a1 = _mm256_set_m128(q[5], q[1]);
    const __m256 a2 = _mm256_set_m128(q[6], q[2]), a3 = _mm256_set_m128(q[7], q[3]);
    return transposeQuads(a0, a1, a2, a3);
}
/// loadQuads of eight records, all read (p[0, 32) must be readable).
inline Quad8 loadQuads(const float* p) {
    const __m256 a0 = _mm256_loadu2_m128(p + 16, p), a1 = _mm256_loadu2_m128(p + 20, p + 4);
    const __m256 a2 = _mm256_loadu2_m128(p + 24, p + 8), a3 = _mm256_loadu2_m128(p + 28, p + 12);
    return transposeQuads(a0, a1, a2, a3);
}
inline void store(float* p, Vec8f x) { _mm256_storeu_ps(p, x.v); }
/// Eight floats p[0..7] (unaligned).
inline Vec8f load(const float* p) { return _mm256_loadu_ps(p); }

/// For each 8-bit lane mask, the lanes it holds in ascending order (then zeros): the permutation
/// that packs the selected lanes to the front.
struct LeftPackTable {
    alignas(32) std::int32_t idx[256][8];
};
constexpr LeftPackTable makeLeftPackTable() {
    LeftPackTable t{};  // zeros after each mask's lanes
    for (int m = 0; m < 256; ++m)
        for (int k = 0, n = 0; k < 8; ++k)
            if ((m >> k) & 1) t.idx[m][n++] = k;
    return t;
}
inline constexpr LeftPackTable kLeftPack = makeLeftPackTable();

/// The lanes of `x` selected by `mask` (bit k: lane k), in ascending order, stored at p[0, n)
/// (n = the mask's set bits); p[n, 8) is overwritten with other lanes: p needs room for 8.
inline void leftPackStore(float* p, Vec8f x, unsigned mask) {
    const __m256i perm = _mm256_load_si256(reinterpret_cast<const __m256i*>(kLeftPack.idx[mask]));
    _mm256_storeu_ps(p, _mm256_permutevar8x32_ps(x.v, perm));
}
/// The same for integer lanes.
inline void leftPackStore(std::uint32_t* p, Vec8i x, unsigned mask) {
    const __m256i perm = _mm256_load_si256(reinterpret_cast<const __m256i*>(kLeftPack.idx[mask]));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(p), _mm256_permutevar8x32_epi32(x.v, perm));
}
/// The same for the integers base + k of lanes k (candidate numbers), masked by `andmask`.
inline void leftPackStoreIota(std::uint32_t* p, std::uint32_t base, std::uint32_t andmask, unsigned mask) {
    const __m256i perm = _mm256_load_si256(reinterpret_cast<const __m256i*>(kLeftPack.idx[mask]));
    const __m256i v = _mm256_and_si256(_mm256_add_epi32(_mm256_set1_epi32(int(base)), perm),
                                       _mm256_set1_epi32(int(andmask)));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(p), v);
}

}  // namespace seaspring::simd

#else
#define SEASPRING_SIMD8 0
#endif
