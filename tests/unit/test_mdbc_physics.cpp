// SeaSpring — MIT licence.
/// \file test_mdbc_physics.cpp
/// \brief The mDBC correction (physics/mdbc.h) on a fluid lattice filling the half space above
///        a wall, with the sums formed by the solver's own neighbour walk:
///  - SlipMode 1: a linear density field is reproduced exactly (to float rounding) at the
///    boundary particle, whatever its gradient: the first-order interpolation at the ghost node
///    and the extrapolation back along the normal;
///  - SlipMode 2/3: the hydrostatic field of a still tank gives the boundary particle the
///    hydrostatic density at its own depth (the pressure cloning adds rho0 g |n|); the velocity
///    is the fluid's mirrored (no-slip) or copied (free-slip);
///  - a ghost node without fluid: rho0 and the wall velocity;
///  - the matrix inverse against a hand-checked matrix.
/// Broken on purpose while writing: the sign of the extrapolation jump (SlipMode 1 then misses
/// by 2 G.n: LinearDensity fails), the sign of the cloning's normal distance (Hydrostatic fails
/// by 2 rho0 g |n| / c0^2), the factor 2 of the no-slip mirror (NoSlip fails), free-slip copying
/// the whole ghost velocity (FreeSlip fails).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numeric>
#include <vector>

#include "physics/fluid_constants.h"
#include "physics/mdbc.h"

using namespace seaspring::physics;

namespace {

/// Fluid particles on the lattice above z = 0 (rows at (k + 1/2) dp, k = 0..rows-1), sorted by
/// cell then index, with the cell ranges of the grid.
struct FluidLattice {
    CellGrid g;
    FluidConstants c;
    std::vector<Float4> poscell, velrho;
    std::vector<std::uint32_t> cell_start;
    double dp = 0.01;

    FluidLattice(int dim, const std::function<Float4(const Double3&)>& field) {
        const double h = 2.0 * dp, width = 0.2;
        FluidInputs fi;
        fi.h = h;
        fi.dp = dp;
        fi.dim = dim;
        fi.cs0 = 20.0;
        fi.b = 20.0 * 20.0 * 1000.0 / 7.0;
        fi.rhop0 = 1000.0;
        fi.massfluid = 1000.0 * (dim == 3 ? dp * dp * dp : dp * dp);
        fi.massbound = fi.massfluid;
        fi.gravity_z = -9.81;
        c = makeFluidConstants(fi);
        EXPECT_TRUE(makeCellGrid(-width / 2, dim == 3 ? -width / 2 : 0.0, -0.05, width / 2, dim == 3 ? width / 2 : 0.0,
                                 0.15, h, 2, g));
        struct P {
            std::uint32_t cell;
            std::uint32_t k;
            Float4 pc, vr;
        };
        std::vector<P> parts;
        const int nx = int(width / dp);
        for (int iz = 0; iz < 12; ++iz)
            for (int iy = 0; iy < (dim == 3 ? nx : 1); ++iy)
                for (int ix = 0; ix < nx; ++ix) {
                    const Double3 x{-width / 2 + (ix + 0.5) * dp, dim == 3 ? -width / 2 + (iy + 0.5) * dp : 0.0,
                                    (iz + 0.5) * dp};
                    std::uint32_t lin;
                    const Float4 pc = makePosCell(g, x, lin);
                    parts.push_back({lin, std::uint32_t(parts.size()), pc, field(x)});
                }
        std::stable_sort(parts.begin(), parts.end(), [](const P& a, const P& b) { return a.cell < b.cell; });
        cell_start.assign(g.cellCount() + 1, 0);
        for (const P& p : parts) {
            poscell.push_back(p.pc);
            velrho.push_back(p.vr);
        }
        std::uint32_t k = 0;
        for (std::uint32_t cell = 0; cell <= g.cellCount(); ++cell) {
            while (k < parts.size() && parts[k].cell < cell) ++k;
            cell_start[cell] = k;
        }
    }

    /// The corrected boundary particle at x_b with ghost vector n.
    template <int kDim>
    MdbcResult correct(const Double3& xb, const Double3& n, SlipMode slip, float wall_vx = 0.f) const {
        std::uint32_t lin;
        const Float4 gpc = makePosCell(g, Double3{xb.x + n.x, xb.y + n.y, xb.z + n.z}, lin);
        const MdbcSums s = mdbcGhostSums<WendlandKernel, kDim>(gpc, cell_start.data(), poscell.data(), velrho.data(), c, g);
        MdbcConstants m;
        m.dp2 = float(dp * dp);
        m.cs02 = c.cs0 * c.cs0;
        m.gz = -9.81f;
        return mdbcCorrect<kDim>(s, slip, float(n.x), float(n.y), float(n.z), wall_vx, 0.f, 0.f, 0.f, 0.f, 0.f, c, m);
    }
};

}  // namespace

