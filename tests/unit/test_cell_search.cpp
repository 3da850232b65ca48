// SeaSpring — MIT licence.
/// \file test_cell_search.cpp
/// \brief The per-cell "near" flags (nearAlongXAt per cell, nearAlongYSegment and
///        nearAlongZSegment per segment of a column of cells, one bit per block) against a brute-force scan of each cell's search box, for every cell mode in
///        2D and 3D, with and without a skin: a particle may skip a block only where it holds
///        nothing; building one block's bit keeps the other's.
///        The candidate rows of forEachCandidateRow against a brute-force pair scan: every
///        neighbour is among them, visited in sorted order; and the rows walked (rowsAlongY
///        bounding each z's rows) are exactly those rowCells accepts over the whole search box;
///        the host's RowTable (SIMD rows) holds the same rows and row frames, bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include "physics/cell_grid.h"
#include "physics/neighbour_rows.h"
#include "physics/particle_updates.h"

using namespace seaspring::physics;

TEST(CellSearch, NearFlagsEqualABruteForceScanOfTheSearchBox) {
    std::mt19937 rng(7);
    for (int dim : {2, 3}) {
        for (int div : {1, 2, 3, 4, kCellDivSpacing})
          for (double skin : {0.0, 0.05}) {
            CellGrid g;  // cells of dp: h = 1.73 dp (coefh 1 in 3D), the search reaches 4 cells
            ASSERT_TRUE(makeCellGrid(0, 0, 0, 1.0, dim == 3 ? 0.9 : 0.0, 0.9, 0.05, div, g, skin, 0.05 / 1.7320508));
            if (div == kCellDivSpacing) {
                ASSERT_EQ(g.range, 4 + (skin > 0 ? 1 : 0));
            }
            const std::uint32_t nc = g.cellCount();
            // Sparse occupancy (about one occupied cell per search box; occupied cells hold 1-3
            // particles), as a block's cell ranges: near and far cells both occur.
            std::uint32_t box = 1;
            for (int k = 0; k < dim; ++k) box *= std::uint32_t(2 * g.range + 1);
            std::vector<std::uint32_t> cs(nc + 1, 0);
            std::vector<std::uint8_t> occupied(nc, 0);
            std::uint32_t n = 0;
            for (std::uint32_t c = 0; c < nc; ++c) {
                cs[c] = n;
                if (rng() % box == 0) {
                    occupied[c] = 1;
                    n += 1 + rng() % 3;
                }
            }
            cs[nc] = n;
            // The other block's bit (kNearBound), random, must come through untouched.
            std::vector<std::uint8_t> a(nc), t(nc), other(nc);
            for (std::uint32_t c = 0; c < nc; ++c) a[c] = other[c] = std::uint8_t(rng() % 2 ? kNearBound : 0);
            const std::uint8_t bit = kNearFluid;
            // As solver/particle_sort.h's nearFlagsOfBlock runs them (t: scratch, stale values).
            for (std::uint32_t c = 0; c < nc; ++c) t[c] = std::uint8_t(rng());
            for (std::uint32_t c = 0; c < nc; ++c) nearAlongXAt(c, g, cs.data(), bit, a.data());
            for (std::uint32_t q = 0; q < std::uint32_t(g.ncx * g.ncz) * nearSegments(g.ncy); ++q)
                nearAlongYSegment(q, g, bit, a.data(), t.data());
            for (std::uint32_t q = 0; q < std::uint32_t(g.ncx * g.ncy) * nearSegments(g.ncz); ++q)
                nearAlongZSegment(q, g, bit, t.data(), a.data());
            int near = 0, far = 0, wrong = 0;
            for (int cz = 0; cz < g.ncz; ++cz)
                for (int cy = 0; cy < g.ncy; ++cy)
                    for (int cx = 0; cx < g.ncx; ++cx) {
                        std::uint8_t any = 0;
                        for (int z = cz - g.range; z <= cz + g.range; ++z)
                            for (int y = cy - g.range; y <= cy + g.range; ++y)
                                for (int x = cx - g.range; x <= cx + g.range; ++x)
                                    if (x >= 0 && y >= 0 && z >= 0 && x < g.ncx && y < g.ncy && z < g.ncz)
                                        any |= occupied[g.linear(x, y, z)];
                        const std::uint32_t c = g.linear(cx, cy, cz);
                        const std::uint8_t flag = (a[c] & bit) ? 1 : 0;
                        wrong += flag != any ? 1 : 0;
                        wrong += (a[c] & kNearBound) != other[c] ? 1 : 0;
                        (any ? near : far) += 1;
                    }
            EXPECT_EQ(wrong, 0) << dim << "D, cells of 2h/" << div;
            EXPECT_GT(near, 0) << dim << "D, cells of 2h/" << div;  // both kinds occur: the check can fail
            EXPECT_GT(far, 0) << dim << "D, cells of 2h/" << div;
            if (div == 4) {  // columns of more than one segment: the sweeps' seams are checked
                EXPECT_GT(nearSegments(g.ncz), 1u);
                if (dim == 3) {
                    EXPECT_GT(nearSegments(g.ncy), 1u);
                }
            }
          }
    }
}

