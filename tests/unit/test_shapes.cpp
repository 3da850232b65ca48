// SeaSpring — MIT licence.
/// \file test_shapes.cpp
/// \brief Lattice indexing and shape rasterisation: exact point counts computed by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "gencase/lattice_grid.h"
#include "gencase/shapes.h"

using namespace seaspring;
using namespace seaspring::gencase;

namespace {

std::size_t countMk(const LatticeGrid& g, std::uint16_t mk) {
    std::size_t n = 0;
    for (std::uint16_t c : g.cells()) n += c == mk;
    return n;
}

LatticeGrid grid3d(double dp = 0.1) { return LatticeGrid({0, 0, 0}, dp, {-1, -1, -1}, {2, 2, 2}); }

}  // namespace

TEST(LatticeGrid, IndexRangeFromPointMinMax) {
    // pointmin -0.05 with dp 0.0085: first site index ceil(-5.88) = -5; pointmax 2: floor(235.3) = 235.
    LatticeGrid g({0, 0, 0}, 0.0085, {-0.05, -0.05, -0.05}, {2, 1, 1});
    EXPECT_EQ(g.lo().x, -5);
    EXPECT_EQ(g.hi().x, 235);
    EXPECT_EQ(g.nx(), 241u);
    EXPECT_EQ(g.ny(), 123u);  // -5..117 (1/0.0085 = 117.6)
    EXPECT_FALSE(g.twoD());
}

TEST(LatticeGrid, TwoDimensionalWhenYExtentIsZero) {
    LatticeGrid g({0, 0, 0}, 0.01, {-1, 0.25, -1}, {4.5, 0.25, 3.5});
    EXPECT_TRUE(g.twoD());
    EXPECT_EQ(g.ny(), 1u);
    EXPECT_DOUBLE_EQ(g.position(0, 0, 0).y, 0.25);  // the plane sits at pointmin.y
}

TEST(LatticeGrid, RoundIndexIsNearestWithTiesUp) {
    LatticeGrid g = grid3d(0.1);
    EXPECT_EQ(g.roundIndex(0.67, 0), 7);
    EXPECT_EQ(g.roundIndex(0.64, 0), 6);
    EXPECT_EQ(g.roundIndex(0.05, 0), 1);     // tie goes up
    EXPECT_EQ(g.roundIndex(-0.05, 0), 0);    // tie goes up
    EXPECT_EQ(g.roundIndex(0.3, 2), 3);      // 0.3/0.1 = 2.9999999999999996 still lands on 3
}

TEST(LatticeGrid, RejectsEmptyAndHugeLattices) {
    EXPECT_THROW(LatticeGrid({0, 0, 0}, 0.1, {0.01, 0, 0}, {0.02, 1, 1}), Error);
    EXPECT_THROW(LatticeGrid({0, 0, 0}, 1e-5, {0, 0, 0}, {10, 10, 10}), Error);
}

TEST(DrawBox, SolidAndFaceCounts) {
    LatticeGrid g = grid3d();
    // [0,1]^3 at dp 0.1: 11 sites per axis.
    EXPECT_EQ(drawBox(g, Affine{}, {0, 0, 0}, {1, 1, 1}, BoxSolid, 1), 1331u);
    LatticeGrid h = grid3d();
    EXPECT_EQ(drawBox(h, Affine{}, {0, 0, 0}, {1, 1, 1}, FacesAll, 2), 1331u - 729u);  // 11^3 - 9^3
    LatticeGrid k = grid3d();
    EXPECT_EQ(drawBox(k, Affine{}, {0, 0, 0}, {1, 1, 1}, FaceBottom, 3), 121u);
    // An open-top tank: bottom 121 + two x-walls 2*11*10 + two y-walls 2*9*10.
    LatticeGrid t = grid3d();
    EXPECT_EQ(drawBox(t, Affine{}, {0, 0, 0}, {1, 1, 1},
                      FaceBottom | FaceLeft | FaceRight | FaceFront | FaceBack, 4),
              121u + 220u + 180u);
}