TEST(MdbcPhysics, InverseOfAKnownMatrix) {
    // A = [[2,1,0],[1,3,1],[0,1,4]]: det = 2*(12-1) - 1*(4-0) = 18.
    const float a[4][4] = {{2, 1, 0, 0}, {1, 3, 1, 0}, {0, 1, 4, 0}, {0, 0, 0, 0}};
    double inv[4][4], det;
    ASSERT_TRUE(mdbcInvert<3>(a, inv, det));
    EXPECT_NEAR(det, 18.0, 1e-12);
    for (int r = 0; r < 3; ++r)
        for (int q = 0; q < 3; ++q) {
            double s = 0;
            for (int k = 0; k < 3; ++k) s += double(a[r][k]) * inv[k][q];
            EXPECT_NEAR(s, r == q ? 1.0 : 0.0, 1e-12) << r << "," << q;
        }
    const float sing[4][4] = {{1, 2, 0, 0}, {2, 4, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}};
    EXPECT_FALSE(mdbcInvert<2>(sing, inv, det));
    EXPECT_EQ(det, 0.0);
}

/// Tolerance: 2e-5 rho0 (float sums of ~100 terms of size rho0, a first-order method is exact on
/// linear fields; measured 1e-6-4e-6 rho0).
TEST(MdbcPhysics, SlipMode1ReproducesALinearDensityField) {
    const double gx = 300.0, gy = -150.0, gz = 800.0;  // kg/m^3 per m: up to 8 kg/m^3 over the kernel
    for (int dim : {2, 3}) {
        auto rho = [&](const Double3& x) { return 1000.0 + gx * x.x + (dim == 3 ? gy * x.y : 0.0) + gz * (x.z - 0.05); };
        FluidLattice f(dim, [&](const Double3& x) { return Float4{0, 0, 0, float(rho(x))}; });
        // Boundary particles of the first two layers under the interface, normal along +z; one at
        // an oblique normal (a particle near a corner whose ghost lies up and to the side).
        const std::vector<std::pair<Double3, Double3>> cases = {
            {{0.003, 0.0, -0.005}, {0.0, 0.0, 0.01}},
            {{-0.012, 0.0, -0.015}, {0.0, 0.0, 0.03}},
            {{0.02, 0.0, -0.005}, {0.006, 0.0, 0.008}},
        };
        for (const auto& [xb, n] : cases) {
            const MdbcResult r = dim == 2 ? f.correct<2>(xb, n, SlipMode::Vel0) : f.correct<3>(xb, n, SlipMode::Vel0);
            EXPECT_FALSE(r.set_velocity);
            EXPECT_NEAR(r.rho, rho(xb), 2e-5 * 1000.0) << dim << "D, boundary particle at z = " << xb.z;
        }
    }
}

/// Still water: rho = rho0 + rho0 g (H - z) / c0^2 (the linear equation of state the cloning
/// uses), H = 0.12 m. The boundary particle takes the hydrostatic density at its own depth: the
/// interpolated ghost value plus the jump rho0 g |n| / c0^2. Tolerance 2e-5 rho0 (the first-order
/// ghost value is exact on a linear field; the bulk lattice is full, A11 = 1 within 1e-3).
TEST(MdbcPhysics, SlipModes2And3CloneTheHydrostaticPressure) {
    const double g = 9.81, H = 0.12, c02 = 400.0;
    for (int dim : {2, 3}) {
        auto rho = [&](double z) { return 1000.0 + 1000.0 * g * (H - z) / c02; };
        FluidLattice f(dim, [&](const Double3& x) { return Float4{0.1f, 0.f, 0.f, float(rho(x.z))}; });
        for (SlipMode slip : {SlipMode::NoSlip, SlipMode::FreeSlip}) {
            for (int layer : {1, 2, 3}) {
                const Double3 xb{0.004, 0.0, -(layer - 0.5) * f.dp};
                const Double3 n{0.0, 0.0, (2 * layer - 1) * f.dp};
                const MdbcResult r = dim == 2 ? f.correct<2>(xb, n, slip) : f.correct<3>(xb, n, slip);
                EXPECT_TRUE(r.set_velocity);
                EXPECT_NEAR(r.rho, rho(xb.z), 2e-5 * 1000.0) << dim << "D layer " << layer;
                // The fluid moves at 0.1 m/s along x: the viscous velocity mirrors it (no-slip) or
                // copies it (free-slip); velrho keeps the wall's (at rest).
                EXPECT_NEAR(r.tvx, slip == SlipMode::NoSlip ? -0.1f : 0.1f, 1e-4) << dim << "D layer " << layer;
                EXPECT_NEAR(r.tvz, 0.f, 1e-5);
                EXPECT_EQ(r.vx, 0.f);
                EXPECT_EQ(r.vz, 0.f);
            }
        }
    }
}

