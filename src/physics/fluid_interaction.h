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
/// split into `lanes` partial sums. Candidate number p of a block (counted from 0 in the row
/// order above, neighbours or not) goes to partial p mod lanes, each partial summed in
/// candidate order; the partials are then combined pairwise, (s0 + s1) + (s2 + s3) and so on
/// (combineLanes). The GPU runs one thread per lane (fluidLanePartial) and combines with the
/// same tree across the lanes of a warp; the host forms all partials in one walk
/// (fluidLanePartials). One lane is the plain sum. More lanes give small cases more threads:
/// the summation order changes with `lanes`, so hashes compare runs of the same lanes.
#pragma once

#include <cstdint>
#include <type_traits>

#include "physics/fluid_pair_terms.h"

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
/// Pair lanes: `lane` takes the candidates j of the row whose number in the block, `seen` + (j -
/// pb), is lane mod `lanes` (lanes a power of two; one lane: every candidate).
template <class Opt, bool kBound>
SEASPRING_HD inline void fluidPairsInRow(std::uint32_t pb, std::uint32_t pe, std::uint32_t seen, std::uint32_t lane,
                                         std::uint32_t lanes, const Float4& par, int cax,
                                         const Float4& va, float ovrhoa, float pressa, const SymTensor& taua,
                                         const InteractionInputs& in, const FluidConstants& c,
                                         const CellGrid& g, FluidAccum& acc) {
    std::uint32_t j = pb + ((lane - seen) & (lanes - 1u));
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
SEASPRING_HD inline void fluidPairsInRowMasked(std::uint32_t pb, std::uint32_t pe, std::uint32_t seen,
                                               std::uint32_t lane, std::uint32_t lanes, const Float4& par, int cax,
                                               const Float4& va, float ovrhoa, float pressa, const SymTensor& taua,
                                               const InteractionInputs& in, const FluidConstants& c,
                                               const CellGrid& g, FluidAccum& acc) {
    for (std::uint32_t base = pb + ((lane - seen) & (lanes - 1u)); base < pe; base += 32u * lanes) {
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

/// The host's path (kCompact): the candidates of one block, gathered row by row, are processed
/// in batches. Offsets are computed in SIMD lanes, neighbours selected without branches, their
/// terms computed in SIMD lanes, and the terms summed one by one in candidate order: the same
/// operations in the same order as the direct loop, so the same bits, at a fraction of the
/// cost of a mispredicted branch per candidate and scalar pair arithmetic. Pair lanes: each
/// candidate carries its lane (its number in the block mod lanes), and its terms go to that
/// lane's partial sum, acc[lane].
template <class Opt, bool kBound>
struct PairBatch {
    static constexpr int kCap = 256;
    static constexpr bool kLaminar = Opt::visco != Viscosity::Artificial;
    static constexpr bool kSps = Opt::sps;
    // The neighbours found so far (candidates that passed isNeighbour, in candidate order).
    // (kPad more: the host's SIMD loop stores eight lanes at the batch's end, SEASPRING_SIMD8.)
    static constexpr int kPad = 8;
    std::uint32_t jj[kCap + kPad];
    std::uint32_t ln[kCap + kPad];
    float bx[kCap + kPad], by[kCap + kPad], bz[kCap + kPad], br[kCap + kPad];
    // Their terms, one array per field (so that the SIMD lanes store whole vectors).
    // m and the continuity term's v together (one 16-byte record per pair: the in-order sum
    // reads them with one load).
    alignas(16) float tm[kCap][4];
    float tcf[kSps ? 1 : kCap], tarw[kCap], tdv[kCap], tdw[kCap], tvisc[kCap];
    float tcv[kLaminar ? kCap : 1], tdvx[kLaminar ? kCap : 1], tdvy[kLaminar ? kCap : 1], tdvz[kLaminar ? kCap : 1];
    float tsxx[kSps ? kCap : 1], tsxy[kSps ? kCap : 1], tsxz[kSps ? kCap : 1], tsyy[kSps ? kCap : 1],
        tsyz[kSps ? kCap : 1], tszz[kSps ? kCap : 1];
    float tux[kSps ? kCap : 1], tuy[kSps ? kCap : 1], tuz[kSps ? kCap : 1];
    int m = 0;

    /// The batch's pairs: their terms in SIMD lanes, then each added to its pair lane's partial
    /// (of `lanes`) in candidate order.
    SEASPRING_HD void flush(std::uint32_t lanes, const Float4& va, float ovrhoa, float pressa, const SymTensor& taua,
                            const InteractionInputs& in, const FluidConstants& c, FluidAccum* acc) {
        const int n = m;
        const std::uint32_t* __restrict sj = jj;
        const float *__restrict sx = bx, *__restrict sy = by, *__restrict sz = bz, *__restrict sr = br;
        for (int q = 0; q < n; ++q) {  // SIMD lanes
            const PairTerms t =
                fluidPairTerms<Opt, kBound>(sj[q], sx[q], sy[q], sz[q], sr[q], va, ovrhoa, pressa, taua, in, c);
            tm[q][0] = t.mx;
            tm[q][1] = t.my;
            tm[q][2] = t.mz;
            tm[q][3] = t.ar.v;
            if constexpr (!kSps) tcf[q] = t.cf;  // with SPS cf is not formed (PairTerms)
            tarw[q] = t.ar.w;
            tdv[q] = t.delta.v;
            tdw[q] = t.delta.w;
            tvisc[q] = t.visc;
            if constexpr (kLaminar) {
                tcv[q] = t.cv;
                tdvx[q] = t.dvx;
                tdvy[q] = t.dvy;
                tdvz[q] = t.dvz;
            }
            if constexpr (kSps) {
                tsxx[q] = t.st.xx; tsxy[q] = t.st.xy; tsxz[q] = t.st.xz;
                tsyy[q] = t.st.yy; tsyz[q] = t.st.yz; tszz[q] = t.st.zz;
                tux[q] = t.gv.ux; tuy[q] = t.gv.uy; tuz[q] = t.gv.uz;
            }
        }
        auto termsAt = [&](int q) {
            PairTerms t;
            t.mx = tm[q][0];
            t.my = tm[q][1];
            t.mz = tm[q][2];
            if constexpr (!kSps) t.cf = tcf[q];
            t.ar = ProductTerm{tm[q][3], tarw[q]};
            t.delta = ProductTerm{tdv[q], tdw[q]};
            t.visc = tvisc[q];
            if constexpr (kLaminar) {
                t.cv = tcv[q];
                t.dvx = tdvx[q];
                t.dvy = tdvy[q];
                t.dvz = tdvz[q];
            }
            if constexpr (kSps) {
                t.st = SymTensor{tsxx[q], tsxy[q], tsxz[q], tsyy[q], tsyz[q], tszz[q]};
                t.gv = VelocityGradientTerm{tux[q], tuy[q], tuz[q]};
            }
            return t;
        };
        // In candidate order. One pair lane: the sums in registers (the same operations).
        if (lanes == 1u) {  // every ln is 0
            FluidAccum a = acc[0];
            for (int q = 0; q < n; ++q) addPairTerms<Opt, kBound>(a, termsAt(q));
            acc[0] = a;
        } else {
            for (int q = 0; q < n; ++q) addPairTerms<Opt, kBound>(acc[ln[q]], termsAt(q));
        }
        m = 0;
    }

    /// Candidates [pb, pe), the first of them number `seen` of the block, whose particles end
    /// at `end` (the lane loads may read records [pe, end)): the neighbours among them are
    /// appended (branch-free: every candidate is written at m, m advances on a neighbour).
    SEASPRING_HD void addRow(std::uint32_t pb, std::uint32_t pe, [[maybe_unused]] std::uint32_t end, std::uint32_t seen,
                             std::uint32_t lanes, const Float4& par, int cax, const Float4& va, float ovrhoa,
                             float pressa, const SymTensor& taua, const InteractionInputs& in, const FluidConstants& c,
                             const CellGrid& g, FluidAccum* acc) {
        while (pb < pe) {
            const int take = pe - pb > std::uint32_t(kCap - m) ? kCap - m : int(pe - pb);
            int w = m;  // w <= m + k < kCap inside the loop
#if SEASPRING_SIMD8
            // Eight candidates at a time (pairOffset and isNeighbour on lanes: the same bits),
            // then the neighbours among them packed to the batch's end in candidate order.
            for (int k0 = 0; k0 < take; k0 += 8) {
                const int cnt = take - k0 < 8 ? take - k0 : 8;
                const std::uint32_t j0 = pb + std::uint32_t(k0);
                // Past the row's end the block's next particles are read (their lanes masked
                // off below); records past the block's end are not.
                const simd::Quad8 q = j0 + 8u <= end ? simd::loadQuads(&in.poscell[j0].x)
                                                      : simd::loadQuads(&in.poscell[j0].x, cnt);
                simd::Vec8f dx, dy, dz;
                const simd::Vec8f r = pairOffset<Opt::dim>(par, q, cax, g, dx, dy, dz);
                const unsigned hits = isNeighbour(r, c).bits() & ((1u << cnt) - 1u);
                // The neighbours packed to the batch's end (w + 8 <= kCap + kPad), branch-free.
                simd::leftPackStoreIota(jj + w, pb + std::uint32_t(k0), ~0u, hits);
                simd::leftPackStoreIota(ln + w, seen + std::uint32_t(k0), lanes - 1u, hits);
                simd::leftPackStore(bx + w, dx, hits);
                simd::leftPackStore(by + w, dy, hits);
                simd::leftPackStore(bz + w, dz, hits);
                simd::leftPackStore(br + w, r, hits);
                w += __builtin_popcount(hits);
            }
#else
            for (int k = 0; k < take; ++k) {
                const std::uint32_t j = pb + std::uint32_t(k);
                float drx, dry, drz;
                const float r = pairOffset<Opt::dim>(par, in.poscell[j], cax, g, drx, dry, drz);
                jj[w] = j;
                ln[w] = (seen + std::uint32_t(k)) & (lanes - 1u);
                bx[w] = drx;
                by[w] = dry;
                bz[w] = drz;
                br[w] = r;
                w += isNeighbour(r, c) ? 1 : 0;
            }
#endif
            m = w;
            pb += std::uint32_t(take);
            seen += std::uint32_t(take);
            if (m == kCap) flush(lanes, va, ovrhoa, pressa, taua, in, c, acc);
        }
    }
};

/// The pairs of `psa` with the candidates of one block (`cell_start` of that block), row by row
/// (forEachCandidateRow), candidates numbered from 0 in the block: kCompact (the host), every
/// lane's partial at once into acc[0, lanes); otherwise lane `lane`'s partial into acc[0].
template <class Opt, bool kBound, bool kCompact, bool kMask = false>
SEASPRING_HD inline void fluidPairsInBlock(const std::uint32_t* cell_start, const Float4& psa,
                                           const Float4& va, float ovrhoa, float pressa,
                                           const SymTensor& taua, const InteractionInputs& in,
                                           const FluidConstants& c, const CellGrid& g, std::uint32_t lane,
                                           std::uint32_t lanes, FluidAccum* acc, const RowTable* rows = nullptr) {
    struct Empty {};
    std::conditional_t<kCompact, PairBatch<Opt, kBound>, Empty> batch;
    std::uint32_t seen = 0;
    // The block's end (the host's lane loads may read up to it).
    [[maybe_unused]] const std::uint32_t end = kCompact ? cell_start[g.cellCount()] : 0u;
    auto row = [&](std::uint32_t pb, std::uint32_t pe, const Float4& par, int cax) {
        if constexpr (kCompact)
            batch.addRow(pb, pe, end, seen, lanes, par, cax, va, ovrhoa, pressa, taua, in, c, g, acc);
        else if constexpr (kMask)
            fluidPairsInRowMasked<Opt, kBound>(pb, pe, seen, lane, lanes, par, cax, va, ovrhoa, pressa, taua, in, c, g,
                                               *acc);
        else
            fluidPairsInRow<Opt, kBound>(pb, pe, seen, lane, lanes, par, cax, va, ovrhoa, pressa, taua, in, c, g, *acc);
        seen += pe - pb;
    };
    if (rows != nullptr && !rows->full)
        rows->forEachCandidateRow(psa, cell_start, row);
    else
        forEachCandidateRow<Opt::dim>(psa, cell_start, c, g, row);
    if constexpr (kCompact) batch.flush(lanes, va, ovrhoa, pressa, taua, in, c, acc);
}

/// The partial sums of fluid particle `i` (fluid neighbours, then boundary neighbours): kCompact,
/// all `lanes` partials into acc[0, lanes) in one walk (the host's path); otherwise lane `lane`'s
/// alone into acc[0] (the GPU's path: one thread per lane). acc[] starts as FluidAccum{}.
/// kMask: the fluid block's rows through fluidPairsInRowMasked; the boundary block's always
/// through the direct loop (the same bits either way): its pairs are cheaper (no neighbour
/// stress, velocity gradient or diffusion) and only the warp's particles near a wall walk it,
/// so the mask's second offset per pair costs more there than it saves (FlexStruc Liao 3D 0.99,
/// SPHERIC laminar+SPS 0.985; docs/performance-large.md, twentieth session).
template <class Opt, bool kCompact, bool kMask = false>
SEASPRING_HD inline void fluidLanePartials(std::uint32_t i, std::uint32_t lane, std::uint32_t lanes,
                                           const InteractionInputs& in, const FluidConstants& c, const CellGrid& g,
                                           FluidAccum* acc) {
    const Float4 psa = in.poscell[i];
    const Float4 va = in.velrho[i];
    const Float2 pa2 = in.press_ovrho[i];
    const float pressa = pa2.x, ovrhoa = pa2.y;
    SymTensor taua{0, 0, 0, 0, 0, 0};
    if (Opt::sps) taua = in.tau[i];
    struct NoRows {};
    std::conditional_t<kCompact, RowTable, NoRows> rows;  // the host: the rows once, for both blocks
    const RowTable* rt = nullptr;
    if constexpr (kCompact) {
        rows.template build<Opt::dim>(psa, c, g);
        rt = &rows;
    } else {
        (void)rows;
    }
    fluidPairsInBlock<Opt, false, kCompact, kMask>(in.cell_start_fluid, psa, va, ovrhoa, pressa, taua, in, c, g, lane,
                                                   lanes, acc, rt);
    if (in.near == nullptr || (in.near[linearCellOf(g, psa.w)] & kNearBound) != 0)
        fluidPairsInBlock<Opt, true, kCompact, false>(in.cell_start_bound, psa, va, ovrhoa, pressa, taua, in, c, g,
                                                      lane, lanes, acc, rt);
}

/// Lane `lane`'s partial sums of fluid particle `i` (the GPU's path, one thread per lane;
/// kMask: fluidPairsInRowMasked, the same bits).
template <class Opt, bool kMask = false>
SEASPRING_HD inline FluidAccum fluidLanePartial(std::uint32_t i, std::uint32_t lane, std::uint32_t lanes,
                                                const InteractionInputs& in, const FluidConstants& c,
                                                const CellGrid& g) {
    FluidAccum acc;
    fluidLanePartials<Opt, false, kMask>(i, lane, lanes, in, c, g, &acc);
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

/// Candidates the host filters at once in boundParticleForces (kCompact).
constexpr int kCandidateChunk = 64;

/// What fluid neighbour j adds to DBC boundary particle a: continuity (ar) and the viscous dt
/// measure (visc).
template <class Opt>
SEASPRING_HD inline void boundPair(std::uint32_t j, float drx, float dry, float drz, float rr2, const Float4& va,
                                   const InteractionInputs& in, const FluidConstants& c, float& ar,
                                   float& visc) {
    using K = typename Opt::Kernel;
    const float fac = K::template gradFactor<true>(rr2, c.ker);  // grad W = fac r_ab
    const Float4 vb = in.velrho[j];
    const float dvx = va.x - vb.x, dvy = va.y - vb.y, dvz = va.z - vb.z;
    const float dot_vr = fma32(drx, dvx, fma32(dry, dvy, drz * dvz));
    const float dot_vf = fac * dot_vr;  // v_ab . grad W
    ar = fma32(c.massfluid * dot_vf, va.w * in.press_ovrho[j].y, ar);
    visc = maxf(visc, viscDtPair(dot_vr, reciprocalNormalRange(rr2 + c.eta2)));
}

/// Force evaluation of DBC boundary particle `i`: continuity with fluid neighbours and the
/// viscous dt measure (boundary particles feel no force: their motion is prescribed).
/// The row walk is forEachCandidateRow's; kCompact (the host): the rows from a RowTable (the
/// same rows) and the candidates eight at a time (as PairBatch).
template <class Opt, bool kCompact = false>
SEASPRING_HD inline void boundParticleForces(std::uint32_t i, const InteractionInputs& in,
                                             const FluidConstants& c, const CellGrid& g,
                                             float& ar_out, float& visc_out) {
    const Float4 psa = in.poscell[i];
    const Float4 va = in.velrho[i];
    float ar = 0.f, visc = 0.f;
    ar_out = 0.f;
    visc_out = 0.f;
    if (in.near != nullptr && (in.near[linearCellOf(g, psa.w)] & kNearFluid) == 0) return;  // a dry wall
    // The fluid block's end (the host's lane loads may read up to it).
    [[maybe_unused]] const std::uint32_t end = kCompact ? in.cell_start_fluid[g.cellCount()] : 0u;
    auto row = [&](std::uint32_t pb, std::uint32_t pe, const Float4& par, int cax) {
        if constexpr (!kCompact) {
            for (std::uint32_t j = pb; j < pe; ++j) {
                float drx, dry, drz;
                const float rr2 = pairOffset<Opt::dim>(par, in.poscell[j], cax, g, drx, dry, drz);
                if (!isNeighbour(rr2, c)) continue;
                boundPair<Opt>(j, drx, dry, drz, rr2, va, in, c, ar, visc);
            }
        } else {
#if SEASPRING_SIMD8
            // Eight candidates at a time (as PairBatch::addRow: the same bits), the neighbours'
            // pairs in candidate order.
            for (std::uint32_t j0 = pb; j0 < pe; j0 += 8u) {
                const int cnt = pe - j0 < 8u ? int(pe - j0) : 8;
                const simd::Quad8 q = j0 + 8u <= end ? simd::loadQuads(&in.poscell[j0].x)
                                                      : simd::loadQuads(&in.poscell[j0].x, cnt);
                simd::Vec8f dx, dy, dz;
                const simd::Vec8f r = pairOffset<Opt::dim>(par, q, cax, g, dx, dy, dz);
                unsigned hits = isNeighbour(r, c).bits() & ((1u << cnt) - 1u);
                if (hits == 0u) continue;
                alignas(32) float ox[8], oy[8], oz[8], orr[8];
                simd::store(ox, dx);
                simd::store(oy, dy);
                simd::store(oz, dz);
                simd::store(orr, r);
                for (; hits != 0u; hits &= hits - 1u) {
                    const int k = lowestSetBit(hits);
                    boundPair<Opt>(j0 + std::uint32_t(k), ox[k], oy[k], oz[k], orr[k], va, in, c, ar, visc);
                }
            }
#else
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
#endif
        }
    };
    if constexpr (kCompact) {  // the host: the rows from a RowTable (SIMD rows, the same rows)
        RowTable rows;
        rows.template build<Opt::dim>(psa, c, g);
        if (!rows.full) {
            rows.forEachCandidateRow(psa, in.cell_start_fluid, row);
        } else {
            forEachCandidateRow<Opt::dim>(psa, in.cell_start_fluid, c, g, row);
        }
    } else {
        forEachCandidateRow<Opt::dim>(psa, in.cell_start_fluid, c, g, row);
    }
    ar_out = ar;
    visc_out = visc;
}

}  // namespace seaspring::physics
