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
///     ddtgz = -rho0 g_z / B. (DualSPHysics 5.4 writes DDTgz = rho0 g_z / B with drz = z_a - z_b,
///     which has the opposite sign for gravity along -z; we follow the paper's definition.)
/// Boundary neighbours: DensityDT 1 and 2 switch the term off for particle a entirely (any
/// boundary neighbour); 3 ("full") skips only those pairs. Formulas as DualSPHysics 5.4.
#pragma once

#include "core/host_device.h"
#include "physics/sph_types.h"

namespace seaspring::physics {

enum class DensityDiffusion { None = 0, Molteni = 1, Fourtakas = 2, FourtakasFull = 3 };

/// (1 + e)^(1/7) - 1 for small e, in float, by its Taylor series to third order (Horner with
/// fused multiply-adds, fma32: the same bits on every backend; no cancellation, as
/// there would be in computing (1 + e)^(1/7) and subtracting 1). The first omitted term,
/// (65/2401) e^4, is < 2.2e-8 for |e| <= 0.03; the hydrostatic range is
/// |e| = rho0 g |dz| / B = gamma g |dz| / c0^2 ~ 1e-3 over 2h.
SEASPRING_HD inline float seventhRootMinusOne(float e) {
    // Binomial coefficients of (1+e)^(1/7): 1/7, -3/49, 13/343.
    return e * fma32(e, fma32(e, 0.0379008746f, -0.0612244898f), 0.142857143f);
}

/// Hydrostatic density difference rhoH_ab = rho0 ((1 + ddtgz drz)^(1/7) - 1), with
/// ddtgz = -rho0 g_z / B and drz = z_a - z_b.
SEASPRING_HD inline float hydrostaticDensityDifference(float drz, float ddtgz, float rho0) {
    return rho0 * seventhRootMinusOne(ddtgz * drz);
}

/// Molteni & Colagrossi pair term (added to D_a). `ovrho_b` = 1/rho_b, `ov_r2eta` =
/// 1/(r^2 + eta2) (computed once per pair by the caller).
SEASPRING_HD inline float ddtMolteniPair(float rho_a, float ovrho_b, float ov_r2eta, float dot3,
                                         float mass_b, float ddtkh, float cs0) {
    const float visc_densi = ddtkh * cs0 * (rho_a * ovrho_b - 1.f) * ov_r2eta;
    return visc_densi * dot3 * mass_b;
}

/// Fourtakas pair term (added to D_a; the sign convention of DualSPHysics' "deltap1 - delta"
/// is folded in).
SEASPRING_HD inline float ddtFourtakasPair(float rho_a, float rho_b, float ovrho_b, float drz,
                                           float ov_r2eta, float dot3, float mass_b, float ddtkh,
                                           float cs0, float ddtgz, float rho0) {
    const float drho_h = hydrostaticDensityDifference(drz, ddtgz, rho0);
    const float k = -(ddtkh * cs0) * mass_b;  // per particle (hoisted out of the pair loop)
    return (((k * ((rho_b - rho_a) - drho_h)) * ov_r2eta) * dot3) * ovrho_b;
}

}  // namespace seaspring::physics