TEST(DrawBox, BoundsRoundToNearestPlane) {
    // 0.67 with dp 0.1 rounds to plane 7, 0.64 to 6: x planes 0..7 (8), y 0..6 (7), z 0..0 (1).
    LatticeGrid g = grid3d();
    EXPECT_EQ(drawBox(g, Affine{}, {0, 0, 0}, {0.67, 0.64, 0.0}, BoxSolid, 1), 56u);
    // Negative size is the same box seen from the other corner.
    LatticeGrid h = grid3d();
    EXPECT_EQ(drawBox(h, Affine{}, {0.67, 0.64, 0}, {-0.67, -0.64, 0.0}, BoxSolid, 1), 56u);
}

TEST(DrawBox, LaterDrawingReplacesEarlier) {
    LatticeGrid g = grid3d();
    drawBox(g, Affine{}, {0, 0, 0}, {1, 1, 1}, BoxSolid, 1);
    drawBox(g, Affine{}, {0, 0, 0}, {1, 1, 1}, FaceTop, 2);
    drawBox(g, Affine{}, {0.4, 0.4, 0.4}, {0.2, 0.2, 0.2}, BoxSolid, 0);  // carve 3^3
    EXPECT_EQ(countMk(g, 2), 121u);
    EXPECT_EQ(countMk(g, 1), 1331u - 121u - 27u);
}

TEST(DrawBox, TranslationAndQuarterTurnKeepCounts) {
    LatticeGrid g = grid3d();
    const Affine m = Affine::translation({0.3, 0, 0}).then(Affine::rotation(90, {0, 0, 1}));
    // Box 0..0.4 x 0..0.2 x 0..0.1 turned 90 degrees about z: 5*3*2 sites, now spanning y.
    EXPECT_EQ(drawBox(g, m, {0, 0, 0}, {0.4, 0.2, 0.1}, BoxSolid, 1), 30u);
    // (0.4,0,0) maps to (0.3, 0.4, 0); (0, 0.2, 0) maps to (0.1, 0, 0).
    EXPECT_EQ(g.get(3, 4, 0), 1);
    EXPECT_EQ(g.get(1, 0, 0), 1);
    EXPECT_EQ(g.get(4, 0, 0), 0);
}

TEST(Affine, RotationAndInverse) {
    const Affine r = Affine::rotation(90, {0, 0, 1});
    const Vec3d p = r.apply({1, 0, 0});
    EXPECT_NEAR(p.x, 0, 1e-15);
    EXPECT_NEAR(p.y, 1, 1e-15);
    const Affine m = Affine::translation({1, 2, 3}).then(Affine::rotation(30, {1, 1, 0}));
    const Vec3d q = m.inverse().apply(m.apply({0.3, -0.2, 0.7}));
    EXPECT_NEAR(q.x, 0.3, 1e-14);
    EXPECT_NEAR(q.y, -0.2, 1e-14);
    EXPECT_NEAR(q.z, 0.7, 1e-14);
}

TEST(DrawSphere, HalfSpacingRule) {
    // R = dp: full takes r < 1.5 dp: centre + 6 at dp + 12 at sqrt(2) dp = 19.
    LatticeGrid g = grid3d();
    EXPECT_EQ(drawSphere(g, Affine{}, {0.5, 0.5, 0.5}, 0.1, DrawMode::Full, 1), 19u);
    LatticeGrid f = grid3d();
    EXPECT_EQ(drawSphere(f, Affine{}, {0.5, 0.5, 0.5}, 0.1, DrawMode::Face, 1), 18u);
    LatticeGrid s = grid3d();
    EXPECT_EQ(drawSphere(s, Affine{}, {0.5, 0.5, 0.5}, 0.1, DrawMode::Solid, 1), 1u);
}

