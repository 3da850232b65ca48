// SeaSpring — MIT licence.
/// \file particle_updates.h
/// \brief Everything a time step does to one particle, as functions of the particle index over
///        a view of the sorted arrays. The CPU driver calls them from OpenMP loops, the CUDA
///        driver from one thread per index: one source for both backends.
///
/// Sorted layout: [0, nbound) boundary block (fixed, then moving, by cell then id),
/// [nbound, nbound + nfluid) active fluid (by cell then id), then excluded fluid (by id).
#pragma once

#include <cstdint>

#include "physics/cell_grid.h"
#include "physics/particle_fields.h"
#include "physics/time_integration.h"
#include "physics/viscosity.h"

namespace seaspring::physics {

/// Device or host pointers to the per-particle arrays (sorted order): one pointer per row of
/// the field table (particle_fields.h); null for a field the run does not allocate.
struct ParticleView {
#define SEASPRING_VIEW_MEMBER(name, type, need, flags) type* name = nullptr;
    SEASPRING_PARTICLE_FIELDS(SEASPRING_VIEW_MEMBER)
#undef SEASPRING_VIEW_MEMBER
};

/// Sort key of particle i (cell of its position, excluded ones last).
SEASPRING_HD inline std::uint64_t sortKeyAt(std::uint32_t i, const ParticleView& v, const CellGrid& g) {
    int cx, cy, cz;
    cellOf(g, v.pos[i], cx, cy, cz);
    return sortKey(g.linear(cx, cy, cz), v.id[i], v.excl[i] != kActive);
}

/// cell_start[c] = first index in [b, e) whose cell >= c. Particle k (b <= k < e, sorted
/// keys) writes the entries from just after the previous particle's cell up to its own;
/// cellStartOuterAt writes the entries before the first and after the last particle's cell.
/// Integer only, so any execution order gives the same array.
SEASPRING_HD inline void cellStartFillAt(std::uint32_t k, std::uint32_t b, const std::uint64_t* keys,
                                         std::uint32_t* cell_start) {
    const std::uint32_t cell = std::uint32_t(keys[k] >> 32);
    const std::uint32_t first = k == b ? cell : std::uint32_t(keys[k - 1] >> 32) + 1u;
    for (std::uint32_t c = first; c <= cell; ++c) cell_start[c] = k;
}
/// Entry c (0 <= c <= ncells) if it lies outside the cells of [b, e).
SEASPRING_HD inline void cellStartOuterAt(std::uint32_t c, std::uint32_t b, std::uint32_t e,
                                          const std::uint64_t* keys, std::uint32_t* cell_start) {
    if (b == e) {
        cell_start[c] = e;
        return;
    }
    if (c <= std::uint32_t(keys[b] >> 32)) cell_start[c] = b;
    else if (c > std::uint32_t(keys[e - 1] >> 32)) cell_start[c] = e;
}

/// "Near" flags per cell, one bit per block: bit kNearBound (kNearFluid) of near[c] is set
/// when the boundary (fluid) block has a particle in a cell within g.range cells of c along
/// every axis (the search box of any point of c). A fluid particle skips the boundary block,
/// and a boundary particle (DBC continuity, hydrodynamic force on a solid) skips the fluid
/// block, where its cell's bit is clear: the block holds no candidate there, so the flags
/// change no result. Built whenever the block is sorted (the boundary block once unless
/// boundaries move; the fluid block at every sort, which the skin makes rare), leaving the
/// other block's bit as it is, in three passes, each extending the box along one axis:
/// nearAlongXAt per cell into near's bit (the block's cell ranges are monotone, so a run of
/// cells holds a particle iff the range from its first cell's start to its last cell's end is
/// not empty: two loads, no loop), then nearAlongYSegment from near's bit into the scratch `t`
/// and nearAlongZSegment from `t` back into near's bit, each per segment of kNearSegment cells
/// of a column along its axis (the window of 2 range + 1 cells kept as bits of a shift
/// register: one load per cell, plus 2 range per segment). Integer only, so any execution
/// order gives the same flags.
constexpr std::uint8_t kNearBound = 1u, kNearFluid = 2u;
constexpr std::uint32_t kNearSegment = 32;

/// Bit `bit` of near[c] = the block (cell ranges `cell_start`) has a particle within g.range
/// cells of c along x (in c's row); the other bits are kept.
SEASPRING_HD inline void nearAlongXAt(std::uint32_t c, const CellGrid& g, const std::uint32_t* cell_start,
                                      std::uint8_t bit, std::uint8_t* near) {
    const std::uint32_t nx = std::uint32_t(g.ncx), r = std::uint32_t(g.range);
    const std::uint32_t x = c % nx;
    const std::uint32_t lo = c - (x < r ? x : r), hi = c + (nx - 1u - x < r ? nx - 1u - x : r);
    near[c] = std::uint8_t((near[c] & std::uint8_t(~bit)) | (cell_start[hi + 1u] != cell_start[lo] ? bit : 0u));
}

/// Segments of a sweep along an axis of n cells: ceil(n / kNearSegment).
SEASPRING_HD inline std::uint32_t nearSegments(int n) { return (std::uint32_t(n) + kNearSegment - 1u) / kNearSegment; }

/// The window sweep shared by both axes: cells [k0, k1) of a column of n cells, `stride` apart
/// from `in` and `out` (at the column's first cell); out = `bit` where bit `in_bit` of in is set
/// within `range` cells along the column, else 0 (only that bit is written; `keep` = out's bits
/// kept).
SEASPRING_HD inline void nearWindowSweep(const std::uint8_t* in, std::uint8_t in_bit, std::uint8_t* out,
                                         std::uint8_t bit, std::uint8_t keep, std::size_t stride, int n, int k0,
                                         int k1, int range) {
    const std::uint32_t mask = (2u << (2 * range)) - 1u;  // 2 range + 1 cells
    std::uint32_t hist = 0;  // bit m: whether the cell m places behind the newest pushed is set
    for (int k = k0 - range; k < k0 + range; ++k)
        hist = (hist << 1) | (k >= 0 && k < n && (in[std::size_t(k) * stride] & in_bit) != 0 ? 1u : 0u);
    for (int k = k0; k < k1; ++k) {
        const int ahead = k + range;
        hist = (hist << 1) | (ahead < n && (in[std::size_t(ahead) * stride] & in_bit) != 0 ? 1u : 0u);
        std::uint8_t& o = out[std::size_t(k) * stride];
        o = std::uint8_t((o & keep) | ((hist & mask) != 0u ? bit : 0u));
    }
}

/// Segment q of the columns along y (q = x + ncx (z + ncz s), s the segment): t = `bit` where
/// near's bit is set within g.range cells along y, else 0.
SEASPRING_HD inline void nearAlongYSegment(std::uint32_t q, const CellGrid& g, std::uint8_t bit,
                                           const std::uint8_t* near, std::uint8_t* t) {
    const std::uint32_t nx = std::uint32_t(g.ncx), cols = nx * std::uint32_t(g.ncz);
    const std::uint32_t col = q % cols, seg = q / cols;
    const std::size_t first = (col % nx) + std::size_t(col / nx) * nx * std::uint32_t(g.ncy);
    const int k0 = int(seg * kNearSegment), k1 = k0 + int(kNearSegment) < g.ncy ? k0 + int(kNearSegment) : g.ncy;
    nearWindowSweep(near + first, bit, t + first, bit, 0u, nx, g.ncy, k0, k1, g.range);
}

/// Segment q of the columns along z (q = x + ncx (y + ncy s)): bit `bit` of near = whether t is
/// set within g.range cells along z; near's other bits are kept.
SEASPRING_HD inline void nearAlongZSegment(std::uint32_t q, const CellGrid& g, std::uint8_t bit,
                                           const std::uint8_t* t, std::uint8_t* near) {
    const std::uint32_t cols = std::uint32_t(g.ncx) * std::uint32_t(g.ncy);
    const std::uint32_t col = q % cols, seg = q / cols;
    const int k0 = int(seg * kNearSegment), k1 = k0 + int(kNearSegment) < g.ncz ? k0 + int(kNearSegment) : g.ncz;
    nearWindowSweep(t + col, bit, near + col, bit, std::uint8_t(~bit), cols, g.ncz, k0, k1, g.range);
}

/// PosCell of particle i.
SEASPRING_HD inline void posCellAt(std::uint32_t i, const ParticleView& v, const CellGrid& g) {
    std::uint32_t cell;
    v.poscell[i] = makePosCell(g, v.pos[i], cell);
}

/// Between two sorts (skin > 0): particle i's PosCell refreshed in the cell it was sorted into
/// (posCellInCell). Returns 1 when the next divide must sort: the particle left the skin of
/// that cell. An excluded particle does not ask for a sort: it is removed from the run in its
/// slot (removedPosCell) and leaves the active range at the next sort (which a particle that
/// left its cell's skin asks for). In the violent phases of an open channel (the 3D sluice
/// gate) particles leave the domain at most divides, where a sort for each cost a fifth of a
/// step (docs/performance-large.md, twenty-ninth session).
SEASPRING_HD inline std::uint32_t refreshPosCellAt(std::uint32_t i, const ParticleView& v, const CellGrid& g) {
    if (v.excl[i] != kActive) {
        v.poscell[i] = removedPosCell(v.poscell[i].w);
        return 0u;
    }
    bool outside;
    v.poscell[i] = posCellInCell(g, v.pos[i], v.poscell[i].w, outside);
    return outside ? 1u : 0u;
}

/// A rigid motion x = R x0 + t (double), and the velocity over the coming interval.
struct RigidMotionGpu {
    double r[9];
    double t[3];
    double r_next[9];  ///< pose at the end of the interval, for the velocity
    double t_next[3];
    double inv_dt;     ///< 1 / interval
};

SEASPRING_HD inline Double3 applyRigid(const double* r, const double* t, const Double3& p) {
    return {r[0] * p.x + r[1] * p.y + r[2] * p.z + t[0], r[3] * p.x + r[4] * p.y + r[5] * p.z + t[1],
            r[6] * p.x + r[7] * p.y + r[8] * p.z + t[2]};
}

/// Moves boundary particle i if it is a moving one (id in [first_moving, first_moving+nmoving)):
/// position from its initial position, velocity = displacement over the coming interval.
SEASPRING_HD inline void motionAt(std::uint32_t i, const ParticleView& v, std::uint32_t first_moving,
                                  std::uint32_t nmoving, const Double3* pos0, const std::uint16_t* object,
                                  const RigidMotionGpu* motions) {
    const std::uint32_t k = v.id[i] - first_moving;
    if (v.id[i] < first_moving || k >= nmoving) return;
    const RigidMotionGpu& m = motions[object[k]];
    const Double3 p = applyRigid(m.r, m.t, pos0[k]);
    const Double3 q = applyRigid(m.r_next, m.t_next, pos0[k]);
    v.pos[i] = p;
    v.velrho[i].x = float((q.x - p.x) * m.inv_dt);
    v.velrho[i].y = float((q.y - p.y) * m.inv_dt);
    v.velrho[i].z = float((q.z - p.z) * m.inv_dt);
}

/// Time-step maxima contributed by particle i (fluid: |a|^2, |v|^2 and visc; boundary: visc,
/// and |v|^2 too with DtAllParticles = 1, so that fast moving walls and solids limit dt).
SEASPRING_HD inline DtMaxima dtMaximaAt(std::uint32_t i, std::uint32_t nbound, const ParticleView& v,
                                        bool all_particles) {
    DtMaxima m;
    if (i >= nbound && removedFromRun(v.poscell[i])) return m;  // out of the run: no dt measure
    m.visc = v.visc[i];
    const Float4 u = v.velrho[i];
    if (i >= nbound) {
        const Float4 a = v.acear[i];
        m.ace2 = a.x * a.x + a.y * a.y + a.z * a.z;
        if (a.w != a.w) m.ace2 = a.w;  // a density rate that is not finite: dt NaN, a blow-up
    }
    if (i >= nbound || all_particles) m.vel2 = u.x * u.x + u.y * u.y + u.z * u.z;
    return m;
}

/// SPS stress of fluid particle i from its velocity gradient.
SEASPRING_HD inline void spsTauAt(std::uint32_t i, const ParticleView& v, float smag, float blin) {
    v.tau[i] = spsTau(v.gradvel[i], v.velrho[i].w, smag, blin);
}

/// Symplectic predictor of particle i; saves the start-of-step velocity and density in
/// velrho_pre.
SEASPRING_HD inline void symplecticPredictorAt(std::uint32_t i, std::uint32_t nbound, const ParticleView& v,
                                               double dt, const StepConstants& s) {
    if (i >= nbound && removedFromRun(v.poscell[i])) return;  // out of the run: its state stays
    const Float4 vr0 = v.velrho[i];
    const Double3 p0 = v.pos[i];
    v.velrho_pre[i] = vr0;
    const Float4 a = v.acear[i];
    if (i < nbound) {
        v.velrho[i].w = symplecticPredictBoundRho(vr0.w, a.w, dt, s.rhop0);
        return;
    }
    Double3 p;
    Float4 vr;
    symplecticPredictFluid(p0, vr0, a, dt, s, p, vr);
    v.pos[i] = p;
    v.velrho[i] = vr;
    v.excl[i] = exclusionOf(p, vr, s);
}

/// Symplectic corrector of particle i (from the predictor's state and velrho_pre).
SEASPRING_HD inline void symplecticCorrectorAt(std::uint32_t i, std::uint32_t nbound, const ParticleView& v,
                                               double dt, const StepConstants& s) {
    if (i >= nbound && removedFromRun(v.poscell[i])) return;
    const Float4 vr0 = v.velrho_pre[i];
    const float rho_half = v.velrho[i].w;
    const Float4 a = v.acear[i];
    if (i < nbound) {
        v.velrho[i].w = symplecticCorrectBoundRho(vr0.w, rho_half, a.w, dt, s.rhop0);
        return;
    }
    Double3 p;
    Float4 vr;
    symplecticCorrectFluid(v.pos[i], vr0, rho_half, a, dt, s, p, vr);
    v.pos[i] = p;
    v.velrho[i] = vr;
    v.excl[i] = exclusionOf(p, vr, s);
}

/// Verlet step of particle i; velrho_pre holds the state at n-1 and receives the state at n.
SEASPRING_HD inline void verletAt(std::uint32_t i, std::uint32_t nbound, const ParticleView& v, double dt,
                                  bool euler, const StepConstants& s) {
    if (i >= nbound && removedFromRun(v.poscell[i])) return;
    const Float4 vr = v.velrho[i];
    const Float4 vrm1 = v.velrho_pre[i];
    const Float4 a = v.acear[i];
    v.velrho_pre[i] = vr;
    if (i < nbound) {
        v.velrho[i].w = verletBoundRho(vr.w, vrm1.w, a.w, dt, euler, s.rhop0);
        return;
    }
    Double3 p;
    Float4 out;
    verletFluid(v.pos[i], vr, vrm1, a, dt, euler, s, p, out);
    v.pos[i] = p;
    v.velrho[i] = out;
    v.excl[i] = exclusionOf(p, out, s);
}

}  // namespace seaspring::physics
