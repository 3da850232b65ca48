// SeaSpring — MIT licence.
/// \file fluid_interaction.h
/// \brief The force evaluation of one particle: the loops over its neighbours, calling the
///        pair terms of fluid_pair_terms.h.
///
/// Both backends call these functions per particle over the same cell-sorted arrays (the CPU
/// from an OpenMP loop, the GPU one thread per lane of a particle), so neighbours are visited
/// in the same order and sums are formed in the same order: results are bit-identical.
/// Neighbour order: all fluid-block rows, then all boundary-block rows, each block in the
/// order of forEachCandidateRow (neighbour_rows.h): rows by z then y (ascending); inside a row,
/// the contiguous particle range of its cells (sorted by cell, then id). Gather only: each
/// particle writes its own results.
///
/// Pair lanes (`lanes`, a power of two <= kMaxPairLanes; -pairlanes): a particle's sums are
/// split into `lanes` partial sums. Candidate j (its index in the particle arrays) goes to
/// partial j mod lanes, each partial summed in candidate order (so which rows and cells a walk
/// visits, beyond those that hold neighbours, cannot change a lane's sum: a walk may skip
/// candidates out of reach that another tests, row_extents.h); the partials are then combined
/// pairwise, (s0 + s1) + (s2 + s3) and so on (combineLanes). The GPU runs one thread per lane
/// (fluidLanePartial) and combines with the same tree across the lanes of a warp; the host
/// forms all partials in one walk (fluidLanePartials). One lane is the plain sum. More lanes
/// give small cases more threads: the summation order changes with `lanes`, so hashes compare
/// runs of the same lanes.
#pragma once

#include <cstdint>
#include <type_traits>

#include "physics/pair_batch.h"

