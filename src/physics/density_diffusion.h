// SeaSpring — MIT licence.
/// \file density_diffusion.h
/// \brief Density diffusion terms (DualSPHysics `DensityDT`) added to the continuity equation.
///
/// Per pair (a = particle, b = neighbour), with r_ab = r_a - r_b, F the kernel gradient factor
/// and dot3 = r_ab . grad_a W = F |r_ab|^2, coefficient ddtkh = delta * 2h, c0 = reference
/// sound speed, eta2 = 0.01 h^2:
///   1 Molteni & Colagrossi (2009): D_a += ddtkh c0 (rho_a/rho_b - 1)/(r^2+eta2) dot3 m_b
///   2/3 Fourtakas et al. (2019):   D_a -= ddtkh c0 ((rho_b - rho_a) - rhoH_ab)/(r^2+eta2)
///                                        dot3 m_b/rho_b,
///     rhoH_ab = rho0 ((1 + rho0 |g| (z_a - z_b)/B)^(1/7) - 1), the hydrostatic density difference
///     rho_b^H - rho_a^H, so the term vanishes in a fluid at hydrostatic rest (tested).
///     ddtgz = -rho0 g_z / B; rhoH_ab is evaluated as a cubic in (z_a - z_b) (HydrostaticCubic).
///     (DualSPHysics 5.4 writes DDTgz = rho0 g_z / B with drz = z_a - z_b,
///     which has the opposite sign for gravity along -z; we follow the paper's definition.)
/// Boundary neighbours: DensityDT 1 and 2 switch the term off for particle a entirely (any
/// boundary neighbour); 3 ("full") skips only those pairs. Formulas as DualSPHysics 5.4.
#pragma once

#include "core/host_device.h"
#include "physics/sph_types.h"

namespace seaspring::physics {

enum class DensityDiffusion { None = 0, Molteni = 1, Fourtakas = 2, FourtakasFull = 3 };

/// The hydrostatic density difference rhoH_ab = rho0 ((1 + e)^(1/7) - 1), e = ddtgz drz
/// (ddtgz = -rho0 g_z / B, drz = z_a - z_b), as a cubic in drz: the Taylor series of
/// (1 + e)^(1/7) - 1 to third order (binomial coefficients 1/7, -3/49, 13/343), with rho0 and the
/// powers of ddtgz folded into its coefficients on the host (makeHydrostaticCubic, in double), so
/// that a pair evaluates it with two fused multiply-adds (Horner, fma32: the same bits on every
/// backend; no cancellation, as there would be in computing (1 + e)^(1/7) and subtracting 1). The
/// first omitted term, (65/2401) e^4, is < 2.2e-8 of rho0 for |e| <= 0.03; the hydrostatic range
/// is |e| = rho0 g |dz| / B = gamma g |dz| / c0^2 ~ 1e-3 over 2h.
struct HydrostaticCubic {
    float c1 = 0, c2 = 0, c3 = 0;  ///< rhoH_ab = drz (c1 + drz (c2 + drz c3))
};

/// The coefficients for ddtgz and rho0 (host).
inline HydrostaticCubic makeHydrostaticCubic(double ddtgz, double rho0) {
    HydrostaticCubic k;
    k.c1 = float(rho0 * ddtgz / 7.0);
    k.c2 = float(-rho0 * ddtgz * ddtgz * 3.0 / 49.0);
    k.c3 = float(rho0 * ddtgz * ddtgz * ddtgz * 13.0 / 343.0);
    return k;
}

/// rhoH_ab / drz: the cubic's quotient, c1 + drz (c2 + drz c3).
SEASPRING_HD inline float hydrostaticQuotient(float drz, const HydrostaticCubic& k) {
    return fma32(drz, fma32(drz, k.c3, k.c2), k.c1);
}

/// The hydrostatic density difference rhoH_ab for drz = z_a - z_b.
SEASPRING_HD inline float hydrostaticDensityDifference(float drz, const HydrostaticCubic& k) {
    return drz * hydrostaticQuotient(drz, k);
}

/// Molteni & Colagrossi pair term (added to D_a, as ProductTerm::addTo). `ovrho_b` = 1/rho_b,
/// `ov_r2eta` = 1/(r^2 + eta2) (computed once per pair by the caller).
SEASPRING_HD inline ProductTerm ddtMolteniPair(float rho_a, float ovrho_b, float ov_r2eta, float dot3,
                                               float mass_b, float ddtkh, float cs0) {
    const float visc_densi = ddtkh * cs0 * (rho_a * ovrho_b - 1.f) * ov_r2eta;
    return ProductTerm{visc_densi * dot3, mass_b};
}

/// Fourtakas pair term (added to D_a, as ProductTerm::addTo; the sign convention of
/// DualSPHysics' "deltap1 - delta" is folded in). (rho_b - rho_a) - rhoH_ab is one fused
/// multiply-add of drz with the cubic's quotient.
SEASPRING_HD inline ProductTerm ddtFourtakasPair(float rho_a, float rho_b, float ovrho_b, float drz,
                                                 float ov_r2eta, float dot3, float mass_b, float ddtkh,
                                                 float cs0, const HydrostaticCubic& hyd) {
    const float excess = fma32(-drz, hydrostaticQuotient(drz, hyd), rho_b - rho_a);
    const float k = -(ddtkh * cs0) * mass_b;  // per particle (hoisted out of the pair loop)
    return ProductTerm{((k * excess) * ov_r2eta) * dot3, ovrho_b};
}

}  // namespace seaspring::physics
