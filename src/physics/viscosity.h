// SeaSpring — MIT licence.
/// \file viscosity.h
/// \brief Viscous terms of the momentum equation (DualSPHysics `ViscoTreatment`) and the SPS
///        (Smagorinsky, Dalrymple & Rogers 2006) sub-particle stress.
///
/// r_ab = r_a - r_b, v_ab = v_a - v_b, (frx, fry, frz) = grad_a W_ab, eta2 = 0.01 h^2.
///   1 artificial (Monaghan 1992), only when v_ab . r_ab < 0:
///       a_a -= m_b Pi_ab grad W,  Pi_ab = -alpha c0 mu_ab / rhobar, mu_ab = h v.r/(r^2+eta2),
///       rhobar = (rho_a + rho_b)/2, alpha = Visco (x ViscoBoundFactor for boundary neighbours).
///   3 laminar (Lo & Shao 2002):  a_a += m_b 4 nu (r . grad W) / ((rho_a+rho_b)(r^2+eta2)) v_ab
///   2 laminar + SPS: the laminar term plus m_b (tau_a + tau_b) . grad W, with tau the SPS
///       stress divided by density, computed per particle from the velocity gradient of the
///       previous force evaluation (spsTau).
#pragma once

#include "core/host_device.h"
#include "physics/sph_types.h"

