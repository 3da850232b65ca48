// SeaSpring — MIT licence.
/// \file test_grid_origin.cpp
/// \brief latticeCentredGridOrigin (solver/grid_origin.h): a fluid lattice whose planes lie on
///        the faces of cells a whole number of spacings wide is moved half a spacing off them
///        (every cell then holds the same number of particles, away from its faces); other
///        cells, a disordered fluid, 2D's y axis and the boundary particles' lattice leave the
///        domain's minimum as it is. The origin is never above the domain's minimum nor a cell
///        below it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>

#include "physics/cell_grid.h"
#include "solver/grid_origin.h"

using namespace seaspring;
using solver::GridOrigin;
using solver::latticeCentredGridOrigin;

namespace {

constexpr double kDp = 0.01;

/// `nb` boundary particles at (0.1 - dp/2, ...) + lattice, then an n^dim fluid lattice from
/// (0.1, 0.1, 0.1) with spacing dp (jitter: uniform in +-jitter dp); the domain from the lowest
/// fluid particle (DualSPHysics' default) to 0.1 + n dp.
solver::SolverCase latticeCase(int dim, int n, double jitter = 0.0, int nb = 0) {
    solver::SolverCase c;
    c.constants.dimensions = dim;
    c.constants.dp = kDp;
    c.domain_min = Vec3d{0.1, 0.1, 0.1};
    c.domain_max = Vec3d{0.1 + n * kDp, 0.1 + n * kDp, 0.1 + n * kDp};
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-jitter * kDp, jitter * kDp);
    for (int i = 0; i < nb; ++i)
        c.particles.pos.push_back(Vec3d{0.1 - 0.5 * kDp + i * kDp, 0.1 - 0.5 * kDp, 0.1 - 0.5 * kDp});
    c.nfixed = std::uint32_t(nb);
    const int ny = dim == 3 ? n : 1;
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < ny; ++y)
            for (int x = 0; x < n; ++x)
                c.particles.pos.push_back(Vec3d{0.1 + x * kDp + u(rng), dim == 3 ? 0.1 + y * kDp + u(rng) : 0.1,
                                                0.1 + z * kDp + u(rng)});
    c.nfluid = std::uint32_t(c.particles.pos.size()) - c.nfixed;
    return c;
}

physics::CellGrid gridFrom(const solver::SolverCase& c, const GridOrigin& o, double cellsize) {
    physics::CellGrid g;
    // makeCellGrid takes h and the cells per 2h: cellsize = 2h / 2.
    EXPECT_TRUE(physics::makeCellGrid(o.min[0], o.min[1], o.min[2], c.domain_max.x, c.domain_max.y, c.domain_max.z,
                                      cellsize, 2, g));
    return g;
}

/// Particles per occupied cell -> number of such cells.
std::map<int, int> occupancy(const solver::SolverCase& c, const physics::CellGrid& g) {
    std::map<std::uint32_t, int> per_cell;
    for (std::size_t i = c.nfixed; i < c.particles.pos.size(); ++i) {
        const Vec3d& p = c.particles.pos[i];
        std::uint32_t cell;
        physics::makePosCell(g, physics::Double3{p.x, p.y, p.z}, cell);
        ++per_cell[cell];
    }
    std::map<int, int> hist;
    for (const auto& kv : per_cell) ++hist[kv.second];
    return hist;
}

void expectWithinOneCellBelow(const solver::SolverCase& c, const GridOrigin& o, double cellsize) {
    const double lo[3] = {c.domain_min.x, c.domain_min.y, c.domain_min.z};
    for (int a = 0; a < 3; ++a) {
        EXPECT_LE(o.min[a], lo[a]) << "axis " << a;
        EXPECT_GT(o.min[a], lo[a] - cellsize) << "axis " << a;
    }
}

}  // namespace

TEST(GridOrigin, MovesALatticeOnTheCellFacesHalfASpacingOffThem) {
    const solver::SolverCase c = latticeCase(3, 12);
    const GridOrigin o = latticeCentredGridOrigin(c, kDp);  // cells of h/2 with h = 2 dp
    EXPECT_TRUE(o.centred[0] && o.centred[1] && o.centred[2]);
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(o.min[a], 0.1 - 0.5 * kDp, 1e-12) << "axis " << a;
    expectWithinOneCellBelow(c, o, kDp);
    // Every particle in a cell of its own, half a cell from its faces.
    const physics::CellGrid g = gridFrom(c, o, kDp);
    EXPECT_EQ(occupancy(c, g), (std::map<int, int>{{1, 12 * 12 * 12}}));
    for (std::size_t i = 0; i < c.particles.pos.size(); ++i) {
        const Vec3d& p = c.particles.pos[i];
        std::uint32_t cell;
        const physics::Float4 pc = physics::makePosCell(g, physics::Double3{p.x, p.y, p.z}, cell);
        ASSERT_NEAR(pc.x, 0.5 * kDp, 1e-6 * kDp) << i;
        ASSERT_NEAR(pc.y, 0.5 * kDp, 1e-6 * kDp) << i;
        ASSERT_NEAR(pc.z, 0.5 * kDp, 1e-6 * kDp) << i;
    }
    // From the domain's minimum the same lattice lies on the faces: cells of 0, 1, 2, 4, 8.
    GridOrigin plain;
    plain.min[0] = plain.min[1] = plain.min[2] = 0.1;
    const std::map<int, int> lumpy = occupancy(c, gridFrom(c, plain, kDp));
    EXPECT_NE(lumpy, (std::map<int, int>{{1, 12 * 12 * 12}}));
}

