// SeaSpring — MIT licence.
/// \file particle_passes.h
/// \brief The per-particle passes of the fluid step other than the pair loops: each is one
///        functor whose operator()(i) calls one function of src/physics for index i. An
///        execution policy runs it (`exec.forEach<Launch>(b, e, pass)`: an OpenMP loop or one
///        CUDA thread per index), so both backends run the same code.
#pragma once

#include <cstdint>

#include "core/lane_group.h"
#include "physics/blowup_bounds.h"
#include "physics/cell_grid.h"
#include "physics/fluid_pair_terms.h"
#include "physics/gauges.h"
#include "physics/particle_updates.h"
#include "physics/row_extents.h"
#include "physics/time_integration.h"

namespace seaspring::solver {

// ---- divide: sort by (cell, id), cell ranges, "near" flags, PosCell ----------------------

/// Particle i's sort key, perm[i] = i, and, when `stays` is given (a block the merge may take),
/// stays[i]: 1 when its key's cell is the cell its PosCell was assigned at the last sort (so the
/// block's order, sorted by those cells and ids, holds for it), else 0 (particle_sort.h's merge
/// takes the stayers as sorted after checking it).
struct SortKeyPass {
    physics::ParticleView v;
    physics::CellGrid g;
    std::uint64_t* keys;
    std::uint32_t* perm;
    std::uint8_t* stays;
    SEASPRING_HD void operator()(std::uint32_t i) const {
        const std::uint64_t k = physics::sortKeyAt(i, v, g);
        keys[i] = k;
        perm[i] = i;
        if (stays != nullptr) stays[i] = std::uint32_t(k >> 32) == physics::linearCellOf(g, v.poscell[i].w) ? 1u : 0u;
    }
};

/// dst[i] = src[perm[i]] (perm: sorted index -> previous index).
template <typename T>
struct GatherPass {
    const std::uint32_t* perm;
    const T* src;
    T* dst;
    SEASPRING_HD void operator()(std::uint32_t i) const { dst[i] = src[perm[i]]; }
};

/// A field of `words` words W per element, gathered `K` words at a time (words [k, k + K)) through
/// a scratch of K words per particle: dst[i] = words [k, k + K) of element perm[i].
template <typename W, std::uint32_t K>
struct GatherWordsPass {
    const std::uint32_t* perm;
    const W* src;
    std::uint32_t words, k;
    W* dst;
    SEASPRING_HD void operator()(std::uint32_t i) const {
        const W* s = src + std::size_t(perm[i]) * words + k;
        W* d = dst + std::size_t(i) * K;
        for (std::uint32_t q = 0; q < K; ++q) d[q] = s[q];
    }
};

/// Words [k, k + K) of element i = the scratch's K words of i (puts a GatherWordsPass's result
/// back).
template <typename W, std::uint32_t K>
struct PutWordsPass {
    const W* src;
    std::uint32_t words, k;
    W* dst;
    SEASPRING_HD void operator()(std::uint32_t i) const {
        const W* s = src + std::size_t(i) * K;
        W* d = dst + std::size_t(i) * words + k;
        for (std::uint32_t q = 0; q < K; ++q) d[q] = s[q];
    }
};

struct CellStartOuterPass {
    std::uint32_t b, e;
    const std::uint64_t* keys;
    std::uint32_t* cell_start;
    SEASPRING_HD void operator()(std::uint32_t c) const { physics::cellStartOuterAt(c, b, e, keys, cell_start); }
};

/// Row extents over the block of `cs_a` and, when not null, of `cs_b`, by `lanes` threads per row
/// (a power of two <= 32): item k is lane k mod lanes of row k / lanes, each a share of the row's
/// particles (physics::rowExtentShare), the shares joined across the lanes (on the GPU a warp's
/// shuffles; exact in any order), the first lane writing the row (physics::storeRowExtent). One
/// lane: a thread per row (the host, and the GPU's boundary block once); the GPU's fluid block
/// at every evaluation: a warp per row.
struct RowExtentsPass {
    physics::CellGrid g;
    const std::uint32_t* cs_a;
    const std::uint32_t* cs_b;
    const physics::Float4* poscell;
    float* data;
    std::uint32_t lanes;
    SEASPRING_HD void operator()(std::uint32_t k) const {
        const std::uint32_t r = k / lanes, lane = k & (lanes - 1u);
        physics::RowExtentAccum e = physics::rowExtentShare(r, lane, lanes, g, cs_a, cs_b, poscell);
        e = combineAcrossLanes(e, lanes, JoinRowExtents{});
        if (lane == 0u) physics::storeRowExtent(r, g, e, data);
    }
    struct JoinRowExtents {
        SEASPRING_HD physics::RowExtentAccum operator()(physics::RowExtentAccum a,
                                                         const physics::RowExtentAccum& b) const {
            a.join(b);
            return a;
        }
    };
};

struct CellStartFillPass {
    std::uint32_t b;
    const std::uint64_t* keys;
    std::uint32_t* cell_start;
    SEASPRING_HD void operator()(std::uint32_t k) const { physics::cellStartFillAt(k, b, keys, cell_start); }
};

struct NearAlongXPass {
    physics::CellGrid g;
    const std::uint32_t* cell_start;
    std::uint8_t bit;
    std::uint8_t* near;
    SEASPRING_HD void operator()(std::uint32_t c) const { physics::nearAlongXAt(c, g, cell_start, bit, near); }
};

/// One thread per segment of a column of cells along y.
struct NearAlongYPass {
    physics::CellGrid g;
    std::uint8_t bit;
    const std::uint8_t* near;
    std::uint8_t* t;
    SEASPRING_HD void operator()(std::uint32_t q) const { physics::nearAlongYSegment(q, g, bit, near, t); }
};

/// One thread per segment of a column of cells along z.
struct NearAlongZPass {
    physics::CellGrid g;
    std::uint8_t bit;
    const std::uint8_t* t;
    std::uint8_t* near;
    SEASPRING_HD void operator()(std::uint32_t q) const { physics::nearAlongZSegment(q, g, bit, t, near); }
};

struct PosCellPass {
    physics::ParticleView v;
    physics::CellGrid g;
    SEASPRING_HD void operator()(std::uint32_t i) const { physics::posCellAt(i, v, g); }
};

/// A divide's verdict (RefreshPosCellPass, reduced with RefreshCombine; each index is visited
/// once): `sort`, the blocks a particle has left its grown cell in (kSortFluidBlock,
/// kSortBoundaryBlock; 0: no sort), and `removed`, the particles removed from the run in their
/// slots (physics::refreshPosCellAt: excluded since the last sort). `sort` comes first: a gate
/// (Exec::gate) reads it.
constexpr std::uint32_t kSortFluidBlock = 1u, kSortBoundaryBlock = 2u;
struct RefreshVerdict {
    std::uint32_t sort = 0;
    std::uint32_t removed = 0;
};
struct RefreshCombine {  // exact in any order (OR, integer sum)
    SEASPRING_HD RefreshVerdict operator()(const RefreshVerdict& a, const RefreshVerdict& b) const {
        return RefreshVerdict{a.sort | b.sort, a.removed + b.removed};
    }
};
/// Between two sorts: refreshes particle i's PosCell in its cell and gives its share of the
/// divide's verdict.
struct RefreshPosCellPass {
    physics::ParticleView v;
    physics::CellGrid g;
    std::uint32_t nbound;
    SEASPRING_HD RefreshVerdict operator()(std::uint32_t i) const {
        const std::uint32_t left = physics::refreshPosCellAt(i, v, g);
        // A boundary particle is never excluded (one whose position is not finite gets NaN
        // offsets too, and asks for a sort: posCellInCell's `outside`): only fluid is counted.
        const bool fluid = i >= nbound;
        return RefreshVerdict{left * (fluid ? kSortFluidBlock : kSortBoundaryBlock),
                              fluid && physics::removedFromRun(v.poscell[i]) ? 1u : 0u};
    }
};

// ---- moving boundaries, integration ------------------------------------------------------

struct MotionPass {
    physics::ParticleView v;
    std::uint32_t first_moving, nmoving;
    const physics::Double3* pos0;
    const std::uint16_t* object;
    const physics::RigidMotionGpu* motions;
    SEASPRING_HD void operator()(std::uint32_t i) const {
        physics::motionAt(i, v, first_moving, nmoving, pos0, object, motions);
    }
};

struct PredictorPass {
    std::uint32_t nbound;
    physics::ParticleView v;
    double dt;
    physics::StepConstants s;
    SEASPRING_HD void operator()(std::uint32_t i) const { physics::symplecticPredictorAt(i, nbound, v, dt, s); }
};

struct CorrectorPass {
    std::uint32_t nbound;
    physics::ParticleView v;
    double dt;
    physics::StepConstants s;
    SEASPRING_HD void operator()(std::uint32_t i) const { physics::symplecticCorrectorAt(i, nbound, v, dt, s); }
};

struct VerletPass {
    std::uint32_t nbound;
    physics::ParticleView v;
    double dt;
    bool euler;
    physics::StepConstants s;
    SEASPRING_HD void operator()(std::uint32_t i) const { physics::verletAt(i, nbound, v, dt, euler, s); }
};

// ---- around the pair loops: pressure, SPS stress, dt maxima ------------------------------

/// Value pass of the count of particles removed from the run in their slots (combined with
/// CountCombine; physics::removedFromRun): the active fluid is the block's less these.
struct RemovedCountPass {
    const physics::Float4* poscell;
    SEASPRING_HD std::uint32_t operator()(std::uint32_t i) const { return physics::removedFromRun(poscell[i]) ? 1u : 0u; }
};

/// Value pass of the count of fluid particles that share their cell with another fluid particle
/// (combined with CountCombine; physics::sharesItsCell), right after a sort of the fluid block:
/// the cells' switch rule (solver/cell_switch.h).
struct SharedCellCountPass {
    const physics::Float4* poscell;
    const std::uint32_t* cell_start;  ///< the fluid block's
    physics::CellGrid g;
    SEASPRING_HD std::uint32_t operator()(std::uint32_t i) const {
        return physics::sharesItsCell(poscell[i], cell_start, g) ? 1u : 0u;
    }
};

/// Value pass of the blow-up scan's count (combined with CountCombine): 1 for a particle
/// physics::particleNotFinite rejects.
struct NotFiniteCountPass {
    const physics::Double3* pos;
    const physics::Float4* velrho;
    const std::uint8_t* excl;
    SEASPRING_HD std::uint32_t operator()(std::uint32_t i) const {
        return physics::particleNotFinite(pos[i], velrho[i], excl[i]) ? 1u : 0u;
    }
};

struct PressurePass {
    physics::ParticleView v;
    physics::FluidConstants c;
    SEASPRING_HD void operator()(std::uint32_t i) const { physics::pressureAt(i, v, c); }
};

/// Value pass of the dt reduction (combined with DtMaximaCombine: max, exact in any order);
/// kSps: first the SPS stress of fluid particle i for the next evaluation (physics::spsTauAt;
/// the dt maxima do not read it), in the same launch.
template <bool kSps>
struct DtMaximaPass {
    std::uint32_t nbound;
    physics::ParticleView v;
    bool all_particles;
    float smag = 0.f, blin = 0.f;
    SEASPRING_HD physics::DtMaxima operator()(std::uint32_t i) const {
        if constexpr (kSps) {
            if (i >= nbound) physics::spsTauAt(i, v, smag, blin);
        }
        return physics::dtMaximaAt(i, nbound, v, all_particles);
    }
};
struct DtMaximaCombine {
    SEASPRING_HD physics::DtMaxima operator()(const physics::DtMaxima& a, const physics::DtMaxima& b) const {
        return physics::combineDtMaxima(a, b);
    }
};

// ---- gauges ------------------------------------------------------------------------------

template <class Kernel, int kDim>
struct GaugeSamplePass {
    const physics::Float4* points;
    const std::uint32_t* cell_start_fluid;
    const physics::Float4* poscell;
    const physics::Float4* velrho;
    physics::FluidConstants c;
    physics::CellGrid g;
    physics::GaugeSample* out;
    SEASPRING_HD void operator()(std::uint32_t k) const {
        out[k] = physics::gaugeSampleAt<Kernel, kDim>(points[k], cell_start_fluid, poscell, velrho, c, g);
    }
};

template <int kDim>
struct MaxzRowPass {
    const physics::MaxzRow* rows;
    const std::uint32_t* cell_start_fluid;
    const physics::Double3* pos;
    const physics::Float4* poscell;
    double* out;
    SEASPRING_HD void operator()(std::uint32_t k) const {
        out[k] = physics::maxzRowAt<kDim>(rows[k], cell_start_fluid, pos, poscell);
    }
};

struct GaugePositionPass {
    const std::uint32_t* id;
    const physics::Double3* pos;
    const std::uint32_t* slot_of_id;
    physics::Double3* out;
    SEASPRING_HD void operator()(std::uint32_t i) const { physics::gaugePositionAt(i, id, pos, slot_of_id, out); }
};

}  // namespace seaspring::solver