namespace {

/// Random particles in a box, cell-sorted, with their block's cell starts; then, for every
/// particle, the neighbours found through forEachCandidateRow against all particles tested with
/// the same pair offset (the frame of the row holding the partner, as hydroForceOnBoundary).
/// With `skin` > 0 every particle is then moved by up to the skin (along each axis, most of
/// them nearly that far) and keeps the cell it was sorted into (posCellInCell), as between two
/// sorts of a run: the rows must still hold every neighbour.
template <int kDim>
void checkCandidateRows(int div, std::mt19937& rng, double skin = 0.0) {
    const double h = 0.03;
    CellGrid g;  // kCellDivSpacing: cells of dp with h = 1.73 dp, as DualSPHysics' coefh 1 in 3D
    ASSERT_TRUE(makeCellGrid(0, 0, 0, 0.4, kDim == 3 ? 0.25 : 0.0, 0.3, h, div, g, skin, h / 1.7320508));
    FluidConstants c;
    c.ker.kernelsize2 = float((2.0 * h) * (2.0 * h));
    const std::uint32_t n = kDim == 3 ? 1500 : 500;
    std::uniform_real_distribution<double> ux(0, 0.4), uy(0, 0.25), uz(0, 0.3);
    std::vector<Float4> pc(n);
    std::vector<std::uint32_t> cell(n), order(n);
    std::uniform_real_distribution<double> far(0.9, 1.0);
    std::bernoulli_distribution sign(0.5);
    auto move = [&] { return (sign(rng) ? 1.0 : -1.0) * far(rng) * skin * g.cellsize; };
    for (std::uint32_t i = 0; i < n; ++i) {
        const Double3 p{ux(rng), kDim == 3 ? uy(rng) : 0.0, uz(rng)};
        pc[i] = makePosCell(g, p, cell[i]);
        if (skin > 0) {
            const Double3 moved{p.x + move(), kDim == 3 ? p.y + move() : 0.0, p.z + move()};
            bool outside = true;
            pc[i] = posCellInCell(g, moved, pc[i].w, outside);
            ASSERT_FALSE(outside) << "particle " << i << " moved out of the skin";
        }
    }
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return cell[a] < cell[b]; });
    std::vector<Float4> ps(n);
    const std::uint32_t nc = g.cellCount();
    std::vector<std::uint32_t> cs(nc + 1, 0);
    for (std::uint32_t k = 0; k < n; ++k) {
        ps[k] = pc[order[k]];
        ++cs[cell[order[k]] + 1];
    }
    for (std::uint32_t k = 0; k < nc; ++k) cs[k + 1] += cs[k];
    std::vector<std::uint32_t> identity(nc + 1);  // cell starts that give a row's cells themselves
    std::iota(identity.begin(), identity.end(), 0u);
    long long pairs = 0;
    for (std::uint32_t a = 0; a < n; ++a) {
        const Float4 psa = ps[a];
        std::vector<std::uint32_t> seen, found;
        forEachCandidateRow<kDim>(psa, cs.data(), c, g, [&](std::uint32_t pb, std::uint32_t pe, const Float4& par, int cax) {
            for (std::uint32_t j = pb; j < pe; ++j) {
                seen.push_back(j);
                float dx, dy, dz;
                if (isNeighbour(pairOffset<kDim>(par, ps[j], cax, g, dx, dy, dz), c)) found.push_back(j);
            }
        });
        // The rows walked are the rows of the search box that rowCells accepts, in order.
        std::vector<std::uint32_t> walked, accepted;
        forEachRowInReach<kDim>(psa, c, g, [&](std::uint32_t c0, std::uint32_t c1, const Float4&, int) {
            walked.push_back(c0);
            walked.push_back(c1);
        });
        const SearchBox box = searchBox<kDim>(psa, g);
        for (int z = box.z0; z <= box.z1; ++z) {
            const float gz = cellGap(z - box.caz, psa.z, g.cellsizef, box.margin);
            for (int y = box.y0; y <= box.y1; ++y) {
                std::uint32_t c0, c1;
                if (!rowCells<kDim>(box, psa, y, z, gz, c, g, c0, c1)) continue;
                accepted.push_back(c0);
                accepted.push_back(c1);
            }
        }
        ASSERT_EQ(walked, accepted) << kDim << "D, cells of 2h/" << div << ", skin " << skin << ", particle " << a;
        // The host's RowTable (eight rows along y at a time where SEASPRING_SIMD8) holds the
        // same rows with the same row frames, bit for bit.
        std::vector<std::uint32_t> frames, tabled, tabled_frames;
        forEachRowInReach<kDim>(psa, c, g, [&](std::uint32_t, std::uint32_t, const Float4& par, int x) {
            frames.insert(frames.end(), {floatBitsToUint(par.x), floatBitsToUint(par.y), floatBitsToUint(par.z),
                                         floatBitsToUint(par.w), std::uint32_t(x)});
        });
        RowTable table;
        table.build<kDim>(psa, c, g);
        ASSERT_FALSE(table.full);
        for (int k = 0; k < table.n; ++k) {
            tabled.push_back(table.c0[k]);
            tabled.push_back(table.c1[k]);
        }
        table.forEachCandidateRow(psa, identity.data(), [&](std::uint32_t, std::uint32_t, const Float4& par, int x) {
            tabled_frames.insert(tabled_frames.end(), {floatBitsToUint(par.x), floatBitsToUint(par.y),
                                                       floatBitsToUint(par.z), floatBitsToUint(par.w),
                                                       std::uint32_t(x)});
        });
        ASSERT_EQ(tabled, walked) << kDim << "D, cells of 2h/" << div << ", skin " << skin << ", particle " << a;
        ASSERT_EQ(tabled_frames, frames) << kDim << "D, cells of 2h/" << div << ", skin " << skin << ", particle " << a;
        ASSERT_TRUE(std::is_sorted(seen.begin(), seen.end()) &&
                    std::adjacent_find(seen.begin(), seen.end()) == seen.end())
            << "candidates out of order, particle " << a;
        std::vector<std::uint32_t> expected;
        const int cay = kDim == 3 ? packedCellY(g, psa.w) : 0, caz = packedCellZ(g, psa.w);
        const int cax = packedCellX(g, psa.w);
        for (std::uint32_t b = 0; b < n; ++b) {
            const Float4 psb = ps[b];
            const float rowdy = kDim == 3 ? g.cellsizef * float(cay - packedCellY(g, psb.w)) : 0.f;
            const float rowdz = g.cellsizef * float(caz - packedCellZ(g, psb.w));
            float dx, dy, dz;
            if (isNeighbour(pairOffset<kDim>(rowFrame(psa, rowdy, rowdz), psb, cax, g, dx, dy, dz), c))
                expected.push_back(b);
        }
        ASSERT_EQ(found, expected) << kDim << "D, cells of 2h/" << div << ", skin " << skin << ", particle " << a;
        pairs += static_cast<long long>(found.size());
        ASSERT_LT(seen.size(), std::size_t(n));  // the rows leave most particles out
    }
    EXPECT_GT(pairs, 10LL * n) << kDim << "D, cells of 2h/" << div;
}

}  // namespace

