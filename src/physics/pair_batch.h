// SeaSpring — MIT licence.
/// \file pair_batch.h
/// \brief The host's batched form of the pair loops (kCompact): a particle's neighbours are
///        gathered from its candidate rows eight candidates at a time, their terms computed in
///        SIMD lanes, and the terms summed one by one in candidate order: the same operations in
///        the same order as the direct loop (fluid_interaction.h), so the same bits, at a
///        fraction of the cost of a mispredicted branch per candidate and scalar pair arithmetic.
#pragma once

#include <cstdint>

#include "physics/fluid_pair_terms.h"

namespace seaspring::physics {

/// The neighbours of one particle found so far in its candidate rows (candidates that passed
/// isNeighbour, in candidate order): index, offset and r^2 (a pair lane is its index mod the
/// lanes: fluid_interaction.h).
struct NeighbourBatch {
    static constexpr int kCap = 256;
    // (kPad more: the host's SIMD loop stores eight lanes at the batch's end, SEASPRING_SIMD8.)
    static constexpr int kPad = 8;
    std::uint32_t jj[kCap + kPad];
    float bx[kCap + kPad], by[kCap + kPad], bz[kCap + kPad], br[kCap + kPad];
    int m = 0;

    /// Candidates [pb, pe) of a block whose particles end at `end` (the lane loads may read
    /// records [pe, end)): the neighbours among the first min(pe - pb, kCap - m) of them are
    /// appended (branch-free: every candidate is written at m, m advances on a neighbour);
    /// returns how many candidates were taken.
    template <int kDim>
    SEASPRING_HD std::uint32_t fill(std::uint32_t pb, std::uint32_t pe, [[maybe_unused]] std::uint32_t end,
                                    const Float4& par, int cax, const InteractionInputs& in, const FluidConstants& c,
                                    const CellGrid& g) {
        const int take = pe - pb > std::uint32_t(kCap - m) ? kCap - m : int(pe - pb);
        int w = m;  // w <= m + k < kCap inside the loop
#if SEASPRING_SIMD8
        // Eight candidates at a time (pairOffset and isNeighbour on lanes: the same bits), then
        // the neighbours among them packed to the batch's end in candidate order.
        for (int k0 = 0; k0 < take; k0 += 8) {
            const int cnt = take - k0 < 8 ? take - k0 : 8;
            const std::uint32_t j0 = pb + std::uint32_t(k0);
            // Past the row's end the block's next particles are read (their lanes masked off
            // below); records past the block's end are not.
            const simd::Quad8 q =
                j0 + 8u <= end ? simd::loadQuads(&in.poscell[j0].x) : simd::loadQuads(&in.poscell[j0].x, cnt);
            simd::Vec8f dx, dy, dz;
            const simd::Vec8f r = pairOffset<kDim>(par, q, cax, g, dx, dy, dz);
            const unsigned hits = isNeighbour(r, c).bits() & ((1u << cnt) - 1u);
            // The neighbours packed to the batch's end (w + 8 <= kCap + kPad), branch-free.
            simd::leftPackStoreIota(jj + w, j0, ~0u, hits);
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
            const float r = pairOffset<kDim>(par, in.poscell[j], cax, g, drx, dry, drz);
            jj[w] = j;
            bx[w] = drx;
            by[w] = dry;
            bz[w] = drz;
            br[w] = r;
            w += isNeighbour(r, c) ? 1 : 0;
        }
#endif
        m = w;
        return std::uint32_t(take);
    }
};

/// A fluid particle's pairs (fluidPairsInBlock, kCompact). Pair lanes: a neighbour's terms go to
/// its lane's partial sum, acc[j mod lanes].
template <class Opt, bool kBound>
struct PairBatch : NeighbourBatch {
    static constexpr bool kLaminar = Opt::visco != Viscosity::Artificial;
    static constexpr bool kSps = Opt::sps;
    // Their terms, one array per field (so that the SIMD lanes store whole vectors).
    // m and the continuity term's v together (one 16-byte record per pair: the in-order sum
    // reads them with one load).
    alignas(16) float tm[kCap][4];
    float tcf[kSps ? 1 : kCap], tarw[kCap], tdv[kCap], tdw[kCap], tvisc[kCap];
    float tcv[kLaminar ? kCap : 1], tdvx[kLaminar ? kCap : 1], tdvy[kLaminar ? kCap : 1], tdvz[kLaminar ? kCap : 1];
    float tsxx[kSps ? kCap : 1], tsxy[kSps ? kCap : 1], tsxz[kSps ? kCap : 1], tsyy[kSps ? kCap : 1],
        tsyz[kSps ? kCap : 1], tszz[kSps ? kCap : 1];
    float tux[kSps ? kCap : 1], tuy[kSps ? kCap : 1], tuz[kSps ? kCap : 1];

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
        if (lanes == 1u) {
            FluidAccum a = acc[0];
            for (int q = 0; q < n; ++q) addPairTerms<Opt, kBound>(a, termsAt(q));
            acc[0] = a;
        } else {
            const std::uint32_t lane_mask = lanes - 1u;
            for (int q = 0; q < n; ++q) addPairTerms<Opt, kBound>(acc[sj[q] & lane_mask], termsAt(q));
        }
        m = 0;
    }