namespace seaspring::physics {

enum class Viscosity { Artificial = 1, LaminarSps = 2, Laminar = 3 };

/// v_ab . r_ab / (r^2 + eta2): the viscous time-step measure of a pair (its maximum over all
/// pairs enters the CFL condition); ov_r2eta = 1/(r^2 + eta2).
SEASPRING_HD inline float viscDtPair(float dot_vr, float ov_r2eta) { return dot_vr * ov_r2eta; }

/// The reciprocals of a pair, from one (the pair loop's only one): D = 1/((r^2 + eta2)(rho_a +
/// rho_b)) through reciprocalNormalRange (the bits of 1.f / x for any argument of a run with
/// finite positive densities, sph_types.h, without the GPU's range check), 1/(r^2 + eta2) = D
/// (rho_a + rho_b) and 1/(rho_a + rho_b) = D (r^2 + eta2). Each term takes what it needs (the
/// rest is never computed): the viscous dt measure and the density diffusion 1/(r^2 + eta2), the
/// artificial viscosity 1/(rho_a + rho_b), the laminar viscosity D.
struct PairReciprocals {
    float ov_r2eta, ov_rhosum, ov_both;
};
SEASPRING_HD inline PairReciprocals pairReciprocals(float rr2, float eta2, float rho_a, float rho_b) {
    const float r2eta = rr2 + eta2, rhosum = rho_a + rho_b;
    const float d = reciprocalNormalRange(r2eta * rhosum);
    return PairReciprocals{d * rhosum, d * r2eta, d};
}

/// Artificial viscosity: the factor s such that a_a -= s * grad W, i.e. m_b Pi_ab with
/// Pi_ab = -alpha c0 h (v_ab.r_ab/(r^2+eta2)) / rhobar, rhobar = (rho_a + rho_b)/2; zero when
/// the pair separates. `visc_dt` = v_ab.r_ab/(r^2+eta2) (viscDtPair), `ov_rhosum` =
/// 1/(rho_a + rho_b), `alpha` already includes ViscoBoundFactor for boundary neighbours.
/// Computed for every pair and selected (no branch: SIMD lanes on the host). (Formed from D =
/// PairReciprocals::ov_both instead, one product less, the SPHERIC benchmark ran 3.5% slower
/// on an H100: docs/performance-large.md, twentieth session.)
SEASPRING_HD inline float artificialViscosityFactor(float visc_dt, float ov_rhosum, float mass_b, float alpha,
                                                    float cs0, float h) {
    const float k = (((-2.f * alpha) * cs0) * h) * mass_b;  // per particle (hoisted out of the pair loop)
    const float s = (k * visc_dt) * ov_rhosum;
    return visc_dt < 0.f ? s : 0.f;
}

/// Laminar viscosity (Lo & Shao): the factor s such that a_a += s * v_ab,
/// s = m_b 4 nu (r.grad W) D, D = 1/((r^2+eta2)(rho_a+rho_b)) (PairReciprocals::ov_both).
SEASPRING_HD inline float laminarViscosityFactor(float dot_rgradw, float ov_both, float mass_b, float nu) {
    const float k = (4.f * nu) * mass_b;  // per particle (hoisted out of the pair loop)
    return (k * ov_both) * dot_rgradw;
}

/// One pair's terms of the velocity-gradient sums that SPS needs (DualSPHysics' layout: xy
/// holds du/dy + dv/dx, and so on): -(m_b/rho_b) v_ab (x) grad W, symmetrised, kept as its two
/// factors u = -v_ab/rho_b and f = m_b grad W (the pair's mass-weighted gradient, which the
/// stress term uses too) and added to the sums as fused multiply-adds (addTo): xx += ux fx,
/// xy += ux fy + uy fx (two fused multiply-adds), and so on; no product rounded on its own.
struct VelocityGradientTerm {
    float ux = 0, uy = 0, uz = 0;
    SEASPRING_HD void addTo(SymTensor& g, float fx, float fy, float fz) const {
        g.xx = fma32(ux, fx, g.xx);
        g.xy = fma32(ux, fy, fma32(uy, fx, g.xy));
        g.xz = fma32(ux, fz, fma32(uz, fx, g.xz));
        g.yy = fma32(uy, fy, g.yy);
        g.yz = fma32(uy, fz, fma32(uz, fy, g.yz));
        g.zz = fma32(uz, fz, g.zz);
    }
};
SEASPRING_HD inline VelocityGradientTerm velocityGradientTerm(float dvx, float dvy, float dvz, float ovrho_b) {
    return VelocityGradientTerm{dvx * -ovrho_b, dvy * -ovrho_b, dvz * -ovrho_b};
}

/// The SPS stress term of a pair, m_b ((tau_a + tau_b) - P I) . grad W = S . f with S the
/// stress with the pressure P = (p_a + p_b)/(rho_a rho_b) on its diagonal and f = m_b grad W,
/// added to the acceleration as fused multiply-adds, row by row (the last column first):
/// a_x = fma(S_xx, f_x, fma(S_xy, f_y, fma(S_xz, f_z, a_x))).
SEASPRING_HD inline void addStressTerm(const SymTensor& st, float fx, float fy, float fz, float& ax, float& ay,
                                       float& az) {
    ax = fma32(st.xx, fx, fma32(st.xy, fy, fma32(st.xz, fz, ax)));
    ay = fma32(st.xy, fx, fma32(st.yy, fy, fma32(st.yz, fz, ay)));
    az = fma32(st.xz, fx, fma32(st.yz, fy, fma32(st.zz, fz, az)));
}

/// SPS stress over density from the velocity gradient sums (DualSPHysics' ComputeSpsTau):
/// smag = (Cs Delta)^2 ... folded as (2/3)... see makeSpsConstants; blin = (2/3) CI Delta^2.
SEASPRING_HD inline SymTensor spsTau(const SymTensor& g, float rho, float smag, float blin) {
    const float pow1 = g.xx * g.xx + g.yy * g.yy + g.zz * g.zz;
    const float prr = pow1 + pow1 + g.xy * g.xy + g.xz * g.xz + g.yz * g.yz;
    const float visc_sps = smag * sqrtf(prr);
    const float div_u = g.xx + g.yy + g.zz;
    const float sps_k = (2.f / 3.f) * visc_sps * div_u;
    const float sps_blin = blin * prr;
    const float sumsps = -(sps_k + sps_blin);
    const float twovisc_sps = visc_sps + visc_sps;
    const float one_rho = 1.f / rho;
    SymTensor t;
    t.xx = one_rho * (twovisc_sps * g.xx + sumsps);
    t.xy = one_rho * (visc_sps * g.xy);
    t.xz = one_rho * (visc_sps * g.xz);
    t.yy = one_rho * (twovisc_sps * g.yy + sumsps);
    t.yz = one_rho * (visc_sps * g.yz);
    t.zz = one_rho * (twovisc_sps * g.zz + sumsps);
    return t;
}

/// SPS constants as DualSPHysics: Delta = dp/sqrt(3) (3D) or dp/sqrt(2) (2D),
/// smag = (0.12 Delta)^2, blin = (2/3) 0.0066 Delta^2 (host only).
struct SpsConstants {
    float smag = 0, blin = 0;
};
inline SpsConstants makeSpsConstants(double dp, int dimensions) {
    const double delta = dimensions == 2 ? dp / 1.4142135623730951 : dp / 1.7320508075688772;
    SpsConstants c;
    c.smag = float((0.12 * delta) * (0.12 * delta));
    c.blin = float((2.0 / 3.0) * 0.0066 * delta * delta);
    return c;
}

}  // namespace seaspring::physics