TEST(MdbcPhysics, NoSlipMirrorsAboutTheWallVelocity) {
    FluidLattice f(2, [](const Double3&) { return Float4{0.1f, 0.f, 0.f, 1000.f}; });
    const MdbcResult r = f.correct<2>({0.0, 0.0, -0.005}, {0.0, 0.0, 0.01}, SlipMode::NoSlip, 0.5f);
    EXPECT_NEAR(r.tvx, 2 * 0.5f - 0.1f, 1e-4);  // viscous velocity: 2 v_wall - v_ghost
    EXPECT_EQ(r.vx, 0.5f);                      // the continuity equation sees the wall
}

/// As DualSPHysics 5.4 (tangenvel): the viscous velocity is the tangential part of 2 v_wall -
/// v_g (no-slip) or of v_g (free-slip); its normal part is 0, and velrho keeps the wall's own
/// velocity, so a fluid particle approaching the wall sees its whole normal velocity in the
/// continuity equation (with no-slip and free-slip alike; this is what keeps the still tank's
/// water above the floor). Broken on purpose: the whole mirrored velocity in velrho (the
/// earlier scheme) fails the vx/vz checks here, and the 3D still tank with no-slip walls
/// drifted and diverged (docs/validation.md, "Still-water tanks").
TEST(MdbcPhysics, SlipModes2And3KeepTheWallVelocityAndAViscousTangentialOne) {
    FluidLattice f(3, [](const Double3&) { return Float4{0.1f, 0.02f, -0.05f, 1000.f}; });
    const MdbcResult fs = f.correct<3>({0.0, 0.0, -0.005}, {0.0, 0.0, 0.01}, SlipMode::FreeSlip);
    EXPECT_NEAR(fs.tvx, 0.1f, 1e-5);
    EXPECT_NEAR(fs.tvy, 0.02f, 1e-5);
    EXPECT_EQ(fs.tvz, 0.f);
    const MdbcResult ns = f.correct<3>({0.0, 0.0, -0.005}, {0.0, 0.0, 0.01}, SlipMode::NoSlip);
    EXPECT_NEAR(ns.tvx, -0.1f, 1e-5);
    EXPECT_NEAR(ns.tvy, -0.02f, 1e-5);
    EXPECT_EQ(ns.tvz, 0.f);
    for (const MdbcResult& r : {fs, ns}) {
        EXPECT_EQ(r.vx, 0.f);
        EXPECT_EQ(r.vy, 0.f);
        EXPECT_EQ(r.vz, 0.f);
    }
    // An oblique wall (normal (1, 0, 1)/sqrt2): the normal part of the viscous velocity is 0.
    const MdbcResult ob = f.correct<3>({0.0, 0.0, -0.005}, {0.00707, 0.0, 0.00707}, SlipMode::FreeSlip);
    EXPECT_NEAR(ob.tvx * 0.7071f + ob.tvz * 0.7071f, 0.f, 1e-6);
}

TEST(MdbcPhysics, AGhostNodeWithoutFluidGivesRho0AndTheWallVelocity) {
    FluidLattice f(2, [](const Double3&) { return Float4{0.1f, 0.f, 0.f, 1010.f}; });
    // Ghost node 0.2 m below the fluid: nothing in reach.
    for (SlipMode slip : {SlipMode::Vel0, SlipMode::NoSlip, SlipMode::FreeSlip}) {
        const MdbcResult r = f.correct<2>({0.0, 0.0, -0.04}, {0.0, 0.0, -0.01}, slip, 0.25f);
        EXPECT_EQ(r.rho, 1000.f);
        EXPECT_EQ(r.vx, 0.25f);
        EXPECT_EQ(r.tvx, 0.25f);  // tangential to the wall (normal along z)
    }
}

