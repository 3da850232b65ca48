// SeaSpring — MIT licence.
/// \file fluid_interaction.h
/// \brief The force evaluation of one particle: the loop over its neighbours and every pair
///        term (pressure, viscosity, continuity, density diffusion, SPS, viscous dt).
///
/// Both backends call these functions per particle over the same cell-sorted arrays (the CPU
/// from an OpenMP loop, the GPU one thread per particle), so neighbours are visited in the
/// same order and sums are formed in the same order: results are bit-identical.
/// Neighbour order: all fluid-block rows, then all boundary-block rows; rows by z then y
/// (ascending); inside a row, the contiguous particle range of its cells (sorted by cell,
/// then id). Gather only: each particle writes its own results.
#pragma once

#include <cstdint>

#include "physics/cell_grid.h"
#include "physics/eos_tait.h"
#include "physics/fluid_constants.h"
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

/// Pairs of fluid particle `pa` with neighbours [pb, pe) of one row. `kBound`: the range is
/// in the boundary block. rowdy/rowdz = cellsize * (cell difference in y / z) of the row.
template <class Opt, bool kBound>
SEASPRING_HD inline void fluidPairsInRow(std::uint32_t pb, std::uint32_t pe, const Float4& psa,
                                         int cax, float rowdy, float rowdz, const Float4& va,
                                         float ovrhoa, float pressa, const SymTensor& taua,
                                         const InteractionInputs& in, const FluidConstants& c,
                                         const CellGrid& g, FluidAccum& acc) {
    using K = typename Opt::Kernel;
    const float massb = kBound ? c.massbound : c.massfluid;
    const float visco = kBound ? c.visco_bound : c.visco;
    for (std::uint32_t j = pb; j < pe; ++j) {
        const Float4 psb = in.poscell[j];
        const float drx = fma32(g.cellsizef, float(cax - packedCellX(g, psb.w)), psa.x - psb.x);
        const float dry = Opt::dim == 3 ? (psa.y - psb.y) + rowdy : 0.f;
        const float drz = (psa.z - psb.z) + rowdz;
        const float rr2 = Opt::dim == 3 ? fma32(drx, drx, fma32(dry, dry, drz * drz)) : fma32(drx, drx, drz * drz);
        if (!(rr2 <= c.ker.kernelsize2 && rr2 >= kAlmostZero)) continue;
        const float fac = K::gradFactor(rr2, c.ker);
        const float frx = fac * drx, fry = fac * dry, frz = fac * drz;
        const Float4 vb = in.velrho[j];
        const Float2 pb2 = in.press_ovrho[j];
        const float pressb = pb2.x, ovrhob = pb2.y;
        const float ov_r2eta = 1.f / (rr2 + c.eta2);

        // Pressure.
        float prs = (pressa + pressb) * (ovrhoa * ovrhob);
        if (K::kType == KernelType::Cubic)
            prs += CubicKernel::tensileCorrection(rr2, pressa, va.w, pressb, vb.w, c.ker);
        const float p_vpm = -prs * massb;
        acc.ax = fma32(p_vpm, frx, acc.ax);
        acc.ay = fma32(p_vpm, fry, acc.ay);
        acc.az = fma32(p_vpm, frz, acc.az);

        // Continuity.
        const float dvx = va.x - vb.x, dvy = va.y - vb.y, dvz = va.z - vb.z;
        const float dot_vf = fma32(dvx, frx, fma32(dvy, fry, dvz * frz));
        acc.ar = fma32(massb * dot_vf, va.w * ovrhob, acc.ar);

        // Viscous time-step measure and viscosity.
        const float dot_vr = fma32(drx, dvx, fma32(dry, dvy, drz * dvz));
        const float dot3 = fma32(drx, frx, fma32(dry, fry, drz * frz));  // r . grad W
        acc.visc = maxf(acc.visc, viscDtPair(dot_vr, ov_r2eta));
        if (Opt::visco == Viscosity::Artificial) {
            const float s = artificialViscosityFactor(dot_vr, ov_r2eta, va.w, vb.w, massb, visco,
                                                      c.cs0, c.ker.h);
            acc.ax = fma32(-s, frx, acc.ax);
            acc.ay = fma32(-s, fry, acc.ay);
            acc.az = fma32(-s, frz, acc.az);
        } else {
            const float s = laminarViscosityFactor(dot3, ov_r2eta, va.w, vb.w, massb, visco);
            acc.ax = fma32(s, dvx, acc.ax);
            acc.ay = fma32(s, dvy, acc.ay);
            acc.az = fma32(s, dvz, acc.az);
            if (Opt::sps) {
                SymTensor t = taua;
                if (!kBound) {
                    const SymTensor tb = in.tau[j];
                    t.xx += tb.xx; t.xy += tb.xy; t.xz += tb.xz;
                    t.yy += tb.yy; t.yz += tb.yz; t.zz += tb.zz;
                }
                acc.ax += massb * (t.xx * frx + t.xy * fry + t.xz * frz);
                acc.ay += massb * (t.xy * frx + t.yy * fry + t.yz * frz);
                acc.az += massb * (t.xz * frx + t.yz * fry + t.zz * frz);
                if (!kBound)
                    accumulateVelocityGradient(acc.gradvel, dvx, dvy, dvz, frx, fry, frz, massb, ovrhob);
            }
        }

        // Density diffusion.
        if (Opt::ddt == DensityDiffusion::Molteni || Opt::ddt == DensityDiffusion::Fourtakas) {
            if (kBound) {
                acc.ddt_off = true;
            } else if (Opt::ddt == DensityDiffusion::Molteni) {
                acc.delta += ddtMolteniPair(va.w, ovrhob, ov_r2eta, dot3, massb, c.ddtkh, c.cs0);
            } else {
                acc.delta += ddtFourtakasPair(va.w, vb.w, ovrhob, drz, ov_r2eta, dot3, massb, c.ddtkh,
                                              c.cs0, c.ddtgz, c.rhop0);
            }
        } else if (Opt::ddt == DensityDiffusion::FourtakasFull && !kBound) {
            acc.delta += ddtFourtakasPair(va.w, vb.w, ovrhob, drz, ov_r2eta, dot3, massb, c.ddtkh,
                                          c.cs0, c.ddtgz, c.rhop0);
        }
    }
}