TEST(CellSearch, CandidateRowsHoldEveryNeighbourInSortedOrder) {
    std::mt19937 rng(3);
    for (int div : {1, 2, 3, kCellDivSpacing}) {
        checkCandidateRows<2>(div, rng);
        checkCandidateRows<3>(div, rng);
    }
}

TEST(CellSearch, CandidateRowsHoldEveryNeighbourOfParticlesMovedWithinTheSkin) {
    std::mt19937 rng(5);
    for (int div : {1, 2, 4, kCellDivSpacing})
        for (double skin : {0.05, kMaxSkinFraction}) {
            checkCandidateRows<2>(div, rng, skin);
            checkCandidateRows<3>(div, rng, skin);
        }
}

TEST(CellSearch, APositionOutsideTheSkinOfItsCellAsksForASort) {
    CellGrid g;
    ASSERT_TRUE(makeCellGrid(0, 0, 0, 1, 1, 1, 0.05, 2, g, 0.1));  // cells of 0.05 m, skin 5 mm
    std::uint32_t cell;
    const Float4 pc = makePosCell(g, Double3{0.52, 0.51, 0.53}, cell);
    bool outside = true;
    posCellInCell(g, Double3{0.5 - 0.004, 0.51, 0.53}, pc.w, outside);
    EXPECT_FALSE(outside);
    posCellInCell(g, Double3{0.5 - 0.006, 0.51, 0.53}, pc.w, outside);
    EXPECT_TRUE(outside);
    posCellInCell(g, Double3{0.52, 0.55 + 0.006, 0.53}, pc.w, outside);
    EXPECT_TRUE(outside);
    posCellInCell(g, Double3{0.52, 0.51, std::nan("")}, pc.w, outside);
    EXPECT_TRUE(outside);
}

