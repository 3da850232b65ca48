// SeaSpring — MIT licence.
/// \file fluid_pair_queue.h
/// \brief The GPU's fluid pair loop with a queue of found neighbours per thread: the same pairs
///        as the direct loop (fluid_interaction.h, fluidPairsInRow), in the same order, through
///        the same fluidPair, so the same bits; only when each pair is evaluated changes.
///
/// Why: the direct loop evaluates a pair as soon as a thread's candidate passes the neighbour
/// test, so at every candidate step the warp pays the pair arithmetic (75 to 140 instructions)
/// if any of its 32 threads found a neighbour. On a lattice (the first steps of a dam break)
/// the threads of a warp, neighbouring particles of one row of cells, find their neighbours at
/// the same steps; in a disordered flow (after an impact) they do not, and half the threads
/// idle through the pair arithmetic (docs/performance-large.md, sixteenth session).
///
/// How: each thread tests its candidates and pushes the neighbours it finds (index and offset,
/// 16 bytes) into a first-in first-out queue of kDepth slots of its own in shared memory; the
/// warp evaluates (each thread its oldest queued pair) when at least 7/8 of its threads hold
/// one, or when no thread can test (those with candidates left have full queues). The rows of
/// cells are walked in step by the whole warp (a uniform box of 2 range + 1 rows per axis; a
/// row out of a thread's reach or outside the grid is empty for it), so their set-up does not
/// diverge; queued pairs carry over to the next row, and the queue is drained after the last.
/// Per thread the pairs are evaluated in the order found, which is the direct loop's order:
/// every sum is formed in the same order (the CPU/GPU hash tests check it).
#pragma once

#include <cstdint>

#include "physics/fluid_interaction.h"

namespace seaspring::physics {

#if defined(__CUDA_ARCH__)

/// Candidates of one block for fluid particle a through the thread's queue (see the file's
/// comment); `mask` = the threads of the warp that call this together (all call it with the
/// same mask), `slots` = this thread's kDepth slots, kThreads apart. Same arguments and
/// results as fluidPairsInBlock's GPU path.
template <class Opt, bool kBound, int kDepth, int kThreads>
__device__ inline void fluidPairsInBlockQueued(const std::uint32_t* cell_start, const Float4& psa, const Float4& va,
                                               float ovrhoa, float pressa, const SymTensor& taua,
                                               const InteractionInputs& in, const FluidConstants& c,
                                               const CellGrid& g, std::uint32_t lane, std::uint32_t lanes,
                                               unsigned mask, Float4* slots, FluidAccum& acc) {
    static_assert((kDepth & (kDepth - 1)) == 0, "the queue's depth is a power of two");
    constexpr int kDim = Opt::dim;
    const int threads = __popc(mask);
    const int enough = threads - threads / 8;  // evaluate when 7/8 of the threads hold a pair
    unsigned head = 0, count = 0;
    auto evaluateOldest = [&] {
        if (count == 0u) return;
        const Float4 q = slots[head * kThreads];
        head = (head + 1u) & unsigned(kDepth - 1);
        --count;
        fluidPair<Opt, kBound>(__float_as_uint(q.x), q.y, q.z, q.w, pairDistance2<kDim>(q.y, q.z, q.w), va, ovrhoa,
                               pressa, taua, in, c, acc);
    };
    const SearchBox box = searchBox<kDim>(psa, g);
    const int r = g.range, ry = kDim == 3 ? g.range : 0;
    std::uint32_t seen = 0;
    for (int dz = -r; dz <= r; ++dz) {
        const int z = box.caz + dz;
        const float rowdz = g.cellsizef * float(box.caz - z);
        const float gz = cellGap(z - box.caz, psa.z, g.cellsizef, box.margin);
        for (int dy = -ry; dy <= ry; ++dy) {
            const int y = box.cay + dy;
            // This thread's row (as forEachRowInReach): empty when out of the grid or of reach.
            std::uint32_t pb = 0, pe = 0;
            Float4 par = psa;
            std::uint32_t c0, c1;
            if (z >= box.z0 && z <= box.z1 && y >= box.y0 && y <= box.y1 &&
                rowCells<kDim>(box, psa, y, z, gz, c, g, c0, c1)) {
                pb = cell_start[c0];
                pe = cell_start[c1];
                par = rowFrame(psa, g.cellsizef * float(box.cay - y), rowdz);
            }
            std::uint32_t j = pb + ((lane - seen) & (lanes - 1u));
            seen += pe - pb;
            while (true) {
                if (j < pe && count < unsigned(kDepth)) {
                    float drx, dry, drz;
                    const float rr2 = pairOffset<kDim>(par, in.poscell[j], box.cax, g, drx, dry, drz);
                    if (isNeighbour(rr2, c)) {
                        slots[((head + count) & unsigned(kDepth - 1)) * kThreads] =
                            Float4{__uint_as_float(j), drx, dry, drz};
                        ++count;
                    }
                    j += lanes;
                }
                const unsigned more = __ballot_sync(mask, j < pe);
                const unsigned room = __ballot_sync(mask, j < pe && count < unsigned(kDepth));
                const unsigned have = __ballot_sync(mask, count > 0u);
                if (__popc(have) >= enough || (more != 0u && room == 0u)) evaluateOldest();
                if (more == 0u) break;
            }
        }
    }
    while (__ballot_sync(mask, count > 0u) != 0u) evaluateOldest();
}

#endif

/// Lane `lane`'s partial sums of fluid particle `i` through the queues (the GPU's path when
/// chosen; on the host, which never takes it, the direct loop). Every thread of the launch's
/// warp that has a particle calls it.
template <class Opt, int kDepth, int kThreads>
SEASPRING_HD inline FluidAccum fluidLanePartialQueued(std::uint32_t i, std::uint32_t lane, std::uint32_t lanes,
                                                      const InteractionInputs& in, const FluidConstants& c,
                                                      const CellGrid& g) {
#if defined(__CUDA_ARCH__)
    __shared__ Float4 queue[kDepth * kThreads];
    const unsigned entry = __activemask();
    Float4* slots = queue + (threadIdx.x % unsigned(kThreads));
    const Float4 psa = in.poscell[i];
    const Float4 va = in.velrho[i];
    const Float2 pa2 = in.press_ovrho[i];
    const float pressa = pa2.x, ovrhoa = pa2.y;
    SymTensor taua{0, 0, 0, 0, 0, 0};
    if (Opt::sps) taua = in.tau[i];
    FluidAccum acc;
    fluidPairsInBlockQueued<Opt, false, kDepth, kThreads>(in.cell_start_fluid, psa, va, ovrhoa, pressa, taua, in, c,
                                                          g, lane, lanes, entry, slots, acc);
    const bool bound = in.near == nullptr || (in.near[linearCellOf(g, psa.w)] & kNearBound) != 0;
    const unsigned bmask = __ballot_sync(entry, bound);
    if (bound)
        fluidPairsInBlockQueued<Opt, true, kDepth, kThreads>(in.cell_start_bound, psa, va, ovrhoa, pressa, taua, in,
                                                             c, g, lane, lanes, bmask, slots, acc);
    return acc;
#else
    return fluidLanePartial<Opt>(i, lane, lanes, in, c, g);
#endif
}

}  // namespace seaspring::physics