/// Visits the rows around `psa`'s cell in one block (cell_start of that block).
template <class Opt, bool kBound>
SEASPRING_HD inline void fluidPairsInBlock(const std::uint32_t* cell_start, const Float4& psa,
                                           const Float4& va, float ovrhoa, float pressa,
                                           const SymTensor& taua,
                                           const InteractionInputs& in, const FluidConstants& c,
                                           const CellGrid& g, FluidAccum& acc) {
    const int cax = packedCellX(g, psa.w);
    const int cay = Opt::dim == 3 ? packedCellY(g, psa.w) : 0;
    const int caz = packedCellZ(g, psa.w);
    const int x0 = maxi(cax - g.range, 0), x1 = mini(cax + g.range, g.ncx - 1);
    const int y0 = Opt::dim == 3 ? maxi(cay - g.range, 0) : 0;
    const int y1 = Opt::dim == 3 ? mini(cay + g.range, g.ncy - 1) : 0;
    const int z0 = maxi(caz - g.range, 0), z1 = mini(caz + g.range, g.ncz - 1);
    for (int z = z0; z <= z1; ++z) {
        const float rowdz = g.cellsizef * float(caz - z);
        for (int y = y0; y <= y1; ++y) {
            const float rowdy = g.cellsizef * float(cay - y);
            const std::uint32_t row = g.linear(0, y, z);
            const std::uint32_t pb = cell_start[row + std::uint32_t(x0)];
            const std::uint32_t pe = cell_start[row + std::uint32_t(x1) + 1u];
            fluidPairsInRow<Opt, kBound>(pb, pe, psa, cax, rowdy, rowdz, va, ovrhoa, pressa, taua,
                                         in, c, g, acc);
        }
    }
}

