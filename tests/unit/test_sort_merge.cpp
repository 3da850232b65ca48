// SeaSpring — MIT licence.
/// \file test_sort_merge.cpp
/// \brief The divide's sort (solver::sortKeys) with the host's execution policy: the stayers'
///        order kept, the movers sorted and merged, gives the one sorted order of the keys and
///        the permutation that goes with it, as a sort of the whole block, and the end of the
///        active part (excluded keys last) counted on the way; stayer flags that do
///        not hold (stayers whose keys do not ascend), too many movers, blocks with no
///        stayer and blocks below the merge's size fall back to that sort. The GPU's primitives are checked through the solver:
///        the typed BackendPhases tests compare every divide's state with the host's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

#include "cpu/host_exec.h"
#include "solver/particle_sort.h"

using seaspring::cpu::HostExec;
using seaspring::solver::SortMemory;
using seaspring::solver::sortKeys;

namespace {

/// One block [b, e) inside arrays of n: keys from a sorted (cell, id) order in which `moved`
/// particles took another cell; stays set where the cell is unchanged (as SortKeyPass does).
struct Block {
    std::vector<std::uint64_t> keys, keys_alt;
    std::vector<std::uint32_t> perm, perm_alt;
    std::vector<std::uint8_t> stays;
    std::uint32_t b, e;

    Block(std::uint32_t n, std::uint32_t b_, std::uint32_t e_, double moved, std::mt19937& rng)
        : keys(n, ~0ull), keys_alt(n, 0), perm(n, 0), perm_alt(n, 0), stays(n, 0), b(b_), e(e_) {
        // The last sort's order: cells ascending, ids ascending in a cell (ids unique).
        std::vector<std::uint32_t> ids(e - b);
        std::iota(ids.begin(), ids.end(), 100u);
        std::shuffle(ids.begin(), ids.end(), rng);
        std::vector<std::uint64_t> old(e - b);
        std::uniform_int_distribution<std::uint32_t> cell(0, (e - b) / 2);
        for (std::uint32_t k = 0; k < e - b; ++k) old[k] = (std::uint64_t(cell(rng)) << 32) | ids[k];
        std::sort(old.begin(), old.end());
        std::uniform_real_distribution<double> u(0, 1);
        std::uniform_int_distribution<int> step(-3, 3);
        for (std::uint32_t i = b; i < e; ++i) {
            std::uint64_t k = old[i - b];
            if (u(rng) < moved) {  // another cell (or excluded: the last cells)
                const std::uint32_t c = std::uint32_t(k >> 32);
                const std::uint32_t nc = u(rng) < 0.1 ? 0xFFFFFFFFu : std::uint32_t(std::max(0, int(c) + step(rng)));
                k = (std::uint64_t(nc) << 32) | (k & 0xFFFFFFFFull);
            }
            keys[i] = k;
            perm[i] = i;
            stays[i] = (k >> 32) == (old[i - b] >> 32) ? 1 : 0;
        }
    }
    SortMemory memory() {
        return SortMemory{keys.data(), perm.data(), keys_alt.data(), perm_alt.data(), stays.data(), keys_alt.data()};
    }
    /// The whole block sorted by key: the expected keys and permutation.
    void expected(std::vector<std::uint64_t>& k, std::vector<std::uint32_t>& p) const {
        std::vector<std::pair<std::uint64_t, std::uint32_t>> v;
        for (std::uint32_t i = b; i < e; ++i) v.emplace_back(keys[i], perm[i]);
        std::sort(v.begin(), v.end());
        for (const auto& x : v) k.push_back(x.first), p.push_back(x.second);
    }
};

/// Sorts the block (every size may merge: min_merge 1, or `min_merge`) and checks the result.
void expectSorted(Block& blk, bool expect_merge, std::uint32_t min_merge = 1) {
    std::vector<std::uint64_t> k;
    std::vector<std::uint32_t> p;
    blk.expected(k, p);
    const std::vector<std::uint64_t> before(blk.keys);
    const std::uint64_t excluded = 0xFFFFFFFFull << 32;
    const std::uint32_t active_end = blk.b + std::uint32_t(std::lower_bound(k.begin(), k.end(), excluded) - k.begin());
    HostExec exec(2);
    bool merged = !expect_merge;
    EXPECT_EQ(sortKeys(exec, blk.memory(), blk.b, blk.e, excluded, &merged, min_merge), active_end)
        << "the active part's end";
    EXPECT_EQ(merged, expect_merge);
    for (std::uint32_t i = blk.b; i < blk.e; ++i) {
        ASSERT_EQ(blk.keys[i], k[i - blk.b]) << "key at " << i;
        ASSERT_EQ(blk.perm[i], p[i - blk.b]) << "permutation at " << i;
        ASSERT_EQ(before[blk.perm[i]], blk.keys[i]) << "the permutation names the key's old place, at " << i;
    }
    for (std::uint32_t i = 0; i < blk.b; ++i) EXPECT_EQ(blk.keys[i], ~0ull) << "outside the block, at " << i;
}

}  // namespace

TEST(SortMerge, FewMoversMergedGiveTheWholeSortsOrder) {
    std::mt19937 rng(11);
    for (double moved : {0.0, 0.01, 0.1, 0.2}) {  // 0.2 with n 17: sometimes above the share
        for (std::uint32_t n : {2u, 17u, 1000u, 20000u}) {
            Block blk(n + 7, 5, 5 + n, moved, rng);
            std::uint32_t movers = 0;
            for (std::uint32_t i = blk.b; i < blk.e; ++i) movers += blk.stays[i] == 0;
            SCOPED_TRACE(testing::Message() << "n " << n << " moved " << moved << " movers " << movers);
            expectSorted(blk, movers < n && movers <= n / seaspring::solver::kMergeMoverShare);
            if (n >= 1000 && moved > 0) {
                EXPECT_GT(movers, 0u);
            }
        }
    }
}

TEST(SortMerge, ManyMoversOrNoStayersSortTheWholeBlock) {
    std::mt19937 rng(12);
    for (double moved : {0.5, 1.0}) {
        Block blk(5000, 0, 5000, moved, rng);
        std::uint32_t movers = 0;
        for (std::uint32_t i = blk.b; i < blk.e; ++i) movers += blk.stays[i] == 0;
        ASSERT_GT(movers, 5000u / seaspring::solver::kMergeMoverShare);
        expectSorted(blk, false);
    }
    Block none(300, 0, 300, 0.0, rng);  // e.g. the first sort: no particle has a cell yet
    std::fill(none.stays.begin(), none.stays.end(), 0);
    expectSorted(none, false);
}

TEST(SortMerge, SmallBlocksSortWhole) {
    std::mt19937 rng(14);
    Block small(1000, 0, 1000, 0.05, rng);
    expectSorted(small, false, 1001);
    Block large(1000, 0, 1000, 0.05, rng);
    expectSorted(large, true, 1000);
    EXPECT_GT(seaspring::solver::kMergeMinParticles, 20000u) << "the solver's small cases sort whole";
}

TEST(SortMerge, StayersWhoseKeysDoNotAscendSortTheWholeBlock) {
    std::mt19937 rng(13);
    Block blk(4000, 0, 4000, 0.05, rng);
    // A mover flagged as a stayer (PosCell naming a cell its key does not have).
    for (std::uint32_t i = blk.b; i < blk.e; ++i)
        if (blk.stays[i] == 0 && (blk.keys[i] >> 32) != 0xFFFFFFFFu && i + 1 < blk.e && blk.keys[i] > blk.keys[i + 1]) {
            blk.stays[i] = 1;
            break;
        }
    expectSorted(blk, false);
}
