// SeaSpring — MIT licence.
/// \file solid_coupling.h
/// \brief Fluid-solid coupling of the VCPM solids (seed paper 000 §2.3): solid particles are
///        DBC boundary particles for the fluid, and each feels the exact opposite of the pressure
///        and viscous terms it exerts on its fluid neighbours (Eq. 16), gathered per solid
///        particle. Also the per-particle copies between the solid arrays (solid-index order)
///        and the cell-sorted boundary block.
#pragma once

#include <cstdint>

#include "physics/fluid_interaction.h"
#include "physics/vcpm.h"

namespace seaspring::physics {

/// The hydrodynamic force on boundary particle i (sorted index; normally a solid particle):
/// F = -sum_j m_j a_j<-i over its fluid neighbours j, where a_j<-i is the acceleration term that
/// fluid particle j received from i in the same force evaluation. Each pair's offset and terms
/// are computed exactly as fluid particle j computes them (its own row frame and cell), so every
/// pair contributes the same bits with the opposite sign: action = -reaction up to the rounding
/// of the two sums.
template <class Opt>
SEASPRING_HD inline Double3 hydroForceOnBoundary(std::uint32_t i, const InteractionInputs& in,
                                                 const FluidConstants& c, const CellGrid& g) {
    const Float4 psb = in.poscell[i];
    const int cby = Opt::dim == 3 ? packedCellY(g, psb.w) : 0;
    const int cbz = packedCellZ(g, psb.w);
    double fx = 0.0, fy = 0.0, fz = 0.0;
    const double m = double(c.massfluid);
    if (in.near != nullptr && (in.near[linearCellOf(g, psb.w)] & kNearFluid) == 0)  // no fluid in reach
        return Double3{m * fx, m * fy, m * fz};
    forEachCandidateRow<Opt::dim>(psb, in.cell_start_fluid, c, g, [&](std::uint32_t pb, std::uint32_t pe,
                                                                      const Float4&, int) {
        for (std::uint32_t j = pb; j < pe; ++j) {
            const Float4 psa = in.poscell[j];
            // Fluid particle j's frame for the row holding i: as forEachCandidateRow gives it to j.
            const int caxj = packedCellX(g, psa.w);
            const float rowdy = Opt::dim == 3 ? g.cellsizef * float(packedCellY(g, psa.w) - cby) : 0.f;
            const float rowdz = g.cellsizef * float(packedCellZ(g, psa.w) - cbz);
            float drx, dry, drz;
            const float rr2 = pairOffset<Opt::dim>(rowFrame(psa, rowdy, rowdz), psb, caxj, g, drx, dry, drz);
            if (!isNeighbour(rr2, c)) continue;
            const Float4 va = in.velrho[j];
            const Float2 pa2 = in.press_ovrho[j];
            SymTensor taua{0, 0, 0, 0, 0, 0};
            if (Opt::sps) taua = in.tau[j];
            const PairTerms t = fluidPairTerms<Opt, true>(i, drx, dry, drz, rr2, va, pa2.y, pa2.x, taua, in, c);
            float ax = -0.f, ay = -0.f, az = -0.f;  // the pair's acceleration alone (addPairAcceleration)
            addPairAcceleration<Opt>(t, ax, ay, az);
            fx -= double(ax);
            fy -= double(ay);
            fz -= double(az);
        }
    });
    return Double3{m * fx, m * fy, m * fz};
}

/// Sorted boundary index i: if it holds solid particle s (id in [first, first + n)), writes
/// slot[s] = i (integer, one writer per entry).
SEASPRING_HD inline void solidSlotAt(std::uint32_t i, const std::uint32_t* id, std::uint32_t first, std::uint32_t n,
                                     std::uint32_t* slot) {
    const std::uint32_t s = id[i] - first;
    if (id[i] >= first && s < n) slot[s] = i;
}

/// Copies the solid's position and velocity into the boundary block (sorted index of solid s)
/// at the end of a sub-cycle of length dt, and adds to the coupling ledger of particle s the
/// impulse F dt and the work F . (r_end - r_start) of the frozen hydrodynamic force F (the
/// block still holds r_start). `ledger` false: copy only (a sub-cycle that will be redone).
SEASPRING_HD inline void solidToBoundaryAt(std::uint32_t s, const std::uint32_t* slot, const Double3* pos,
                                           const Double3* vel, const Double3* fluid_force, double dt,
                                           Double3* impulse, double* work, bool ledger, Double3* bpos,
                                           Float4* bvelrho) {
    const std::uint32_t i = slot[s];
    const Double3 p = pos[s];
    if (ledger) {
        const Double3 p0 = bpos[i], f = fluid_force[s], j = impulse[s];
        impulse[s] = Double3{j.x + f.x * dt, j.y + f.y * dt, j.z + f.z * dt};
        work[s] += f.x * (p.x - p0.x) + f.y * (p.y - p0.y) + f.z * (p.z - p0.z);
    }
    bpos[i] = p;
    const Double3 v = vel[s];
    bvelrho[i].x = float(v.x);
    bvelrho[i].y = float(v.y);
    bvelrho[i].z = float(v.z);
}

/// Clamp node c's positions at the start and the end of a solid interval: its boundary
/// particle's initial position moved by its motion object (or fixed when object < 0).
SEASPRING_HD inline void clampMotionAt(std::uint32_t c, const Double3* pos_initial, const std::int16_t* object,
                                       const RigidMotionGpu* motions, Double3* pos_start, Double3* pos_end) {
    const Double3 p = pos_initial[c];
    if (object[c] < 0) {
        pos_start[c] = p;
        pos_end[c] = p;
        return;
    }
    const RigidMotionGpu& m = motions[object[c]];
    pos_start[c] = applyRigid(m.r, m.t, p);
    pos_end[c] = applyRigid(m.r_next, m.t_next, p);
}

}  // namespace seaspring::physics