/// Force evaluation of fluid particle `i`.
template <class Opt>
SEASPRING_HD inline FluidAccum fluidParticleForces(std::uint32_t i, const InteractionInputs& in,
                                                   const FluidConstants& c, const CellGrid& g) {
    const Float4 psa = in.poscell[i];
    const Float4 va = in.velrho[i];
    const Float2 pa2 = in.press_ovrho[i];
    const float pressa = pa2.x, ovrhoa = pa2.y;
    SymTensor taua{0, 0, 0, 0, 0, 0};
    if (Opt::sps) taua = in.tau[i];
    FluidAccum acc;
    fluidPairsInBlock<Opt, false>(in.cell_start_fluid, psa, va, ovrhoa, pressa, taua, in, c, g, acc);
    fluidPairsInBlock<Opt, true>(in.cell_start_bound, psa, va, ovrhoa, pressa, taua, in, c, g, acc);
    if (Opt::ddt != DensityDiffusion::None && !acc.ddt_off) acc.ar += acc.delta;
    return acc;
}

/// Force evaluation of DBC boundary particle `i`: continuity with fluid neighbours and the
/// viscous dt measure (boundary particles feel no force: their motion is prescribed).
/// Returns (ar, visc).
template <class Opt>
SEASPRING_HD inline void boundParticleForces(std::uint32_t i, const InteractionInputs& in,
                                             const FluidConstants& c, const CellGrid& g,
                                             float& ar_out, float& visc_out) {
    using K = typename Opt::Kernel;
    const Float4 psa = in.poscell[i];
    const Float4 va = in.velrho[i];
    const int cax = packedCellX(g, psa.w);
    const int cay = Opt::dim == 3 ? packedCellY(g, psa.w) : 0;
    const int caz = packedCellZ(g, psa.w);
    const int x0 = maxi(cax - g.range, 0), x1 = mini(cax + g.range, g.ncx - 1);
    const int y0 = Opt::dim == 3 ? maxi(cay - g.range, 0) : 0;
    const int y1 = Opt::dim == 3 ? mini(cay + g.range, g.ncy - 1) : 0;
    const int z0 = maxi(caz - g.range, 0), z1 = mini(caz + g.range, g.ncz - 1);
    float ar = 0.f, visc = 0.f;
    for (int z = z0; z <= z1; ++z) {
        const float rowdz = g.cellsizef * float(caz - z);
        for (int y = y0; y <= y1; ++y) {
            const float rowdy = g.cellsizef * float(cay - y);
            const std::uint32_t row = g.linear(0, y, z);
            const std::uint32_t pb = in.cell_start_fluid[row + std::uint32_t(x0)];
            const std::uint32_t pe = in.cell_start_fluid[row + std::uint32_t(x1) + 1u];
            for (std::uint32_t j = pb; j < pe; ++j) {
                const Float4 psb = in.poscell[j];
                const float drx = fma32(g.cellsizef, float(cax - packedCellX(g, psb.w)), psa.x - psb.x);
                const float dry = Opt::dim == 3 ? (psa.y - psb.y) + rowdy : 0.f;
                const float drz = (psa.z - psb.z) + rowdz;
                const float rr2 = Opt::dim == 3 ? fma32(drx, drx, fma32(dry, dry, drz * drz))
                                                : fma32(drx, drx, drz * drz);
                if (!(rr2 <= c.ker.kernelsize2 && rr2 >= kAlmostZero)) continue;
                const float fac = K::gradFactor(rr2, c.ker);
                const float frx = fac * drx, fry = fac * dry, frz = fac * drz;
                const Float4 vb = in.velrho[j];
                const float dvx = va.x - vb.x, dvy = va.y - vb.y, dvz = va.z - vb.z;
                const float dot_vf = fma32(dvx, frx, fma32(dvy, fry, dvz * frz));
                ar = fma32(c.massfluid * dot_vf, va.w * in.press_ovrho[j].y, ar);
                const float dot_vr = fma32(drx, dvx, fma32(dry, dvy, drz * dvz));
                visc = maxf(visc, viscDtPair(dot_vr, 1.f / (rr2 + c.eta2)));
            }
        }
    }
    ar_out = ar;
    visc_out = visc;
}

}  // namespace seaspring::physics
