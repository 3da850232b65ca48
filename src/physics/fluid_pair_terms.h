// SeaSpring — MIT licence.
/// \file fluid_pair_terms.h
/// \brief What every fluid pair interaction is made of, on both backends: the read-only
///        inputs, the terms of one pair (pressure, viscosity, continuity, density diffusion,
///        SPS, viscous dt), the pair's acceleration and their sum. The neighbour search (rows,
///        candidates, pair offset, neighbour test) is neighbour_rows.h; the loops over
///        neighbours that call these are in fluid_interaction.h and solid_coupling.h.
#pragma once

#include <cstdint>
#include <type_traits>

#include "physics/cell_grid.h"
#include "physics/eos_tait.h"
#include "physics/fluid_constants.h"
#include "physics/neighbour_rows.h"
#include "physics/particle_updates.h"
#include "physics/sph_types.h"

namespace seaspring::physics {

/// Read-only inputs of the interaction (sorted order).
struct InteractionInputs {
    const Float4* poscell = nullptr;
    const Float4* velrho = nullptr;
    const std::uint32_t* cell_start_bound = nullptr;  ///< ncells+1 first indices per cell
    const std::uint32_t* cell_start_fluid = nullptr;  ///< ncells+1 first indices per cell
    const SymTensor* tau = nullptr;                   ///< SPS stress/rho, per particle (SPS only)
    const Float2* press_ovrho = nullptr;              ///< (Tait pressure, 1/rho) per particle
    /// Per cell: kNearBound / kNearFluid, a boundary / fluid particle in its search box
    /// (nearAlongXAt, nearAlongYSegment, nearAlongZSegment); null: visit always.
    const std::uint8_t* near = nullptr;
    /// mDBC SlipMode 2/3 (null otherwise): per boundary particle, the velocity its viscous
    /// terms use (the tangential ghost velocity, mdbc.h); its velrho keeps the wall's.
    const Float4* bound_visc_vel = nullptr;
    /// The host's row extents of this evaluation, both blocks' joined (row_extents.h; none on the
    /// GPU): its row table (RowTable) tests rows against them.
    RowExtents row_ext;
    /// The GPU's extents of the boundary block's rows (its walls keep their lattice): its walk of
    /// that block tests rows against them (forEachCandidateRowInExtents); none on the host.
    RowExtents bound_ext;
    /// The GPU's extents of the fluid block's rows at this evaluation (none on the host): its
    /// walks of that block test rows against them (forEachCandidateRowInExtents).
    RowExtents fluid_ext;
};

/// (p, 1/rho) of particle i, computed once per force evaluation before the pair loops.
SEASPRING_HD inline void pressureAt(std::uint32_t i, const ParticleView& v, const FluidConstants& c) {
    const float rho = v.velrho[i].w;
    v.press_ovrho[i] = Float2{taitPressure7(rho, c.cteb, c.ovrhop0), 1.f / rho};
}

/// What a fluid particle's force evaluation produces.
struct FluidAccum {
    float ax = 0, ay = 0, az = 0;  ///< acceleration without gravity [m/s^2]
    float ar = 0;                  ///< continuity d(rho)/dt [kg/m^3/s]
    float delta = 0;               ///< density diffusion sum
    float visc = 0;                ///< max v.r/(r^2+eta2) over pairs
    bool ddt_off = false;          ///< DensityDT 1/2: a boundary neighbour switches DDT off
    SymTensor gradvel{0, 0, 0, 0, 0, 0};  ///< SPS velocity gradient sums
};

/// What pair (a, b) adds to fluid particle a, before it is summed (addPairTerms).
struct PairTerms {
    /// Without SPS: r_ab, and cf the coefficient of grad W_ab (pressure, artificial viscosity)
    /// times the kernel's gradient factor F (grad W_ab = F r_ab): one product per pair instead
    /// of grad W's three; dv_a/dt gets cf m. With SPS: f = m_b grad W_ab, which the stress st
    /// multiplies (addStressTerm) and the velocity-gradient term's u (cf not formed).
    float mx, my, mz;
    float cf;
    float cv;              ///< coefficient of v_ab in dv_a/dt (laminar viscosity)
    float dvx, dvy, dvz;   ///< v_ab (laminar)
    ProductTerm ar;        ///< continuity term of d(rho_a)/dt (summed as ProductTerm::addTo)
    ProductTerm delta;     ///< density diffusion term (likewise)
    float visc;            ///< viscous dt measure v_ab.r_ab / (r^2 + eta2)
    SymTensor st;          ///< SPS: (tau_a + tau_b) - P I, P = (p_a + p_b)/(rho_a rho_b)
    VelocityGradientTerm gv;  ///< SPS velocity-gradient term (its f is m above)
};

/// The terms of pair (a, b): b = j at offset (drx, dry, drz) from a, rr2 = r^2, inside the
/// support. `kBound`: b is a boundary particle. No branches on data (selects only), so the
/// host can evaluate a batch of pairs in SIMD lanes with the same bits as one by one.
template <class Opt, bool kBound>
SEASPRING_HD inline PairTerms fluidPairTerms(std::uint32_t j, float drx, float dry, float drz, float rr2,
                                             const Float4& va, float ovrhoa, float pressa,
                                             const SymTensor& taua, const InteractionInputs& in,
                                             const FluidConstants& c) {
    using K = typename Opt::Kernel;
    const float massb = kBound ? c.massbound : c.massfluid;
    const float visco = kBound ? c.visco_bound : c.visco;
    PairTerms t;
    const float fac = K::template gradFactor<true>(rr2, c.ker);  // grad W_ab = fac r_ab
    const Float4 vb = in.velrho[j];
    const Float2 pb2 = in.press_ovrho[j];
    const float pressb = pb2.x, ovrhob = pb2.y;
    const PairReciprocals rec = pairReciprocals(rr2, c.eta2, va.w, vb.w);
    const float ov_r2eta = rec.ov_r2eta;

    // Pressure (its coefficient of grad W, -m_b prs, is formed below with the artificial
    // viscosity's).
    float prs = (pressa + pressb) * (ovrhoa * ovrhob);
    if (K::kType == KernelType::Cubic)
        prs += CubicKernel::tensileCorrection(rr2, pressa, va.w, pressb, vb.w, c.ker);

    // Continuity: v_ab . grad W = fac (v_ab . r_ab).
    const float dvx = va.x - vb.x, dvy = va.y - vb.y, dvz = va.z - vb.z;
    const float dvdr = fma32(drx, dvx, fma32(dry, dvy, drz * dvz));
    const float dot_vf = fac * dvdr;
    t.ar = ProductTerm{dot_vf, ovrhob * (massb * va.w)};  // massb * rho_a: per particle

    // Viscous time-step measure and viscosity: against an mDBC SlipMode 2/3 boundary particle,
    // its viscous velocity (DualSPHysics' tangenvel), the wall's in the continuity term above.
    float wvx = dvx, wvy = dvy, wvz = dvz;
    float dot_vr = dvdr;
    if (kBound && in.bound_visc_vel) {
        const Float4 vv = in.bound_visc_vel[j];
        wvx = va.x - vv.x;
        wvy = va.y - vv.y;
        wvz = va.z - vv.z;
        dot_vr = fma32(drx, wvx, fma32(dry, wvy, drz * wvz));
    }
    const float dot3 = fac * rr2;  // r . grad W = fac |r|^2
    t.visc = viscDtPair(dot_vr, ov_r2eta);
    if (Opt::visco == Viscosity::Artificial) {
        // -m_b prs - s in one fused multiply-add.
        t.cf = fma32(-prs, massb, -artificialViscosityFactor(t.visc, rec.ov_rhosum, massb, visco, c.cs0, c.ker.h));
    } else {
        if (!Opt::sps) t.cf = -prs * massb;  // with SPS the pressure joins the stress (st)
        t.cv = laminarViscosityFactor(dot3, rec.ov_both, massb, visco);
        t.dvx = wvx;
        t.dvy = wvy;
        t.dvz = wvz;
        if (Opt::sps) {
            // f = m_b grad W; m_b ((tau_a + tau_b) - P I) . grad W = st . f (addStressTerm).
            const float facm = fac * massb;
            t.mx = facm * drx;
            t.my = facm * dry;
            t.mz = facm * drz;
            SymTensor ts = taua;
            if (!kBound) {
                const SymTensor tb = in.tau[j];
                ts.xx += tb.xx; ts.xy += tb.xy; ts.xz += tb.xz;
                ts.yy += tb.yy; ts.yz += tb.yz; ts.zz += tb.zz;
            }
            ts.xx -= prs;
            ts.yy -= prs;
            ts.zz -= prs;
            t.st = ts;
            t.gv = kBound ? VelocityGradientTerm{} : velocityGradientTerm(dvx, dvy, dvz, ovrhob);
        }
    }
    if (!Opt::sps) {  // cf r_ab with cf = F x the coefficient of grad W
        t.cf *= fac;
        t.mx = drx;
        t.my = dry;
        t.mz = drz;
    }

    // Density diffusion (DensityDT 1 and 2 are switched off by any boundary neighbour:
    // addPairTerms).
    t.delta = ProductTerm{};
    if (!kBound && Opt::ddt == DensityDiffusion::Molteni)
        t.delta = ddtMolteniPair(va.w, ovrhob, ov_r2eta, dot3, massb, c.ddtkh, c.cs0);
    if (!kBound && (Opt::ddt == DensityDiffusion::Fourtakas || Opt::ddt == DensityDiffusion::FourtakasFull))
        t.delta = ddtFourtakasPair(va.w, vb.w, ovrhob, drz, ov_r2eta, dot3, massb, c.ddtkh, c.cs0, c.ddt_hyd);
    return t;
}

/// Adds the acceleration of one pair to (ax, ay, az): cf m (pressure, artificial viscosity) or,
/// with SPS, the stress term st . f (addStressTerm; f = m), + cv v_ab (laminar viscosity); the one
/// source of the momentum contribution of a pair, for the fluid particle's sum (addPairTerms)
/// and for the reaction on a boundary particle (hydroForceOnBoundary). Starting from -0.f gives
/// the pair's acceleration alone, bit for bit: fma32(a, b, -0.f) = round(a b), the sign of zero
/// included.
template <class Opt>
SEASPRING_HD inline void addPairAcceleration(const PairTerms& t, float& ax, float& ay, float& az) {
    if (Opt::sps) {
        addStressTerm(t.st, t.mx, t.my, t.mz, ax, ay, az);
    } else {
        ax = fma32(t.cf, t.mx, ax);
        ay = fma32(t.cf, t.my, ay);
        az = fma32(t.cf, t.mz, az);
    }
    if (Opt::visco != Viscosity::Artificial) {
        ax = fma32(t.cv, t.dvx, ax);
        ay = fma32(t.cv, t.dvy, ay);
        az = fma32(t.cv, t.dvz, az);
    }
}

/// Adds one pair's terms to particle a's sums (in neighbour order on every backend).
template <class Opt, bool kBound>
SEASPRING_HD inline void addPairTerms(FluidAccum& acc, const PairTerms& t) {
    addPairAcceleration<Opt>(t, acc.ax, acc.ay, acc.az);
    if (Opt::sps && !kBound) t.gv.addTo(acc.gradvel, t.mx, t.my, t.mz);
    acc.ar = t.ar.addTo(acc.ar);
    acc.visc = maxf(acc.visc, t.visc);
    if (!kBound) acc.delta = t.delta.addTo(acc.delta);
    if (kBound && (Opt::ddt == DensityDiffusion::Molteni || Opt::ddt == DensityDiffusion::Fourtakas))
        acc.ddt_off = true;
}

/// One pair, terms and sum (the GPU's path).
template <class Opt, bool kBound>
SEASPRING_HD inline void fluidPair(std::uint32_t j, float drx, float dry, float drz, float rr2,
                                   const Float4& va, float ovrhoa, float pressa, const SymTensor& taua,
                                   const InteractionInputs& in, const FluidConstants& c, FluidAccum& acc) {
    addPairTerms<Opt, kBound>(acc, fluidPairTerms<Opt, kBound>(j, drx, dry, drz, rr2, va, ovrhoa, pressa, taua, in, c));
}

/// What fluid neighbour j adds to DBC boundary particle a (boundParticleForces): continuity and
/// the viscous dt measure.
struct BoundPairTerms {
    ProductTerm ar;  ///< m_b (v_ab . grad W) rho_a / rho_b (summed as ProductTerm::addTo)
    float visc;      ///< viscous dt measure v_ab.r_ab / (r^2 + eta2)
};

/// The terms of boundary particle a's pair with fluid particle b = j at offset (drx, dry, drz),
/// rr2 = r^2, inside the support. No branches on data (the host evaluates a batch in SIMD lanes).
template <class Opt>
SEASPRING_HD inline BoundPairTerms boundPairTerms(std::uint32_t j, float drx, float dry, float drz, float rr2,
                                                  const Float4& va, const InteractionInputs& in,
                                                  const FluidConstants& c) {
    using K = typename Opt::Kernel;
    const float fac = K::template gradFactor<true>(rr2, c.ker);  // grad W = fac r_ab
    const Float4 vb = in.velrho[j];
    const float dvx = va.x - vb.x, dvy = va.y - vb.y, dvz = va.z - vb.z;
    const float dot_vr = fma32(drx, dvx, fma32(dry, dvy, drz * dvz));
    const float dot_vf = fac * dot_vr;  // v_ab . grad W
    return BoundPairTerms{ProductTerm{c.massfluid * dot_vf, va.w * in.press_ovrho[j].y},
                          viscDtPair(dot_vr, reciprocalNormalRange(rr2 + c.eta2))};
}

/// Adds one boundary pair's terms to boundary particle a's sums (in neighbour order).
SEASPRING_HD inline void addBoundPairTerms(float& ar, float& visc, const BoundPairTerms& t) {
    ar = t.ar.addTo(ar);
    visc = maxf(visc, t.visc);
}

}  // namespace seaspring::physics
