// SeaSpring — MIT licence.
/// \file particle_sort.h
/// \brief The divide's sort of one block of particles (solver/engine.h): keys by (cell, id),
///        the execution policy's radix sort, the gather of every field that follows the sort,
///        the block's cell ranges, and its bit of the per-cell near flags. Written once over an
///        execution policy `Exec` and the particle store, as the rest of the engine.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <type_traits>

#include "physics/cell_grid.h"
#include "physics/particle_fields.h"
#include "solver/launch.h"
#include "solver/particle_passes.h"

namespace seaspring::solver {

/// The divide's sort memory, in the force-evaluation fields (physics::kForceEval), which
/// nothing reads between a divide and the next force evaluation: keys (8 bytes a particle) in
/// press_ovrho, the permutation (4) in visc, the second key and permutation buffers (8 + 4)
/// and the stayer flags (1) and then the gather scratch (16) in acear.
struct SortMemory {
    std::uint64_t* keys;
    std::uint32_t* perm;
    std::uint64_t* keys_alt;
    std::uint32_t* perm_alt;
    std::uint8_t* stays;
    void* scratch;  ///< 16 bytes a particle
};

/// The merge (sortKeys) is taken while the movers are at most this share of a block
/// (1 / kMergeMoverShare); above it the whole block is radix-sorted.
constexpr std::uint32_t kMergeMoverShare = 4;
/// Blocks smaller than this are radix-sorted whole: there the merge's extra launches and
/// readback cost more than the radix passes they save (NVIDIA H200, FlexStruc Liao 2D, 28 k
/// particles: 1.04-1.08 of the whole sort; docs/performance-large.md, twenty-sixth session).
constexpr std::uint32_t kMergeMinParticles = 1u << 17;

/// SEASPRING_SORT_MERGE_MIN (a non-negative integer: the tests merge their small blocks with 1),
/// else kMergeMinParticles; read once per engine.
inline std::uint32_t sortMergeMinFromEnv() {
    const char* env = std::getenv("SEASPRING_SORT_MERGE_MIN");
    if (env == nullptr || *env == '\0') return kMergeMinParticles;
    char* end = nullptr;
    const unsigned long v = std::strtoul(env, &end, 10);
    return *end == '\0' ? std::uint32_t(std::min<unsigned long>(v, 0xffffffffUL)) : kMergeMinParticles;
}

template <class Store>
SortMemory sortMemoryOf(Store& p) {
    static_assert(sizeof(physics::Float2) == sizeof(std::uint64_t) && sizeof(float) == sizeof(std::uint32_t) &&
                      sizeof(physics::Float4) == 2 * sizeof(std::uint64_t),
                  "the sort memory layout assumes these sizes");
    auto* alt = reinterpret_cast<std::uint64_t*>(p.acear.data());
    auto* perm_alt = reinterpret_cast<std::uint32_t*>(alt + p.acear.size());
    return SortMemory{reinterpret_cast<std::uint64_t*>(p.press_ovrho.data()), reinterpret_cast<std::uint32_t*>(p.visc.data()),
                      alt, perm_alt, reinterpret_cast<std::uint8_t*>(perm_alt + p.acear.size()), alt};
}

/// Words [k, k + K) of every element of [b, e) reordered by the permutation, through the scratch.
template <std::uint32_t K, class Exec, class W>
void gatherWords(Exec& exec, W* words, std::uint32_t n_words, std::uint32_t k, std::uint32_t b, std::uint32_t e,
                 const SortMemory& m) {
    static_assert(K * sizeof(W) <= sizeof(physics::Float4), "a chunk fits the 16-byte scratch");
    W* tmp = reinterpret_cast<W*>(m.scratch);  // particle i's slot: tmp + i * K (K words <= 16 bytes)
    exec.template forEach<LaunchDefault>(b, e, GatherWordsPass<W, K>{m.perm, words, n_words, k, tmp});
    exec.template forEach<LaunchDefault>(b, e, PutWordsPass<W, K>{tmp, n_words, k, words});
}

/// Reorders [b, e) of a sorted field by the permutation of the last sort, through the 16-byte
/// scratch: a field of up to 16 bytes whole, a wider one in chunks of up to 16 bytes (a gather
/// and a put-back each; Double3 and SymTensor, 24 bytes: two chunks).
template <class Exec, class BufT>
void gatherSorted(Exec& exec, BufT& arr, std::uint32_t b, std::uint32_t e, const SortMemory& m) {
    using T = std::remove_pointer_t<decltype(arr.data())>;
    if (arr.empty() || e <= b) return;
    if constexpr (sizeof(T) <= sizeof(physics::Float4)) {
        T* tmp = reinterpret_cast<T*>(m.scratch);
        exec.template forEach<LaunchDefault>(b, e, GatherPass<T>{m.perm, arr.data(), tmp});
        exec.copy(arr.data() + b, tmp + b, e - b);
    } else {
        using W = std::conditional_t<sizeof(T) % sizeof(std::uint64_t) == 0 && alignof(T) >= alignof(std::uint64_t),
                                     std::uint64_t, std::uint32_t>;
        static_assert(sizeof(T) % sizeof(W) == 0, "a field is a whole number of words");
        constexpr std::uint32_t kWords = sizeof(T) / sizeof(W);
        constexpr std::uint32_t kChunk = std::uint32_t(sizeof(physics::Float4) / sizeof(W));  // words per chunk
        W* words = reinterpret_cast<W*>(arr.data());
        std::uint32_t k = 0;
        for (; k + kChunk <= kWords; k += kChunk) gatherWords<kChunk>(exec, words, kWords, k, b, e, m);
        if constexpr (kWords % kChunk >= 2) {
            static_assert(kWords % kChunk == 2, "the last chunk of the fields there are");
            gatherWords<2>(exec, words, kWords, k, b, e, m);
        } else if constexpr (kWords % kChunk == 1) {
            gatherWords<1>(exec, words, kWords, k, b, e, m);
        }
    }
}

/// Sorts the keys and the identity permutation of [b, e) (SortKeyPass) into m.keys and m.perm;
/// returns the end of the active part (the first key >= `excluded`). Between two sorts most
/// particles stay in the cell of their last sort, so the block's order still holds for them:
/// their indices are taken in that order (exec.stayersFirst, which checks that their keys
/// ascend and counts the keys >= `excluded`), only the movers are radix-sorted, and the two
/// sequences are merged. Keys are unique, so the result is the one sorted order whichever way:
/// the same permutation as a sort of the whole block, which runs (and exec.lowerBound finds the
/// active end) when the check fails, when more than 1 / kMergeMoverShare of the block moved, or
/// when no order is kept (the first sort), and for blocks of fewer than `min_merge` particles.
/// *merged (when given) says which way it went. m.stays[b, e) is read; m.keys_alt and
/// m.perm_alt are scratch.
template <class Exec>
std::uint32_t sortKeys(Exec& exec, const SortMemory& m, std::uint32_t b, std::uint32_t e, std::uint64_t excluded,
                       bool* merged = nullptr, std::uint32_t min_merge = kMergeMinParticles) {
    if (merged) *merged = false;
    if (e <= b) return b;
    const std::uint32_t n = e - b;
    std::uint32_t nexcl = 0;
    const std::uint32_t nstay =
        n >= min_merge ? exec.stayersFirst(m.keys, m.perm, m.stays, m.keys_alt, m.perm_alt, b, e, excluded, nexcl) : 0;
    if (nstay == 0 || n - nstay > n / kMergeMoverShare) {
        exec.sortPairs(m.keys, m.keys_alt, m.perm, m.perm_alt, b, e);
        return exec.lowerBound(m.keys, b, e, excluded);
    }
    // The movers, [b + nstay, e) of the *_alt arrays, sorted there (m.keys and m.perm: its second buffers).
    exec.sortPairs(m.keys_alt, m.keys, m.perm_alt, m.perm, b + nstay, e);
    exec.mergePairs(m.keys_alt, m.perm_alt, b, b + nstay, e, m.keys, m.perm);
    if (merged) *merged = true;
    return e - nexcl;
}

/// Sorts [b, e) by (cell, id), excluded last (sortKeys, merging from `min_merge` particles;
/// *merged, when given, says whether it did);
/// gathers the fields that follow the sort (kSorted; kSortedPre when `pre`); rebuilds the cell
/// ranges `cs` for the active part. Returns its end.
template <class Exec, class Store, class CellStarts>
std::uint32_t sortBlockRange(Exec& exec, Store& p, const physics::CellGrid& g, std::uint32_t b, std::uint32_t e,
                             CellStarts& cs, bool pre, std::uint32_t min_merge = kMergeMinParticles,
                             bool* merged = nullptr) {
    const SortMemory m = sortMemoryOf(p);
    std::uint32_t active_end = b;
    if (e > b) {
        // The stayer flags only where sortKeys may merge (small blocks sort whole).
        exec.template forEach<LaunchDefault>(b, e, SortKeyPass{p.view(), g, m.keys, m.perm,
                                                               e - b >= min_merge ? m.stays : nullptr});
        active_end = sortKeys(exec, m, b, e, physics::kExcludedCell << 32, merged, min_merge);
        p.forEachField([&](auto& buf, unsigned flags, physics::FieldNeed) {
            if ((flags & physics::kSorted) || (pre && (flags & physics::kSortedPre))) gatherSorted(exec, buf, b, e, m);
        });
    }
    exec.template forEach<LaunchDefault>(0u, std::uint32_t(cs.size()), CellStartOuterPass{b, active_end, m.keys, cs.data()});
    exec.template forEach<LaunchDefault>(b, active_end, CellStartFillPass{b, m.keys, cs.data()});
    return active_end;
}

/// Bit `bit` of the per-cell near flags `near` from the cell ranges `cs` of its block, through
/// the scratch `tmp` (physics::nearAlongXAt per cell, nearAlongYSegment and nearAlongZSegment
/// per segment of a column; the other bit is kept).
template <class Exec, class CellStarts, class Flags>
void nearFlagsOfBlock(Exec& exec, const physics::CellGrid& g, const CellStarts& cs, std::uint8_t bit, Flags& near,
                      Flags& tmp) {
    const std::uint32_t nx = std::uint32_t(g.ncx), ny = std::uint32_t(g.ncy), nz = std::uint32_t(g.ncz);
    std::uint8_t *a = near.data(), *t = tmp.data();
    exec.template forEach<LaunchDefault>(0u, g.cellCount(), NearAlongXPass{g, cs.data(), bit, a});
    exec.template forEach<LaunchDefault>(0u, nx * nz * physics::nearSegments(g.ncy), NearAlongYPass{g, bit, a, t});
    exec.template forEach<LaunchDefault>(0u, nx * ny * physics::nearSegments(g.ncz), NearAlongZPass{g, bit, t, a});
}

}  // namespace seaspring::solver
