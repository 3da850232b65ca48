// SeaSpring — MIT licence.
/// \file test_cell_search.cpp
/// \brief The boundary block's per-cell "near" flags (cellOccupiedAt + dilateCellsAt along x,
///        y, z) against a brute-force scan of each cell's search box, for every cell mode in
///        2D and 3D: a fluid particle may skip the boundary block only where it holds nothing.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "physics/cell_grid.h"
#include "physics/particle_updates.h"

using namespace seaspring::physics;

TEST(CellSearch, NearFlagsEqualABruteForceScanOfTheSearchBox) {
    std::mt19937 rng(7);
    for (int dim : {2, 3}) {
        for (int div : {1, 2, 3, 4}) {
            CellGrid g;
            ASSERT_TRUE(makeCellGrid(0, 0, 0, 1.0, dim == 3 ? 0.6 : 0.0, 0.5, 0.05, div, g));
            const std::uint32_t nc = g.cellCount();
            // Sparse occupancy (about one occupied cell per search box; occupied cells hold 1-3
            // particles), as a block's cell ranges: near and far cells both occur.
            std::uint32_t box = 1;
            for (int k = 0; k < dim; ++k) box *= std::uint32_t(2 * div + 1);
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
            std::vector<std::uint8_t> a(nc), t(nc);
            for (std::uint32_t c = 0; c < nc; ++c) cellOccupiedAt(c, cs.data(), a.data());
            for (std::uint32_t c = 0; c < nc; ++c) dilateCellsAt(c, 0, g, a.data(), t.data());
            for (std::uint32_t c = 0; c < nc; ++c) dilateCellsAt(c, 1, g, t.data(), a.data());
            for (std::uint32_t c = 0; c < nc; ++c) dilateCellsAt(c, 2, g, a.data(), t.data());
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
                        const std::uint8_t flag = t[g.linear(cx, cy, cz)];
                        wrong += flag != any ? 1 : 0;
                        (any ? near : far) += 1;
                    }
            EXPECT_EQ(wrong, 0) << dim << "D, cells of 2h/" << div;
            EXPECT_GT(near, 0) << dim << "D, cells of 2h/" << div;  // both kinds occur: the check can fail
            EXPECT_GT(far, 0) << dim << "D, cells of 2h/" << div;
        }
    }
}