TEST(DrawCylinder, HalfSpacingRule) {
    // Axis z from 0 to 0.2, R = dp: planes z = 0, 0.1, 0.2, each with 9 sites (rho < 1.5 dp).
    LatticeGrid g = grid3d();
    EXPECT_EQ(drawCylinder(g, Affine{}, {0.5, 0.5, 0}, {0.5, 0.5, 0.2}, 0.1, DrawMode::Full, 1), 27u);
    LatticeGrid s = grid3d();
    EXPECT_EQ(drawCylinder(s, Affine{}, {0.5, 0.5, 0}, {0.5, 0.5, 0.2}, 0.1, DrawMode::Solid, 1), 1u);
    LatticeGrid f = grid3d();
    EXPECT_EQ(drawCylinder(f, Affine{}, {0.5, 0.5, 0}, {0.5, 0.5, 0.2}, 0.1, DrawMode::Face, 1), 26u);
}

TEST(FillBox, FillsTheInsideOfAClosedTankWithoutItsBorder) {
    LatticeGrid g = grid3d();
    drawBox(g, Affine{}, {0, 0, 0}, {1, 1, 1}, FacesAll, 10);
    // Fill box = the tank: interior 9^3 sites; the border planes are the walls anyway.
    EXPECT_EQ(fillBox(g, Affine{}, {0.5, 0.5, 0.5}, {0, 0, 0}, {1, 1, 1}, FillVoid, 1, 9), 729u);
    // A fill box whose top plane is z = 0.5 stops below it (GenCase rule): z 1..4.
    LatticeGrid h = grid3d();
    drawBox(h, Affine{}, {0, 0, 0}, {1, 1, 1}, FacesAll, 10);
    EXPECT_EQ(fillBox(h, Affine{}, {0.5, 0.5, 0.2}, {0, 0, 0}, {1, 1, 0.5}, FillVoid, 1, 9), 9u * 9u * 4u);
    // With "border" the plane z = 0.5 is filled too.
    LatticeGrid b = grid3d();
    drawBox(b, Affine{}, {0, 0, 0}, {1, 1, 1}, FacesAll, 10);
    EXPECT_EQ(fillBox(b, Affine{}, {0.5, 0.5, 0.2}, {0, 0, 0}, {1, 1, 0.5}, FillVoid | FillBorder, 1, 9),
              9u * 9u * 5u);
}

TEST(FillBox, StopsAtWallsAndRespectsTheMask) {
    LatticeGrid g = grid3d();
    drawBox(g, Affine{}, {0, 0, 0}, {1, 1, 1}, FacesAll, 10);
    drawBox(g, Affine{}, {0.5, 0, 0}, {0, 1, 1}, BoxSolid, 10);  // wall at x = 0.5
    EXPECT_EQ(fillBox(g, Affine{}, {0.2, 0.5, 0.5}, {-1, -1, -1}, {3, 3, 3}, FillVoid, 1, 9), 4u * 9u * 9u);
    // Seed on a boundary site with a void-only mask fills nothing.
    EXPECT_EQ(fillBox(g, Affine{}, {0.5, 0.5, 0.5}, {-1, -1, -1}, {3, 3, 3}, FillVoid, 2, 9), 0u);
    // Mask "fluid" re-tags the fluid region just filled (MK 1 -> 2).
    EXPECT_EQ(fillBox(g, Affine{}, {0.2, 0.5, 0.5}, {-1, -1, -1}, {3, 3, 3}, FillFluid, 2, 9), 324u);
    EXPECT_EQ(countMk(g, 1), 0u);
}

TEST(FillBox, TwoDimensionalIsFourConnected) {
    LatticeGrid g({0, 0, 0}, 0.1, {-1, 0, -1}, {2, 0, 2});
    drawBox(g, Affine{}, {0, -1, 0}, {1, 2, 1}, FaceLeft | FaceRight | FaceBottom | FaceTop, 10);
    EXPECT_EQ(countMk(g, 10), 40u);  // a square ring of 11 per side
    EXPECT_EQ(fillBox(g, Affine{}, {0.5, 0, 0.5}, {0, -1, 0}, {1, 2, 1}, FillVoid, 1, 9), 81u);
}