// The cells' switch rule (solver/cell_switch.h): a particle shares its cell when its block's cell
// range holds two or more; counted on a sorted block of a lattice centred in its cells (none
// shares), then with one particle moved into its neighbour's cell (both share, wherever in it).
TEST(CellSearch, SharesItsCellCountsTheParticlesOfCellsHoldingTwoOrMore) {
    CellGrid g;
    ASSERT_TRUE(makeCellGrid(0, 0, 0, 0.1, 0.1, 0.1, 0.015, kCellDivSpacing, g, 0.0, 0.01));
    auto block = [&](std::vector<Double3> pos) {
        std::vector<Float4> pc(pos.size());
        std::vector<std::uint64_t> keys(pos.size());
        for (std::size_t i = 0; i < pos.size(); ++i) {
            std::uint32_t cell;
            pc[i] = makePosCell(g, pos[i], cell);
            keys[i] = sortKey(cell, std::uint32_t(i), false);
        }
        std::vector<std::size_t> order(pos.size());
        std::iota(order.begin(), order.end(), 0u);
        std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return keys[a] < keys[b]; });
        std::vector<Float4> sorted;
        std::vector<std::uint64_t> skeys;
        for (std::size_t k : order) sorted.push_back(pc[k]), skeys.push_back(keys[k]);
        std::vector<std::uint32_t> cs(g.cellCount() + 1);
        for (std::uint32_t c = 0; c <= g.cellCount(); ++c) cellStartOuterAt(c, 0, std::uint32_t(sorted.size()), skeys.data(), cs.data());
        for (std::uint32_t k = 0; k < sorted.size(); ++k) cellStartFillAt(k, 0, skeys.data(), cs.data());
        int shared = 0;
        for (const Float4& p : sorted) shared += sharesItsCell(p, cs.data(), g) ? 1 : 0;
        return std::make_pair(shared, sorted.size());
    };
    std::vector<Double3> lattice;
    for (int z = 0; z < 4; ++z)
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x) lattice.push_back(Double3{0.005 + 0.01 * x, 0.005 + 0.01 * y, 0.005 + 0.01 * z});
    EXPECT_EQ(block(lattice).first, 0);
    std::vector<Double3> moved = lattice;
    moved[5].x += 0.01;  // into particle 6's cell
    EXPECT_EQ(block(moved).first, 2);
    moved[5].x += 0.003;
    EXPECT_EQ(block(moved).first, 2);
}