namespace seaspring::physics {


/// fluidPairsInRow loads the next candidate's PosCell before the test and pair of this one, so
/// that its latency overlaps them (the same candidates, pairs and order, so the same bits), for
/// the laminar families' boundary block: there it pays (NVIDIA H200: SPHERIC laminar+SPS 0.989,
/// FlexStruc Liao 3D 0.986); in the artificial-viscosity fluid block it costs registers (56 ->
/// 64) and 3% (docs/performance-large.md, twenty-second session).
template <class Opt, bool kBound>
constexpr bool kLoadAhead = kBound && Opt::visco != Viscosity::Artificial;

/// Candidates [pb, pe) of one row for fluid particle a (b in the fluid block, or kBound), `par`
/// and `cax` as forEachCandidateRow gives them: the direct loop (the GPU's path).
/// Pair lanes: `lane` takes the candidates j of the row with j mod `lanes` = lane (lanes a power
/// of two; one lane: every candidate).
template <class Opt, bool kBound>
SEASPRING_HD inline void fluidPairsInRow(std::uint32_t pb, std::uint32_t pe, std::uint32_t lane,
                                         std::uint32_t lanes, const Float4& par, int cax,
                                         const Float4& va, float ovrhoa, float pressa, const SymTensor& taua,
                                         const InteractionInputs& in, const FluidConstants& c,
                                         const CellGrid& g, FluidAccum& acc) {
    std::uint32_t j = pb + ((lane - pb) & (lanes - 1u));
    if constexpr (!kLoadAhead<Opt, kBound>) {
        for (; j < pe; j += lanes) {
            float drx, dry, drz;
            const float rr2 = pairOffset<Opt::dim>(par, in.poscell[j], cax, g, drx, dry, drz);
            if (!isNeighbour(rr2, c)) continue;
            fluidPair<Opt, kBound>(j, drx, dry, drz, rr2, va, ovrhoa, pressa, taua, in, c, acc);
        }
    } else {
        if (j >= pe) return;
        Float4 psb = in.poscell[j];
        for (;;) {
            const std::uint32_t jn = j + lanes;
            Float4 next = psb;
            if (jn < pe) next = in.poscell[jn];  // kLoadAhead
            float drx, dry, drz;
            const float rr2 = pairOffset<Opt::dim>(par, psb, cax, g, drx, dry, drz);
            if (isNeighbour(rr2, c))
                fluidPair<Opt, kBound>(j, drx, dry, drz, rr2, va, ovrhoa, pressa, taua, in, c, acc);
            if (jn >= pe) break;
            j = jn;
            psb = next;
        }
    }
}

/// fluidPairsInRow's alternative on the GPU for the laminar families (solver/force_passes_impl.h,
/// kMaskedRows): the row's candidates of this lane are
/// tested first, up to 32 at a time, into a bit mask of neighbours; then the pairs are taken from
/// the mask in ascending order, their offsets computed again (pairOffset: the same bits). The
/// same pairs in the same order as the direct loop, so the same sums; but the threads of a warp
/// run the pair arithmetic together for their k-th neighbour of the row rather than for
/// candidate k, which in a disordered flow (where the threads' neighbours lie at unrelated
/// candidate steps) keeps more of them busy (docs/performance-large.md, sixteenth session).
template <class Opt, bool kBound>
SEASPRING_HD inline void fluidPairsInRowMasked(std::uint32_t pb, std::uint32_t pe, std::uint32_t lane,
                                               std::uint32_t lanes, const Float4& par, int cax, const Float4& va,
                                               float ovrhoa, float pressa, const SymTensor& taua,
                                               const InteractionInputs& in, const FluidConstants& c,
                                               const CellGrid& g, FluidAccum& acc) {
    for (std::uint32_t base = pb + ((lane - pb) & (lanes - 1u)); base < pe; base += 32u * lanes) {
        std::uint32_t hits = 0;
        for (std::uint32_t k = 0, j = base; k < 32u && j < pe; ++k, j += lanes) {
            float drx, dry, drz;
            const float rr2 = pairOffset<Opt::dim>(par, in.poscell[j], cax, g, drx, dry, drz);
            hits |= (isNeighbour(rr2, c) ? 1u : 0u) << k;
        }
        while (hits != 0u) {
            const std::uint32_t j = base + std::uint32_t(lowestSetBit(hits)) * lanes;
            hits &= hits - 1u;
            float drx, dry, drz;
            const float rr2 = pairOffset<Opt::dim>(par, in.poscell[j], cax, g, drx, dry, drz);
            fluidPair<Opt, kBound>(j, drx, dry, drz, rr2, va, ovrhoa, pressa, taua, in, c, acc);
        }
    }
}

/// The pairs of `psa` with the candidates of one block (`cell_start` of that block), row by row
/// (forEachCandidateRow, or the host's row table): kCompact (the host), every lane's partial at
/// once into acc[0, lanes); otherwise lane `lane`'s partial into acc[0]. kExt (the GPU): the
/// fluid block's rows tested against that block's extents (in.fluid_ext,
/// forEachCandidateRowInExtents), the only walk of that block compiled in (the cell walk beside
/// it in one kernel, chosen at run time, cost the kernel 6%: docs/performance-large.md,
/// twenty-eighth session).
template <class Opt, bool kBound, bool kCompact, bool kMask = false, bool kExt = false>
SEASPRING_HD inline void fluidPairsInBlock(const std::uint32_t* cell_start, const Float4& psa,
                                           const Float4& va, float ovrhoa, float pressa,
                                           const SymTensor& taua, const InteractionInputs& in,
                                           const FluidConstants& c, const CellGrid& g, std::uint32_t lane,
                                           std::uint32_t lanes, FluidAccum* acc, const RowTable* rows = nullptr) {
    struct Empty {};
    std::conditional_t<kCompact, PairBatch<Opt, kBound>, Empty> batch;
    // The block's end (the host's lane loads may read up to it).
    [[maybe_unused]] const std::uint32_t end = kCompact ? cell_start[g.cellCount()] : 0u;
    auto row = [&](std::uint32_t pb, std::uint32_t pe, const Float4& par, int cax) {
        if constexpr (kCompact)
            batch.addRow(pb, pe, end, lanes, par, cax, va, ovrhoa, pressa, taua, in, c, g, acc);
        else if constexpr (kMask)
            fluidPairsInRowMasked<Opt, kBound>(pb, pe, lane, lanes, par, cax, va, ovrhoa, pressa, taua, in, c, g, *acc);
        else
            fluidPairsInRow<Opt, kBound>(pb, pe, lane, lanes, par, cax, va, ovrhoa, pressa, taua, in, c, g, *acc);
    };
    if constexpr (kExt && !kBound) {
        forEachCandidateRowInExtents<Opt::dim>(psa, cell_start, in.fluid_ext, c, g, row);
        return;
    }
    if (rows != nullptr && !rows->full)
        rows->forEachCandidateRow(psa, cell_start, row);
    else if (kBound && !kCompact && in.bound_ext.lo[0] != nullptr)
        forEachCandidateRowInExtents<Opt::dim>(psa, cell_start, in.bound_ext, c, g, row);
    else
        forEachCandidateRow<Opt::dim>(psa, cell_start, c, g, row);
    if constexpr (kCompact) batch.flush(lanes, va, ovrhoa, pressa, taua, in, c, acc);
}

/// The partial sums of fluid particle `i` (fluid neighbours, then boundary neighbours): kCompact,
/// all `lanes` partials into acc[0, lanes) in one walk (the host's path); otherwise lane `lane`'s
/// alone into acc[0] (the GPU's path: one thread per lane). kExt: see fluidPairsInBlock.
/// acc[] starts as FluidAccum{}.
/// kMask: the fluid block's rows through fluidPairsInRowMasked; the boundary block's always
/// through the direct loop (the same bits either way): its pairs are cheaper (no neighbour
/// stress, velocity gradient or diffusion) and only the warp's particles near a wall walk it,
/// so the mask's second offset per pair costs more there than it saves (FlexStruc Liao 3D 0.99,
/// SPHERIC laminar+SPS 0.985; docs/performance-large.md, twentieth session).
template <class Opt, bool kCompact, bool kMask = false, bool kExt = false>
SEASPRING_HD inline void fluidLanePartials(std::uint32_t i, std::uint32_t lane, std::uint32_t lanes,
                                           const InteractionInputs& in, const FluidConstants& c, const CellGrid& g,
                                           FluidAccum* acc) {
    const Float4 psa = in.poscell[i];
    // Out of the run (removedPosCell): zero sums. Its NaN offsets would find no neighbour
    // anyway (its cells come from the packed cell); this spares the walk.
    if (removedFromRun(psa)) return;
    const Float4 va = in.velrho[i];
    const Float2 pa2 = in.press_ovrho[i];
    const float pressa = pa2.x, ovrhoa = pa2.y;
    SymTensor taua{0, 0, 0, 0, 0, 0};
    if (Opt::sps) taua = in.tau[i];
    struct NoRows {};
    std::conditional_t<kCompact, RowTable, NoRows> rows;  // the host: the rows once, for both blocks
    const RowTable* rt = nullptr;
    if constexpr (kCompact) {
        rows.template build<Opt::dim>(psa, c, g, in.row_ext);
        rt = &rows;
    } else {
        (void)rows;
    }
    fluidPairsInBlock<Opt, false, kCompact, kMask, kExt>(in.cell_start_fluid, psa, va, ovrhoa, pressa, taua, in, c,
                                                         g, lane, lanes, acc, rt);
    if (in.near == nullptr || (in.near[linearCellOf(g, psa.w)] & kNearBound) != 0)
        fluidPairsInBlock<Opt, true, kCompact, false>(in.cell_start_bound, psa, va, ovrhoa, pressa, taua, in, c, g,
                                                      lane, lanes, acc, rt);
}

/// Lane `lane`'s partial sums of fluid particle `i` (the GPU's path, one thread per lane;
/// kMask: fluidPairsInRowMasked, the same bits).
template <class Opt, bool kMask = false, bool kExt = false>
SEASPRING_HD inline FluidAccum fluidLanePartial(std::uint32_t i, std::uint32_t lane, std::uint32_t lanes,
                                                const InteractionInputs& in, const FluidConstants& c,
                                                const CellGrid& g) {
    FluidAccum acc;
    fluidLanePartials<Opt, false, kMask, kExt>(i, lane, lanes, in, c, g, &acc);
    return acc;
}

/// Two partial sums combined (a, the lower lane, first): sums added, maxima and flags merged.
template <class Opt>
SEASPRING_HD inline FluidAccum combineLanePair(const FluidAccum& a, const FluidAccum& b) {
    FluidAccum r;
    r.ax = a.ax + b.ax;
    r.ay = a.ay + b.ay;
    r.az = a.az + b.az;
    r.ar = a.ar + b.ar;
    r.delta = a.delta + b.delta;
    r.visc = maxf(a.visc, b.visc);
    r.ddt_off = a.ddt_off || b.ddt_off;
    if (Opt::sps) {
        r.gradvel.xx = a.gradvel.xx + b.gradvel.xx; r.gradvel.xy = a.gradvel.xy + b.gradvel.xy;
        r.gradvel.xz = a.gradvel.xz + b.gradvel.xz; r.gradvel.yy = a.gradvel.yy + b.gradvel.yy;
        r.gradvel.yz = a.gradvel.yz + b.gradvel.yz; r.gradvel.zz = a.gradvel.zz + b.gradvel.zz;
    }
    return r;
}

/// combineLanePair as a function object (for combineAcrossLanes, core/lane_group.h).
template <class Opt>
struct CombineLanePair {
    SEASPRING_HD FluidAccum operator()(const FluidAccum& a, const FluidAccum& b) const {
        return combineLanePair<Opt>(a, b);
    }
};

/// The partials acc[0, lanes) combined pairwise into acc[0]: at width w = 1, 2, 4, ..., acc[k] =
/// combineLanePair(acc[k], acc[k + w]) for k a multiple of 2w; (s0 + s1) + (s2 + s3) for four.
/// A warp's butterfly (lane k takes lane k ^ w's value at width w) gives lane 0 the same.
template <class Opt>
SEASPRING_HD inline void combineLanes(FluidAccum* acc, std::uint32_t lanes) {
    for (std::uint32_t w = 1; w < lanes; w <<= 1)
        for (std::uint32_t k = 0; k < lanes; k += 2 * w) acc[k] = combineLanePair<Opt>(acc[k], acc[k + w]);
}

/// A fluid particle's sums complete: the density diffusion joins the continuity term (unless a
/// boundary neighbour switched it off).
template <class Opt>
SEASPRING_HD inline void finishFluidAccum(FluidAccum& acc) {
    if (Opt::ddt != DensityDiffusion::None && !acc.ddt_off) acc.ar += acc.delta;
}

/// Force evaluation of fluid particle `i` over `lanes` pair lanes: fluid neighbours, then
/// boundary neighbours. kCompact: see PairBatch (the host sets it; same results).
template <class Opt, bool kCompact = false>
SEASPRING_HD inline FluidAccum fluidParticleForces(std::uint32_t i, const InteractionInputs& in,
                                                   const FluidConstants& c, const CellGrid& g,
                                                   std::uint32_t lanes = 1) {
    FluidAccum acc[kMaxPairLanes];
    if constexpr (kCompact) {
        fluidLanePartials<Opt, true>(i, 0, lanes, in, c, g, acc);
    } else {
        for (std::uint32_t l = 0; l < lanes; ++l) acc[l] = fluidLanePartial<Opt>(i, l, lanes, in, c, g);
    }
    combineLanes<Opt>(acc, lanes);
    finishFluidAccum<Opt>(acc[0]);
    return acc[0];
}

/// Force evaluation of DBC boundary particle `i`: continuity with fluid neighbours and the
/// viscous dt measure (boundary particles feel no force: their motion is prescribed).
/// The row walk is forEachCandidateRow's; kCompact (the host): the rows from a RowTable (the
/// same rows) and the pairs through a BoundBatch (pair_batch.h: the same bits); kExt (the GPU):
/// the fluid block's rows tested against its extents (in.fluid_ext; the same neighbours).
template <class Opt, bool kCompact = false, bool kExt = false>
SEASPRING_HD inline void boundParticleForces(std::uint32_t i, const InteractionInputs& in,
                                             const FluidConstants& c, const CellGrid& g,
                                             float& ar_out, float& visc_out) {
    const Float4 psa = in.poscell[i];
    const Float4 va = in.velrho[i];
    float ar = 0.f, visc = 0.f;
    ar_out = 0.f;
    visc_out = 0.f;
    if (in.near != nullptr && (in.near[linearCellOf(g, psa.w)] & kNearFluid) == 0) return;  // a dry wall
    if constexpr (kCompact) {
        BoundBatch<Opt> batch;
        // The fluid block's end (the batch's lane loads may read up to it).
        const std::uint32_t end = in.cell_start_fluid[g.cellCount()];
        auto row = [&](std::uint32_t pb, std::uint32_t pe, const Float4& par, int cax) {
            batch.addRow(pb, pe, end, par, cax, va, in, c, g, ar, visc);
        };
        RowTable rows;  // the rows in SIMD lanes (the same rows, or those the extents leave)
        rows.template build<Opt::dim>(psa, c, g, in.row_ext);
        if (!rows.full)
            rows.forEachCandidateRow(psa, in.cell_start_fluid, row);
        else
            forEachCandidateRow<Opt::dim>(psa, in.cell_start_fluid, c, g, row);
        batch.flush(va, in, c, ar, visc);
    } else {
        auto row = [&](std::uint32_t pb, std::uint32_t pe, const Float4& par, int cax) {
            for (std::uint32_t j = pb; j < pe; ++j) {
                float drx, dry, drz;
                const float rr2 = pairOffset<Opt::dim>(par, in.poscell[j], cax, g, drx, dry, drz);
                if (!isNeighbour(rr2, c)) continue;
                addBoundPairTerms(ar, visc, boundPairTerms<Opt>(j, drx, dry, drz, rr2, va, in, c));
            }
        };
        if constexpr (kExt)
            forEachCandidateRowInExtents<Opt::dim>(psa, in.cell_start_fluid, in.fluid_ext, c, g, row);
        else
            forEachCandidateRow<Opt::dim>(psa, in.cell_start_fluid, c, g, row);
    }
    ar_out = ar;
    visc_out = visc;
}

}  // namespace seaspring::physics
