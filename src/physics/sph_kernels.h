// SeaSpring — MIT licence.
/// \file sph_kernels.h
/// \brief Smoothing kernels with support 2h, as DualSPHysics implements them: Wendland C2
///        (Kernel=2) and the cubic spline with Monaghan's tensile correction (Kernel=1).
///
/// W(r) and the gradient factor F(r) = (dW/dr)/r, so that grad_a W_ab = F(r_ab) r_ab with
/// r_ab = r_a - r_b. Evaluated in float; the normalisations for 2D and 3D are folded into
/// KernelConstants (filled on the host by makeKernelConstants).
///   Wendland: W = aD (1 - q/2)^4 (2q + 1), q = r/h;  F = -5 aD/h^2 (1 - q/2)^3, its 1 - q/2
///             formed as fma(r, -1/(2h), 1) (one rounding; the pair loops' instruction count),
///             aD = 7/(4 pi h^2) in 2D, 21/(16 pi h^3) in 3D.
///   Cubic:    W = a2 (1 - 1.5 q^2 + 0.75 q^3) for q <= 1, a2/4 (2 - q)^3 for 1 < q <= 2,
///             a2 = 10/(7 pi h^2) in 2D, 1/(pi h^3) in 3D.
#pragma once

#include <cmath>

#include "core/host_device.h"
#include "physics/sph_types.h"

namespace seaspring::physics {

/// Kernel constants (float, as used per pair).
struct KernelConstants {
    float h = 0;            ///< smoothing length [m]
    float ovh = 0;          ///< 1/h
    float mhalfovh = 0;     ///< -1/(2h): Wendland's 1 - q/2 = fma(r, mhalfovh, 1)
    float kernelsize2 = 0;  ///< (2h)^2
    float awen = 0;         ///< Wendland normalisation aD
    float bwen = 0;         ///< Wendland gradient constant -5 aD / h^2
    float cubic_a2 = 0;     ///< cubic normalisation a2
    float cubic_a24 = 0;    ///< a2 / 4
    float cubic_c1 = 0;     ///< -3 a2/h
    float cubic_d1 = 0;     ///< 9/4 a2/h
    float cubic_c2 = 0;     ///< -3/4 a2/h
    float cubic_odwdeltap = 0;  ///< 1 / W(dp), for the tensile correction
};

/// Pairs closer than this (squared distance) are skipped, as DualSPHysics' ALMOSTZERO.
constexpr float kAlmostZero = 1e-18f;
// A neighbour's r^2, in [kAlmostZero, (2h)^2], is inside sqrtNormalRange's range (gradFactor<true>)
// for any h below 4e18 m.
static_assert(kAlmostZero >= kSqrtNormalRangeMin, "a neighbour's r^2 must lie in sqrtNormalRange's range");

enum class KernelType { Cubic = 1, Wendland = 2 };

struct WendlandKernel {
    static constexpr KernelType kType = KernelType::Wendland;
    /// W(r) for r^2 = rr2 (caller guarantees rr2 <= (2h)^2).
    SEASPRING_HD static float value(float rr2, const KernelConstants& k) {
        const float qq = sqrtf(rr2) * k.ovh;
        const float wqq1 = 1.f - 0.5f * qq;
        const float wqq2 = wqq1 * wqq1;
        return k.awen * (2.f * qq + 1.f) * (wqq2 * wqq2);
    }
    /// F(r) = (dW/dr)/r. kNeighbour: rr2 is a neighbour pair's (isNeighbour), whose square root
    /// sqrtNormalRange takes with the same bits as sqrtf and fewer GPU instructions.
    template <bool kNeighbour = false>
    SEASPRING_HD static float gradFactor(float rr2, const KernelConstants& k) {
        const float wqq1 = fma32(kNeighbour ? sqrtNormalRange(rr2) : sqrtf(rr2), k.mhalfovh, 1.f);
        return k.bwen * (wqq1 * wqq1 * wqq1);
    }
};

struct CubicKernel {
    static constexpr KernelType kType = KernelType::Cubic;
    SEASPRING_HD static float value(float rr2, const KernelConstants& k) {
        const float qq = sqrtf(rr2) * k.ovh;
        if (qq > 1.f) {
            const float wqq1 = 2.f - qq;
            return k.cubic_a24 * (wqq1 * wqq1 * wqq1);
        }
        const float wqq2 = qq * qq;
        return k.cubic_a2 * (1.f - 1.5f * wqq2 + 0.75f * (wqq2 * qq));
    }
    /// F(r) = (dW/dr)/r; kNeighbour as WendlandKernel's.
    template <bool kNeighbour = false>
    SEASPRING_HD static float gradFactor(float rr2, const KernelConstants& k) {
        const float rad = kNeighbour ? sqrtNormalRange(rr2) : sqrtf(rr2);
        const float qq = rad * k.ovh;
        if (qq > 1.f) {
            const float wqq1 = 2.f - qq;
            return k.cubic_c2 * (wqq1 * wqq1) / rad;
        }
        return (k.cubic_c1 * qq + k.cubic_d1 * (qq * qq)) / rad;
    }
    /// Monaghan's tensile correction added to (p_a + p_b)/(rho_a rho_b):
    /// (W/W(dp))^4 * (f_a + f_b), f = p/rho^2 * (0.01 if p > 0 else -0.2).
    SEASPRING_HD static float tensileCorrection(float rr2, float press_a, float rho_a,
                                                float press_b, float rho_b,
                                                const KernelConstants& k) {
        float fab = value(rr2, k) * k.cubic_odwdeltap;
        fab *= fab;
        fab *= fab;
        const float ta = (press_a / (rho_a * rho_a)) * (press_a > 0.f ? 0.01f : -0.2f);
        const float tb = (press_b / (rho_b * rho_b)) * (press_b > 0.f ? 0.01f : -0.2f);
        return fab * (ta + tb);
    }
};

/// Fills the constants for smoothing length h, particle spacing dp, dimensions 2 or 3
/// (host only; library math is fine here: the values are computed once and shared).
inline KernelConstants makeKernelConstants(double h, double dp, int dimensions) {
    const double pi = 3.14159265358979323846;
    KernelConstants k;
    k.h = float(h);
    k.ovh = float(1.0 / h);
    k.mhalfovh = float(-0.5 / h);
    k.kernelsize2 = float((2.0 * h) * (2.0 * h));
    const double awen = dimensions == 2 ? 7.0 / (4.0 * pi * h * h)
                                        : 21.0 / (16.0 * pi * h * h * h);
    k.awen = float(awen);
    k.bwen = float(-5.0 * awen / (h * h));
    const double a1 = dimensions == 2 ? 10.0 / (7.0 * pi) : 1.0 / pi;
    const double a2 = dimensions == 2 ? a1 / (h * h) : a1 / (h * h * h);
    const double aa = a2 / h;
    k.cubic_a2 = float(a2);
    k.cubic_a24 = float(0.25 * a2);
    k.cubic_c1 = float(-3.0 * aa);
    k.cubic_d1 = float(9.0 / 4.0 * aa);
    k.cubic_c2 = float(-0.75 * aa);
    const double q = dp / h;
    const double wdp = q > 1.0 ? 0.25 * a2 * (2.0 - q) * (2.0 - q) * (2.0 - q)
                               : a2 * (1.0 - 1.5 * q * q + 0.75 * q * q * q);
    k.cubic_odwdeltap = float(1.0 / wdp);
    return k;
}

}  // namespace seaspring::physics