namespace {
/// Solid particle 0 of a 2D (x-z) or 3D lattice patch with its first and second neighbours as
/// bond partners 1..nb, slot-major with n = nb + 1 particles (only particle 0's row is used).
struct SolidPatch {
    std::vector<Double3> pos0, pos;
    std::vector<std::uint8_t> count, flags, broken;
    std::vector<std::uint32_t> partner;
    std::vector<double> rest;
    SolidBonds b;
    explicit SolidPatch(int dim, double dp = 0.01) {
        pos0.push_back({0, 0, 0});
        for (int i = -1; i <= 1; ++i)
            for (int j = (dim == 3 ? -1 : 0); j <= (dim == 3 ? 1 : 0); ++j)
                for (int k = -1; k <= 1; ++k)
                    if (i || j || k) pos0.push_back({i * dp, j * dp, k * dp});
        const std::uint32_t n = std::uint32_t(pos0.size()), nb = n - 1;
        count.assign(n, 0);
        count[0] = std::uint8_t(nb);
        partner.assign(nb * n, 0);
        flags.assign(nb * n, 0);
        broken.assign(nb * n, 0);
        rest.assign(nb * n, dp);
        for (std::uint32_t q = 0; q < nb; ++q) partner[q * n + 0] = q + 1;
        pos = pos0;
        b.n = n;
        b.count = count.data();
        b.partner = partner.data();
        b.rest = rest.data();
        b.flags = flags.data();
        b.broken = broken.data();
    }
    template <int kDim>
    Double3 ghost(const Double3& n0) { return solidGhostVector<kDim>(0, n0, pos.data(), pos0.data(), b); }
};
}  // namespace

/// A rigid rotation of the patch rotates the ghost vector with it (exactly, to rounding); a
/// stretch along x keeps a normal along x and tilts an oblique one as Nanson's formula says
/// (n ~ F^-T n0); the length is kept; with every bond broken the particle keeps n0.
/// Broken on purpose: F^-T replaced by F^-1 (B^-1 for B^-T: the rotation check fails, the
/// normal turns the other way).
TEST(MdbcPhysics, SolidGhostVectorsFollowTheLattice) {
    const double th = 0.3, c = std::cos(th), s = std::sin(th);
    {
        SolidPatch p(2);
        for (Double3& x : p.pos) x = Double3{c * x.x + s * x.z, 0.0, -s * x.x + c * x.z};
        const Double3 n = p.ghost<2>({0.0, 0.0, 0.02});
        EXPECT_NEAR(n.x, s * 0.02, 1e-12);
        EXPECT_NEAR(n.z, c * 0.02, 1e-12);
        EXPECT_EQ(n.y, 0.0);
    }
    {
        SolidPatch p(3);
        for (Double3& x : p.pos) x = Double3{c * x.x - s * x.y, s * x.x + c * x.y, x.z};  // about z
        const Double3 n = p.ghost<3>({0.01, 0.0, 0.01});
        EXPECT_NEAR(n.x, c * 0.01, 1e-12);
        EXPECT_NEAR(n.y, s * 0.01, 1e-12);
        EXPECT_NEAR(n.z, 0.01, 1e-12);
    }
    {
        SolidPatch p(2);
        const double e = 0.25;
        for (Double3& x : p.pos) x.x *= 1.0 + e;
        const Double3 nx = p.ghost<2>({0.02, 0.0, 0.0});
        EXPECT_NEAR(nx.x, 0.02, 1e-12);
        EXPECT_NEAR(nx.z, 0.0, 1e-12);
        // n0 = (1, 1): F^-T n0 = (1/(1+e), 1), scaled to |n0|.
        const Double3 nd = p.ghost<2>({0.01, 0.0, 0.01});
        const double len = std::sqrt(0.0002), mx = 1.0 / (1.0 + e), ml = std::sqrt(mx * mx + 1.0);
        EXPECT_NEAR(nd.x, len * mx / ml, 1e-12);
        EXPECT_NEAR(nd.z, len / ml, 1e-12);
    }
    {
        SolidPatch p(2);
        for (auto& br : p.broken) br = 1;
        for (Double3& x : p.pos) x = Double3{c * x.x + s * x.z, 0.0, -s * x.x + c * x.z};
        const Double3 n = p.ghost<2>({0.0, 0.0, 0.02});
        EXPECT_EQ(n.x, 0.0);
        EXPECT_EQ(n.z, 0.02);
    }
}