TEST(GridOrigin, CellsOfTwoSpacingsHoldTwoPlanesEachAwayFromTheFaces) {
    const solver::SolverCase c = latticeCase(3, 8);
    const GridOrigin o = latticeCentredGridOrigin(c, 2.0 * kDp);
    EXPECT_TRUE(o.any());
    expectWithinOneCellBelow(c, o, 2.0 * kDp);
    // Each axis: the planes at dp/2 and 3 dp/2 from the cell's lower face (a cell at the lattice's
    // edge may hold one of them only).
    const physics::CellGrid g = gridFrom(c, o, 2.0 * kDp);
    auto offPlane = [](float off) { return std::min(std::abs(off - 0.5 * kDp), std::abs(off - 1.5 * kDp)); };
    for (std::size_t i = 0; i < c.particles.pos.size(); ++i) {
        const Vec3d& p = c.particles.pos[i];
        std::uint32_t cell;
        const physics::Float4 pc = physics::makePosCell(g, physics::Double3{p.x, p.y, p.z}, cell);
        ASSERT_LT(offPlane(pc.x), 1e-6 * kDp) << i;
        ASSERT_LT(offPlane(pc.y), 1e-6 * kDp) << i;
        ASSERT_LT(offPlane(pc.z), 1e-6 * kDp) << i;
    }
    EXPECT_EQ(occupancy(c, g).rbegin()->first, 8);  // interior cells: 2 x 2 x 2
}

TEST(GridOrigin, CellsThatAreNotAWholeNumberOfSpacingsKeepTheDomainMinimum) {
    const solver::SolverCase c = latticeCase(3, 8);
    for (double cs : {2.0 * 1.7320508 * kDp / 3.0, 1.5 * kDp, 0.5 * kDp}) {
        const GridOrigin o = latticeCentredGridOrigin(c, cs);
        EXPECT_FALSE(o.any()) << cs;
        EXPECT_EQ(o.min[0], 0.1);
        EXPECT_EQ(o.min[1], 0.1);
        EXPECT_EQ(o.min[2], 0.1);
    }
}

TEST(GridOrigin, CellsWithinADriftOfATenthOfASpacingCountAsWhole) {
    // coefh 0.866025 for h = 1.5 dp (the sluice gate's): cells of 2h/3 = 0.9999997 dp. Over the
    // 12 spacings of this domain the planes drift by 4e-6 spacings: centred. Cells of 1.005 dp
    // drift by 0.065 (centred), of 1.01 dp by 0.13 (not).
    const solver::SolverCase c = latticeCase(3, 12);
    const double cs6 = 2.0 * (0.866025 * std::sqrt(3.0) * kDp) / 3.0;
    EXPECT_TRUE(latticeCentredGridOrigin(c, cs6).any());
    EXPECT_TRUE(latticeCentredGridOrigin(c, 1.005 * kDp).any());
    EXPECT_FALSE(latticeCentredGridOrigin(c, 1.01 * kDp).any());
    // The same 0.9999997 dp cells over a domain of 10^6 spacings drift by 0.25: not centred.
    solver::SolverCase wide = c;
    wide.domain_max.x = wide.domain_min.x + 1e6 * kDp;
    const solver::GridOrigin o = latticeCentredGridOrigin(wide, cs6);
    EXPECT_FALSE(o.centred[0]);
    EXPECT_TRUE(o.centred[1] && o.centred[2]);
}

TEST(GridOrigin, ADisorderedFluidKeepsTheDomainMinimum) {
    const GridOrigin o = latticeCentredGridOrigin(latticeCase(3, 8, 0.2), kDp);
    EXPECT_FALSE(o.any());
    // Jitter well inside the tolerance (1e-3 dp) is still a lattice.
    EXPECT_TRUE(latticeCentredGridOrigin(latticeCase(3, 8, 1e-5), kDp).any());
}

TEST(GridOrigin, TwoDimensionsLeaveYAloneAndBoundaryParticlesDoNotCount) {
    // The boundary particles lie half a spacing off the fluid's lattice: the fluid decides.
    const solver::SolverCase c = latticeCase(2, 10, 0.0, 20);
    const GridOrigin o = latticeCentredGridOrigin(c, kDp);
    EXPECT_TRUE(o.centred[0]);
    EXPECT_FALSE(o.centred[1]);
    EXPECT_TRUE(o.centred[2]);
    EXPECT_EQ(o.min[1], c.domain_min.y);
    EXPECT_NEAR(o.min[0], 0.1 - 0.5 * kDp, 1e-12);
    EXPECT_NEAR(o.min[2], 0.1 - 0.5 * kDp, 1e-12);
    // No fluid: nothing to centre.
    solver::SolverCase dry = c;
    dry.particles.pos.resize(dry.nfixed);
    dry.nfluid = 0;
    EXPECT_FALSE(latticeCentredGridOrigin(dry, kDp).any());
}
