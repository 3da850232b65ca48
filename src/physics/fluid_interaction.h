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
#include <type_traits>

#include "physics/cell_grid.h"
#include "physics/eos_tait.h"
#include "physics/fluid_constants.h"
#include "physics/particle_updates.h"
#include "physics/sph_types.h"

namespace seaspring::physics {

/// Safety margin of the row spans, in cells: absorbs the rounding of the span arithmetic.
constexpr float kRowSpanMargin = 1e-3f;

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

/// Particle a's cell offsets moved into the frame of one row of cells: y + rowdy, z + rowdz,
/// rowdy/rowdz = cellsize * (a's cell - the row's cell) in y/z. Computed once per row.
SEASPRING_HD inline Float4 rowFrame(const Float4& psa, float rowdy, float rowdz) {
    return Float4{psa.x, psa.y + rowdy, psa.z + rowdz, psa.w};
}

/// Offset r_ab = r_a - r_b of a candidate b of the row and its squared length; `par` is a's
/// rowFrame for that row.
template <int kDim>
SEASPRING_HD inline float pairOffset(const Float4& par, const Float4& psb, int cax, const CellGrid& g,
                                     float& drx, float& dry, float& drz) {
    drx = fma32(g.cellsizef, float(cax - packedCellX(g, psb.w)), par.x - psb.x);
    dry = kDim == 3 ? par.y - psb.y : 0.f;
    drz = par.z - psb.z;
    return kDim == 3 ? fma32(drx, drx, fma32(dry, dry, drz * drz)) : fma32(drx, drx, drz * drz);
}

/// The exact neighbour test of a pair (inside the kernel support, not the particle itself).
SEASPRING_HD inline bool isNeighbour(float rr2, const FluidConstants& c) {
    return rr2 <= c.ker.kernelsize2 && rr2 >= kAlmostZero;
}

/// What pair (a, b) adds to fluid particle a, before it is summed (addPairTerms).
struct PairTerms {
    float frx, fry, frz;   ///< grad W_ab
    float cf;              ///< coefficient of grad W_ab in dv_a/dt (pressure, artificial viscosity)
    float cv;              ///< coefficient of v_ab in dv_a/dt (laminar viscosity)
    float dvx, dvy, dvz;   ///< v_ab (laminar)
    float sx, sy, sz;      ///< SPS stress term of dv_a/dt
    float ar;              ///< continuity term of d(rho_a)/dt
    float delta;           ///< density diffusion term
    float visc;            ///< viscous dt measure v_ab.r_ab / (r^2 + eta2)
    SymTensor gv;          ///< SPS velocity-gradient terms
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
    const float fac = K::gradFactor(rr2, c.ker);
    t.frx = fac * drx;
    t.fry = fac * dry;
    t.frz = fac * drz;
    const Float4 vb = in.velrho[j];
    const Float2 pb2 = in.press_ovrho[j];
    const float pressb = pb2.x, ovrhob = pb2.y;
    float ov_r2eta, ov_rhosum;
    pairReciprocals(rr2, c.eta2, va.w, vb.w, ov_r2eta, ov_rhosum);

    // Pressure.
    float prs = (pressa + pressb) * (ovrhoa * ovrhob);
    if (K::kType == KernelType::Cubic)
        prs += CubicKernel::tensileCorrection(rr2, pressa, va.w, pressb, vb.w, c.ker);
    t.cf = -prs * massb;

    // Continuity.
    const float dvx = va.x - vb.x, dvy = va.y - vb.y, dvz = va.z - vb.z;
    const float dot_vf = fma32(dvx, t.frx, fma32(dvy, t.fry, dvz * t.frz));
    t.ar = dot_vf * (ovrhob * (massb * va.w));  // massb * rho_a: per particle

