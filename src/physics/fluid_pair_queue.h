// SeaSpring — MIT licence.
/// \file fluid_pair_queue.h
/// \brief The force evaluation of a fluid particle for lanes that run in lockstep (a GPU warp):
///        the same pairs, the same terms and the same sums in the same order as
///        fluidParticleForces (fluid_interaction.h), so the same bits, but the pair arithmetic
///        runs with (nearly) every lane busy.
///
/// Why. In the direct loop a lane tests a candidate and, if it is a neighbour, evaluates the
/// pair; the lanes of a warp test their own candidates side by side, so the pair arithmetic runs
/// whenever any lane has a neighbour, with the lanes whose candidate is not one idle. About 60%
/// of the candidates are neighbours in 3D, so the pair arithmetic (five times the cost of a test)
/// ran at about 3/4 of the lanes (Nsight Compute: 23.8 of 32).
///
/// How. Each lane steps through its candidates with a CandidateCursor (forEachCandidateRow's
/// order), testing only, and keeps the indices of the neighbours it finds in kBatch slots of its
/// own (Lanes::put) until they are full or its candidates are used up; then every lane evaluates
/// the pairs it holds, in the order found, which is the direct loop's order; and again while any
/// lane has candidates left. The tests diverge (lanes need different numbers of candidates to
/// fill their slots) but are cheap; the pair arithmetic runs with the lanes that hold full
/// batches, i.e. all but those near the end of their candidates.
///
/// `Lanes` is the group of lanes: `any(p)` over the group, `put(slot, j)`/`get(slot)` on the
/// calling lane's slots, and kBatch. The CUDA backend's is a warp with the slots in shared
/// memory (cuda/warp_lanes.cuh); SingleLane below is the host's one-lane group (tests).
#pragma once

#include <cstdint>

#include "physics/fluid_pair_terms.h"

namespace seaspring::physics {

/// A group of one lane with its batch in an array (the host: tests of the queued loop).
template <unsigned kBatchPairs = 16>
struct SingleLane {
    static constexpr unsigned kBatch = kBatchPairs;
    std::uint32_t slots[kBatch];
    SEASPRING_HD bool any(bool p) const { return p; }
    SEASPRING_HD void put(unsigned slot, std::uint32_t j) { slots[slot] = j; }
    SEASPRING_HD std::uint32_t get(unsigned slot) const { return slots[slot]; }
};

/// The pairs of fluid particle a (psa; `active` false: a lane with no particle, which still
/// takes part in the group's votes) with the candidates of one block, in rounds: each lane
/// tests its next candidates until it holds kBatch neighbours or has none left (a loop of
/// tests only), then every lane evaluates the pairs it holds, in the order found.
template <class Opt, bool kBound, class Lanes>
SEASPRING_HD void queuedPairsInBlock(bool active, const std::uint32_t* cell_start, const Float4& psa,
                                     const Float4& va, float ovrhoa, float pressa, const SymTensor& taua,
                                     const InteractionInputs& in, const FluidConstants& c, const CellGrid& g,
                                     FluidAccum& acc, Lanes& lanes) {
    constexpr unsigned kBatch = Lanes::kBatch;
    CandidateCursor<Opt::dim> cur;
    bool more = false;
    if (active) {
        cur.begin(psa, cell_start, c, g);
        more = !cur.done();
    }
    while (lanes.any(more)) {
        unsigned n = 0;
        while (more && n < kBatch) {
            const std::uint32_t j = cur.j;
            float drx, dry, drz;
            const float rr2 = pairOffset<Opt::dim>(cur.par, in.poscell[j], cur.box.cax, g, drx, dry, drz);
            if (isNeighbour(rr2, c)) lanes.put(n++, j);
            cur.next(psa, cell_start, c, g);
            more = !cur.done();
        }
        for (unsigned k = 0; k < n; ++k) {
            const std::uint32_t j = lanes.get(k);
            float drx, dry, drz;
            const float rr2 = pairOffsetInOwnRow<Opt::dim>(psa, cur.box, in.poscell[j], g, drx, dry, drz);
            fluidPair<Opt, kBound>(j, drx, dry, drz, rr2, va, ovrhoa, pressa, taua, in, c, acc);
        }
    }
}

/// fluidParticleForces (same results) for a lane of a group: fluid neighbours, then boundary
/// neighbours, each block through queuedPairsInBlock. Every lane of the group calls it;
/// `active` false for a lane without a particle (i is then not read).
template <class Opt, class Lanes>
SEASPRING_HD FluidAccum fluidParticleForcesQueued(std::uint32_t i, bool active, const InteractionInputs& in,
                                                  const FluidConstants& c, const CellGrid& g, Lanes& lanes) {
    Float4 psa{0, 0, 0, 0}, va{0, 0, 0, 0};
    float pressa = 0.f, ovrhoa = 0.f;
    SymTensor taua{0, 0, 0, 0, 0, 0};
    if (active) {
        psa = in.poscell[i];
        va = in.velrho[i];
        const Float2 pa2 = in.press_ovrho[i];
        pressa = pa2.x;
        ovrhoa = pa2.y;
        if (Opt::sps) taua = in.tau[i];
    }
    FluidAccum acc;
    queuedPairsInBlock<Opt, false>(active, in.cell_start_fluid, psa, va, ovrhoa, pressa, taua, in, c, g, acc, lanes);
    const bool bound = active && (in.near == nullptr || (in.near[linearCellOf(g, psa.w)] & kNearBound) != 0);
    if (lanes.any(bound))
        queuedPairsInBlock<Opt, true>(bound, in.cell_start_bound, psa, va, ovrhoa, pressa, taua, in, c, g, acc, lanes);
    if (Opt::ddt != DensityDiffusion::None && !acc.ddt_off) acc.ar += acc.delta;
    return acc;
}

}  // namespace seaspring::physics