    /// Candidates [pb, pe) of one row (NeighbourBatch::fill), flushed whenever the batch is full.
    SEASPRING_HD void addRow(std::uint32_t pb, std::uint32_t pe, std::uint32_t end, std::uint32_t lanes,
                             const Float4& par, int cax, const Float4& va, float ovrhoa,
                             float pressa, const SymTensor& taua, const InteractionInputs& in, const FluidConstants& c,
                             const CellGrid& g, FluidAccum* acc) {
        while (pb < pe) {
            pb += fill<Opt::dim>(pb, pe, end, par, cax, in, c, g);
            if (m == kCap) flush(lanes, va, ovrhoa, pressa, taua, in, c, acc);
        }
    }
};

/// A DBC boundary particle's pairs with its fluid neighbours (boundParticleForces, kCompact):
/// continuity and the viscous dt measure.
template <class Opt>
struct BoundBatch : NeighbourBatch {
    float tv[kCap], tw[kCap], tvisc[kCap];

    /// The batch's pairs: their terms in SIMD lanes, then added to (ar, visc) in candidate order.
    SEASPRING_HD void flush(const Float4& va, const InteractionInputs& in, const FluidConstants& c, float& ar,
                            float& visc) {
        const int n = m;
        const std::uint32_t* __restrict sj = jj;
        const float *__restrict sx = bx, *__restrict sy = by, *__restrict sz = bz, *__restrict sr = br;
        for (int q = 0; q < n; ++q) {  // SIMD lanes
            const BoundPairTerms t = boundPairTerms<Opt>(sj[q], sx[q], sy[q], sz[q], sr[q], va, in, c);
            tv[q] = t.ar.v;
            tw[q] = t.ar.w;
            tvisc[q] = t.visc;
        }
        for (int q = 0; q < n; ++q) addBoundPairTerms(ar, visc, BoundPairTerms{ProductTerm{tv[q], tw[q]}, tvisc[q]});
        m = 0;
    }

    /// Candidates [pb, pe) of one row (NeighbourBatch::fill), flushed whenever the batch is full.
    SEASPRING_HD void addRow(std::uint32_t pb, std::uint32_t pe, std::uint32_t end, const Float4& par, int cax,
                             const Float4& va, const InteractionInputs& in, const FluidConstants& c,
                             const CellGrid& g, float& ar, float& visc) {
        while (pb < pe) {
            pb += fill<Opt::dim>(pb, pe, end, par, cax, in, c, g);
            if (m == kCap) flush(va, in, c, ar, visc);
        }
    }
};

}  // namespace seaspring::physics