    // Viscous time-step measure and viscosity.
    const float dot_vr = fma32(drx, dvx, fma32(dry, dvy, drz * dvz));
    const float dot3 = fma32(drx, t.frx, fma32(dry, t.fry, drz * t.frz));  // r . grad W
    t.visc = viscDtPair(dot_vr, ov_r2eta);
    if (Opt::visco == Viscosity::Artificial) {
        t.cf -= artificialViscosityFactor(t.visc, ov_rhosum, massb, visco, c.cs0, c.ker.h);
    } else {
        t.cv = laminarViscosityFactor(dot3, ov_r2eta, ov_rhosum, massb, visco);
        t.dvx = dvx;
        t.dvy = dvy;
        t.dvz = dvz;
        if (Opt::sps) {
            SymTensor ts = taua;
            if (!kBound) {
                const SymTensor tb = in.tau[j];
                ts.xx += tb.xx; ts.xy += tb.xy; ts.xz += tb.xz;
                ts.yy += tb.yy; ts.yz += tb.yz; ts.zz += tb.zz;
            }
            t.sx = massb * (ts.xx * t.frx + ts.xy * t.fry + ts.xz * t.frz);
            t.sy = massb * (ts.xy * t.frx + ts.yy * t.fry + ts.yz * t.frz);
            t.sz = massb * (ts.xz * t.frx + ts.yz * t.fry + ts.zz * t.frz);
            t.gv = SymTensor{0, 0, 0, 0, 0, 0};
            if (!kBound) accumulateVelocityGradient(t.gv, dvx, dvy, dvz, t.frx, t.fry, t.frz, massb, ovrhob);
        }
    }

    // Density diffusion (DensityDT 1 and 2 are switched off by any boundary neighbour:
    // addPairTerms).
    t.delta = 0.f;
    if (!kBound && Opt::ddt == DensityDiffusion::Molteni)
        t.delta = ddtMolteniPair(va.w, ovrhob, ov_r2eta, dot3, massb, c.ddtkh, c.cs0);
    if (!kBound && (Opt::ddt == DensityDiffusion::Fourtakas || Opt::ddt == DensityDiffusion::FourtakasFull))
        t.delta = ddtFourtakasPair(va.w, vb.w, ovrhob, drz, ov_r2eta, dot3, massb, c.ddtkh, c.cs0, c.ddtgz,
                                   c.rhop0);
    return t;
}

/// Adds one pair's terms to particle a's sums (in neighbour order on every backend).
template <class Opt, bool kBound>
SEASPRING_HD inline void addPairTerms(FluidAccum& acc, const PairTerms& t) {
    acc.ax = fma32(t.cf, t.frx, acc.ax);
    acc.ay = fma32(t.cf, t.fry, acc.ay);
    acc.az = fma32(t.cf, t.frz, acc.az);
    if (Opt::visco != Viscosity::Artificial) {
        acc.ax = fma32(t.cv, t.dvx, acc.ax);
        acc.ay = fma32(t.cv, t.dvy, acc.ay);
        acc.az = fma32(t.cv, t.dvz, acc.az);
        if (Opt::sps) {
            acc.ax += t.sx;
            acc.ay += t.sy;
            acc.az += t.sz;
            if (!kBound) {
                acc.gradvel.xx += t.gv.xx; acc.gradvel.xy += t.gv.xy; acc.gradvel.xz += t.gv.xz;
                acc.gradvel.yy += t.gv.yy; acc.gradvel.yz += t.gv.yz; acc.gradvel.zz += t.gv.zz;
            }
        }
    }
    acc.ar += t.ar;
    acc.visc = maxf(acc.visc, t.visc);
    if (!kBound) acc.delta += t.delta;
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

/// The cells around a particle's cell that its neighbour search visits: rows y0..y1, z0..z1
/// (2D: y0 = y1 = 0) of at most 2 range + 1 cells each.
struct SearchBox {
    int cax, cay, caz, y0, y1, z0, z1;
    float margin;  ///< rowSpan's safety margin [m]
};

template <int kDim>
SEASPRING_HD inline SearchBox searchBox(const Float4& psa, const CellGrid& g) {
    SearchBox b;
    b.cax = packedCellX(g, psa.w);
    b.cay = kDim == 3 ? packedCellY(g, psa.w) : 0;
    b.caz = packedCellZ(g, psa.w);
    b.y0 = kDim == 3 ? maxi(b.cay - g.range, 0) : 0;
    b.y1 = kDim == 3 ? mini(b.cay + g.range, g.ncy - 1) : 0;
    b.z0 = maxi(b.caz - g.range, 0);
    b.z1 = mini(b.caz + g.range, g.ncz - 1);
    b.margin = kRowSpanMargin * g.cellsizef;
    return b;
}

/// Candidates [pb, pe) of row (y, z) in the block whose first indices per cell are
/// `cell_start`: the cells of the row in reach of `psa` (rowSpan). `gz` = the row's gap in z
/// (cellGap, once per z). False when the row is out of reach.
template <int kDim>
SEASPRING_HD inline bool rowCandidates(const SearchBox& b, const Float4& psa, int y, int z, float gz,
                                       const std::uint32_t* cell_start, const FluidConstants& c,
                                       const CellGrid& g, std::uint32_t& pb, std::uint32_t& pe) {
    const float gy = kDim == 3 ? cellGap(y - b.cay, psa.y, g.cellsizef, b.margin) : 0.f;
    int x0, x1;
    if (!rowSpan(g, b.cax, psa.x, gy * gy + gz * gz, c.ker.kernelsize2, b.margin, x0, x1)) return false;
    const std::uint32_t row = g.linear(0, y, z);
    pb = cell_start[row + std::uint32_t(x0)];
    pe = cell_start[row + std::uint32_t(x1) + 1u];
    return true;
}

/// Candidates [pb, pe) of one row for fluid particle a (b in the fluid block, or kBound): the
/// direct loop (the GPU's path).
template <class Opt, bool kBound>
SEASPRING_HD inline void fluidPairsInRow(std::uint32_t pb, std::uint32_t pe, const Float4& psa, int cax,
                                         float rowdy, float rowdz, const Float4& va, float ovrhoa,
                                         float pressa, const SymTensor& taua, const InteractionInputs& in,
                                         const FluidConstants& c, const CellGrid& g, FluidAccum& acc) {
    const Float4 par = rowFrame(psa, rowdy, rowdz);
    for (std::uint32_t j = pb; j < pe; ++j) {
        float drx, dry, drz;
        const float rr2 = pairOffset<Opt::dim>(par, in.poscell[j], cax, g, drx, dry, drz);
        if (!isNeighbour(rr2, c)) continue;
        fluidPair<Opt, kBound>(j, drx, dry, drz, rr2, va, ovrhoa, pressa, taua, in, c, acc);
    }
}

/// The host's path (kCompact): the candidates of one block, gathered row by row, are processed
/// in batches. Offsets are computed in SIMD lanes, neighbours selected without branches, their
/// terms computed in SIMD lanes, and the terms summed one by one in candidate order: the same
/// operations in the same order as the direct loop, so the same bits, at a fraction of the
/// cost of a mispredicted branch per candidate and scalar pair arithmetic.
template <class Opt, bool kBound>
struct PairBatch {
    static constexpr int kCap = 256;
    std::uint32_t jj[kCap];
    float bx[kCap], by[kCap], bz[kCap], br[kCap];
    PairTerms t[kCap];
    int m = 0;

    SEASPRING_HD void flush(const Float4& va, float ovrhoa, float pressa, const SymTensor& taua,
                            const InteractionInputs& in, const FluidConstants& c, FluidAccum& acc) {
        int n = 0;
        for (int k = 0; k < m; ++k) {  // in place: n <= k
            jj[n] = jj[k];
            bx[n] = bx[k];
            by[n] = by[k];
            bz[n] = bz[k];
            const float r = br[k];
            br[n] = r;
            n += isNeighbour(r, c) ? 1 : 0;
        }
        const std::uint32_t* __restrict sj = jj;
        const float *__restrict sx = bx, *__restrict sy = by, *__restrict sz = bz, *__restrict sr = br;
        for (int q = 0; q < n; ++q)  // SIMD lanes
            t[q] = fluidPairTerms<Opt, kBound>(sj[q], sx[q], sy[q], sz[q], sr[q], va, ovrhoa, pressa, taua, in, c);
        for (int q = 0; q < n; ++q) addPairTerms<Opt, kBound>(acc, t[q]);
        m = 0;
    }

    SEASPRING_HD void addRow(std::uint32_t pb, std::uint32_t pe, const Float4& psa, int cax, float rowdy,
                             float rowdz, const Float4& va, float ovrhoa, float pressa, const SymTensor& taua,
                             const InteractionInputs& in, const FluidConstants& c, const CellGrid& g,
                             FluidAccum& acc) {
        const Float4 par = rowFrame(psa, rowdy, rowdz);
        while (pb < pe) {
            const int take = pe - pb > std::uint32_t(kCap - m) ? kCap - m : int(pe - pb);
            for (int k = 0; k < take; ++k) {
                const std::uint32_t j = pb + std::uint32_t(k);
                jj[m + k] = j;
                br[m + k] = pairOffset<Opt::dim>(par, in.poscell[j], cax, g, bx[m + k], by[m + k], bz[m + k]);
            }
            m += take;
            pb += std::uint32_t(take);
            if (m == kCap) flush(va, ovrhoa, pressa, taua, in, c, acc);
        }
    }
};

/// Visits the rows of cells around `psa`'s cell that can hold a neighbour (by z then y,
/// ascending) in one block (`cell_start` of that block).
template <class Opt, bool kBound, bool kCompact>
SEASPRING_HD inline void fluidPairsInBlock(const std::uint32_t* cell_start, const Float4& psa,
                                           const Float4& va, float ovrhoa, float pressa,
                                           const SymTensor& taua, const InteractionInputs& in,
                                           const FluidConstants& c, const CellGrid& g, FluidAccum& acc) {
    const SearchBox box = searchBox<Opt::dim>(psa, g);
    const int cax = box.cax;
    struct Empty {};
    std::conditional_t<kCompact, PairBatch<Opt, kBound>, Empty> batch;
    for (int z = box.z0; z <= box.z1; ++z) {
        const float rowdz = g.cellsizef * float(box.caz - z);
        const float gz = cellGap(z - box.caz, psa.z, g.cellsizef, box.margin);
        for (int y = box.y0; y <= box.y1; ++y) {
            std::uint32_t pb, pe;
            if (!rowCandidates<Opt::dim>(box, psa, y, z, gz, cell_start, c, g, pb, pe)) continue;
            const float rowdy = g.cellsizef * float(box.cay - y);
            if constexpr (kCompact)
                batch.addRow(pb, pe, psa, cax, rowdy, rowdz, va, ovrhoa, pressa, taua, in, c, g, acc);
            else
                fluidPairsInRow<Opt, kBound>(pb, pe, psa, cax, rowdy, rowdz, va, ovrhoa, pressa, taua, in, c, g, acc);
        }
    }
    if constexpr (kCompact) batch.flush(va, ovrhoa, pressa, taua, in, c, acc);
}

/// Force evaluation of fluid particle `i`: fluid neighbours, then boundary neighbours.
/// kCompact: see PairBatch (the host sets it; same results).
template <class Opt, bool kCompact = false>
SEASPRING_HD inline FluidAccum fluidParticleForces(std::uint32_t i, const InteractionInputs& in,
                                                   const FluidConstants& c, const CellGrid& g) {
    const Float4 psa = in.poscell[i];
    const Float4 va = in.velrho[i];
    const Float2 pa2 = in.press_ovrho[i];
    const float pressa = pa2.x, ovrhoa = pa2.y;
    SymTensor taua{0, 0, 0, 0, 0, 0};
    if (Opt::sps) taua = in.tau[i];
    FluidAccum acc;
    fluidPairsInBlock<Opt, false, kCompact>(in.cell_start_fluid, psa, va, ovrhoa, pressa, taua, in, c, g, acc);
    fluidPairsInBlock<Opt, true, kCompact>(in.cell_start_bound, psa, va, ovrhoa, pressa, taua, in, c, g, acc);
    if (Opt::ddt != DensityDiffusion::None && !acc.ddt_off) acc.ar += acc.delta;
    return acc;
}

/// Candidates the host filters at once in boundParticleForces (kCompact).
constexpr int kCandidateChunk = 64;

/// What fluid neighbour j adds to DBC boundary particle a: continuity (ar) and the viscous dt
/// measure (visc).
template <class Opt>
SEASPRING_HD inline void boundPair(std::uint32_t j, float drx, float dry, float drz, float rr2, const Float4& va,
                                   const InteractionInputs& in, const FluidConstants& c, float& ar,
                                   float& visc) {
    using K = typename Opt::Kernel;
    const float fac = K::gradFactor(rr2, c.ker);
    const float frx = fac * drx, fry = fac * dry, frz = fac * drz;
    const Float4 vb = in.velrho[j];
    const float dvx = va.x - vb.x, dvy = va.y - vb.y, dvz = va.z - vb.z;
    const float dot_vf = fma32(dvx, frx, fma32(dvy, fry, dvz * frz));
    ar = fma32(c.massfluid * dot_vf, va.w * in.press_ovrho[j].y, ar);
    const float dot_vr = fma32(drx, dvx, fma32(dry, dvy, drz * dvz));
    visc = maxf(visc, viscDtPair(dot_vr, 1.f / (rr2 + c.eta2)));
}

/// Force evaluation of DBC boundary particle `i`: continuity with fluid neighbours and the
/// viscous dt measure (boundary particles feel no force: their motion is prescribed).
/// The row walk is fluidPairsInBlock's; kCompact: branch-free selection (as PairBatch).
template <class Opt, bool kCompact = false>
SEASPRING_HD inline void boundParticleForces(std::uint32_t i, const InteractionInputs& in,
                                             const FluidConstants& c, const CellGrid& g,
                                             float& ar_out, float& visc_out) {
    const Float4 psa = in.poscell[i];
    const Float4 va = in.velrho[i];
    const SearchBox box = searchBox<Opt::dim>(psa, g);
    const int cax = box.cax;
    float ar = 0.f, visc = 0.f;
    for (int z = box.z0; z <= box.z1; ++z) {
        const float rowdz = g.cellsizef * float(box.caz - z);
        const float gz = cellGap(z - box.caz, psa.z, g.cellsizef, box.margin);
        for (int y = box.y0; y <= box.y1; ++y) {
            std::uint32_t pb, pe;
            if (!rowCandidates<Opt::dim>(box, psa, y, z, gz, in.cell_start_fluid, c, g, pb, pe)) continue;
            const float rowdy = g.cellsizef * float(box.cay - y);
            const Float4 par = rowFrame(psa, rowdy, rowdz);
            if constexpr (!kCompact) {
                for (std::uint32_t j = pb; j < pe; ++j) {
                    float drx, dry, drz;
                    const float rr2 = pairOffset<Opt::dim>(par, in.poscell[j], cax, g, drx, dry, drz);
                    if (!isNeighbour(rr2, c)) continue;
                    boundPair<Opt>(j, drx, dry, drz, rr2, va, in, c, ar, visc);
                }
            } else {
                std::uint32_t idx[kCandidateChunk];
                float bx[kCandidateChunk], by[kCandidateChunk], bz[kCandidateChunk], br[kCandidateChunk];
                for (std::uint32_t j0 = pb; j0 < pe; j0 += kCandidateChunk) {
                    const std::uint32_t je = pe - j0 > std::uint32_t(kCandidateChunk) ? j0 + kCandidateChunk : pe;
                    int n = 0;
                    for (std::uint32_t j = j0; j < je; ++j) {
                        float drx, dry, drz;
                        const float rr2 = pairOffset<Opt::dim>(par, in.poscell[j], cax, g, drx, dry, drz);
                        idx[n] = j;
                        bx[n] = drx;
                        by[n] = dry;
                        bz[n] = drz;
                        br[n] = rr2;
                        n += isNeighbour(rr2, c) ? 1 : 0;
                    }
                    for (int k = 0; k < n; ++k) boundPair<Opt>(idx[k], bx[k], by[k], bz[k], br[k], va, in, c, ar, visc);
                }
            }
        }
    }
    ar_out = ar;
    visc_out = visc;
}

}  // namespace seaspring::physics
