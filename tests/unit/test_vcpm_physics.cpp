// SeaSpring — MIT licence.
/// \file test_vcpm_physics.cpp
/// \brief VCPM lattice physics (physics/vcpm.h) on small lattice blocks (tests/unit/vcpm_block.h) built from
///        gencase's lattice offsets: patch tests (3D and 2D recover E, nu and mu of the input),
///        rigid motion, force = -dU/dx, breakage, the sub-step integrator, the sub-step count,
///        the material constants, and the output formulas (lattice energy as the coupling ledger
///        sums it, bond strain, particle mass, sub-step length).
///
/// Stress is the virial stress of the centre particle I of the block (all its bonds and its
/// neighbours' bonds complete):  sigma = -(1/(2V)) sum_J f_IJ u_IJ (x) r_IJ,  r_IJ = x_I - x_J,
/// u_IJ = r_IJ/|r_IJ|, f_IJ the signed force on I along u_IJ (Eq. 13, negative = attraction),
/// V = dp^3 (3D) or dp^2 (2D, per unit thickness). It equals (1/V) dW/d(eps) of the Cauchy-Born
/// energy per particle. The strain response is linearised by a central difference in the strain
/// amplitude, (sigma(+e eps) - sigma(-e eps)) / (2e), which removes the quadratic geometric term.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

#include "core/vec3.h"
#include "gencase/vcpm_bonds.h"
#include "physics/vcpm.h"
#include "physics/vcpm_substep.h"
#include "unit/vcpm_block.h"

using namespace seaspring::physics;
using seaspring::Vec3i;
using seaspring::gencase::firstNeighbourCount;
using seaspring::gencase::latticeOffsets;
using seaspring::test::affine;
using seaspring::test::Block;
using seaspring::test::comp;
using seaspring::test::energy;
using seaspring::test::forceEnergyMismatch;
using seaspring::test::forces;
using seaspring::test::Mat3;
using seaspring::test::norm;
using seaspring::test::perturb;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// Virial stress of particle c from the per-bond forces of vcpm.h (bondVector, halfElongation,
/// bondForce: the chain solidBondForceAt sums), with S from forces().
Mat3 virial(const Block& b, const std::vector<Double3>& x, std::uint32_t c) {
    Mat3 sig{};
    const double vol = b.two_d ? b.dp * b.dp : b.dp * b.dp * b.dp;
    for (int q = 0; q < b.count[c]; ++q) {
        const std::uint32_t k = b.slot(c, q), j = b.partner[k];
        if (b.broken[k]) continue;
        double r[3];
        const double len = bondVector(x[c], x[j], r[0], r[1], r[2]);
        const double kk = (b.flags[k] & kBondSecond) ? b.mat.k_second : b.mat.k_first;
        const double f = bondForce(kk, b.mat.t_half, halfElongation(len, b.rest[k]), b.sum[c], b.sum[j]);
        for (int i = 0; i < 3; ++i)
            for (int l = 0; l < 3; ++l) sig[i][l] -= 0.5 / vol * f * r[i] / len * r[l];
    }
    return sig;
}

/// Linearised stress per unit strain amplitude along eps; also checks that every deep particle
/// carries no net force (relative to k dp e) at +e and -e.
Mat3 linearStress(Block& b, const Mat3& eps, double e, double* worst_force) {
    Mat3 out{};
    for (int sign = -1; sign <= 1; sign += 2) {
        const std::vector<Double3> x = affine(b, eps, sign * e);
        const std::vector<Double3> f = forces(b, x);
        for (std::uint32_t s = 0; s < b.n; ++s)
            if (b.deep(s)) *worst_force = std::max(*worst_force, norm(f[s]) / (b.mat.k_first * b.dp * e));
        const Mat3 sg = virial(b, x, b.at(b.nx / 2, b.ny / 2, b.nz / 2));
        for (int i = 0; i < 3; ++i)
            for (int l = 0; l < 3; ++l) out[i][l] += sign * sg[i][l] / (2.0 * e);
    }
    return out;
}

// Patch tests: homogeneous strain on a 9^3 (3D) / 15^2 (2D) block.
class VcpmPatch : public ::testing::TestWithParam<std::tuple<bool, double>> {};

TEST_P(VcpmPatch, RecoversIsotropicElasticity) {
    const bool two_d = std::get<0>(GetParam());
    const double nu = std::get<1>(GetParam()), E = 2.0e6, dp = 0.01, e = 1e-5;
    const VcpmElastic el = vcpmElastic(E, nu, 1000.0);
    Block b(two_d, two_d ? 15 : 9, 9, two_d ? 15 : 9, dp, vcpmMaterial(two_d ? 2 : 3, E, nu, 1000.0, dp, 0, 0));
    const int lat = two_d ? 2 : 1;  // the lateral in-plane axis (z in 2D, y in 3D)
    double worst_force = 0.0;
    const double tol = 1e-6;

    // Uniaxial strain: sigma_xx = C11 e = (lambda + 2 mu) e, sigma_lat = C12 e = lambda e.
    const Mat3 ex{{{1, 0, 0}, {0, 0, 0}, {0, 0, 0}}};
    const Mat3 s1 = linearStress(b, ex, e, &worst_force);
    const double c11 = s1[0][0], c12 = s1[lat][lat];
    const double nu_rec = c12 / (c11 + c12), e_rec = (c11 - c12) * (c11 + 2 * c12) / (c11 + c12);
    EXPECT_NEAR(e_rec / E, 1.0, tol);
    EXPECT_NEAR(nu_rec, nu, tol);
    EXPECT_NEAR(c12, el.lame, tol * E);

    // Uniaxial stress: lateral eps -nu e (3D) or -nu/(1-nu) e (2D plane strain, sigma_zz = 0);
    // sigma_xx = E e (3D) or E/(1-nu^2) e (plane strain), lateral stresses zero.
    const Mat3 eu{{{1, 0, 0}, {0, two_d ? 0 : -nu, 0}, {0, 0, two_d ? -nu / (1 - nu) : -nu}}};
    const Mat3 s2 = linearStress(b, eu, e, &worst_force);
    const double e_axial = two_d ? E / (1 - nu * nu) : E;
    EXPECT_NEAR(s2[0][0] / e_axial, 1.0, tol);
    EXPECT_NEAR(s2[2][2], 0.0, tol * E);
    EXPECT_NEAR(s2[1][1], 0.0, tol * E);

    // Pure shear eps_xz = g/2: sigma_xz = mu g, nothing else.
    const Mat3 es{{{0, 0, 0.5}, {0, 0, 0}, {0.5, 0, 0}}};
    const Mat3 s3 = linearStress(b, es, e, &worst_force);
    EXPECT_NEAR(s3[0][2] / el.shear, 1.0, tol);
    EXPECT_NEAR(s3[0][0], 0.0, tol * E);
    EXPECT_NEAR(s3[2][2], 0.0, tol * E);

    // A random strain (in-plane in 2D): sigma = lambda tr(eps) I + 2 mu eps.
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Mat3 er{};  // (2D: the y row and column stay zero)
    for (int i = 0; i < 3; ++i)
        for (int l = i; l < 3; ++l)
            if (!two_d || (i != 1 && l != 1)) er[i][l] = er[l][i] = u(rng);
    const Mat3 s4 = linearStress(b, er, e, &worst_force);
    const double tr = er[0][0] + er[1][1] + er[2][2];
    for (int i = 0; i < 3; ++i)
        for (int l = 0; l < 3; ++l)
            if (!two_d || (i != 1 && l != 1)) {
                EXPECT_NEAR(s4[i][l], el.lame * tr * (i == l) + 2 * el.shear * er[i][l], tol * E) << i << l;
            }

    // Net force on deep particles ~ 0 (exact cancellation up to round-off).
    std::printf("[ patch ] %s nu=%+.2f  E_rec/E-1=%+.1e  nu_rec-nu=%+.1e  mu_rec/mu-1=%+.1e  max|F_deep|/(k dp e)=%.1e\n",
                two_d ? "2D" : "3D", nu, e_rec / E - 1, nu_rec - nu, s3[0][2] / el.shear - 1, worst_force);
    EXPECT_LT(worst_force, 1e-7);
}

INSTANTIATE_TEST_SUITE_P(NuRange, VcpmPatch,
                         ::testing::Combine(::testing::Bool(), ::testing::Values(-0.3, 0.0, 0.25, 0.3, 0.45)));

// Plane stress (constitmodel 2): the 2D lattice with planeStressEquivalent's constants is a sheet
// of the body's E and nu: under uniaxial in-plane stress sigma_xx = E e with the lateral strain
// -nu e (plane strain: E/(1-nu^2) and -nu/(1-nu)), the same shear modulus, and the P-wave speed
// sqrt(E/(rho (1-nu^2))). Broken on purpose: nu' = nu/(1-nu) (a plausible slip) fails here.
TEST(VcpmPhysics, PlaneStressBodyIsAPlaneStressSheet) {
    const double E = 2.0e6, dp = 0.01, e = 1e-5, rho = 1000.0, tol = 1e-6;
    for (double nu : {0.0, 0.25, 0.3, 0.45, 0.49}) {
        double young, poisson;
        planeStressEquivalent(E, nu, young, poisson);
        Block b(true, 15, 9, 15, dp, vcpmMaterial(2, young, poisson, rho, dp, 0, 0));
        double worst_force = 0.0;
        const Mat3 eu{{{1, 0, 0}, {0, 0, 0}, {0, 0, -nu}}};
        const Mat3 s = linearStress(b, eu, e, &worst_force);
        EXPECT_NEAR(s[0][0] / E, 1.0, tol) << "nu " << nu;
        EXPECT_NEAR(s[2][2], 0.0, tol * E) << "nu " << nu;
        const Mat3 es{{{0, 0, 0.5}, {0, 0, 0}, {0.5, 0, 0}}};
        const Mat3 sh = linearStress(b, es, e, &worst_force);
        EXPECT_NEAR(sh[0][2] / (E / (2 * (1 + nu))), 1.0, tol) << "nu " << nu;
        EXPECT_NEAR(vcpmElastic(young, poisson, rho).wave_speed / std::sqrt(E / (rho * (1 - nu * nu))), 1.0, 1e-12);
        EXPECT_LT(worst_force, 1e-7);
    }
}

/// Rotation by `angle` about the axis (ax, ay, az) (Rodrigues: R = c I + s [a]x + (1-c) a a^T).
Mat3 rotation(double ax, double ay, double az, double angle) {
    const double l = std::sqrt(ax * ax + ay * ay + az * az), c = std::cos(angle), s = std::sin(angle);
    const double a[3] = {ax / l, ay / l, az / l};
    const Mat3 cross{{{0, -a[2], a[1]}, {a[2], 0, -a[0]}, {-a[1], a[0], 0}}};
    Mat3 r{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r[i][j] = (i == j ? c : 0.0) + s * cross[i][j] + (1 - c) * a[i] * a[j];
    return r;
}

TEST(VcpmPhysics, RigidMotionGivesNoForce) {
    for (bool two_d : {false, true})
        for (double nu : {-0.3, 0.3, 0.45}) {
            const double dp = 0.02;
            Block b(two_d, 6, 6, 6, dp, vcpmMaterial(two_d ? 2 : 3, 5e6, nu, 1200.0, dp, 0, 0));
            const Mat3 r = two_d ? rotation(0, 1, 0, kPi / 6) : rotation(1, 2, 3, kPi / 6);
            const Double3 t{0.37 * dp, two_d ? 0.0 : -1.2 * dp, 2.5 * dp};
            std::vector<Double3> x = affine(b, r, 1.0, 0.0);
            for (Double3& p : x) p = Double3{p.x + t.x, p.y + t.y, p.z + t.z};
            const std::vector<Double3> f = forces(b, x);
            double worst = 0.0;
            for (std::uint32_t s = 0; s < b.n; ++s) worst = std::max(worst, norm(f[s]) / (b.mat.k_first * dp));
            std::printf("[ rigid ] %s nu=%+.2f  max |F|/(k dp)=%.2e\n", two_d ? "2D" : "3D", nu, worst);
            EXPECT_LT(worst, 1e-9);
        }
}

TEST(VcpmPhysics, ForceIsMinusEnergyGradient) {
    for (bool two_d : {false, true})
        for (double nu : {-0.3, 0.3, 0.45}) {
            const double dp = 0.01;
            Block b(two_d, two_d ? 5 : 4, 4, two_d ? 5 : 4, dp, vcpmMaterial(two_d ? 2 : 3, 1e6, nu, 1000.0, dp, 0, 0));
            // One bond pair pre-broken (both slots): it must drop out of U, S and F alike.
            const std::uint32_t k0 = b.slot(b.at(1, two_d ? 0 : 1, 1), 2);
            b.broken[k0] = b.broken[b.mirror[k0]] = 1;
            std::mt19937_64 rng(11);
            std::uniform_real_distribution<double> u(-1.0, 1.0);
            Mat3 eps{};
            for (int i = 0; i < 3; ++i)
                for (int l = 0; l < 3; ++l) eps[i][l] = (two_d && i == 1) ? 0.0 : 0.01 * u(rng);  // 2D: y stays 0
            std::vector<Double3> x = affine(b, eps, 1.0);
            perturb(x, 0.01 * dp, two_d, rng);
            const double rel = forceEnergyMismatch(b, x);
            std::printf("[ energy ] %s nu=%+.2f  max |F + dU/dx| / max|F| = %.2e\n", two_d ? "2D" : "3D", nu, rel);
            EXPECT_LT(rel, 1e-6);
        }
}

TEST(VcpmPhysics, BondBreaksCriterion) {
    EXPECT_TRUE(bondBreaks(1.0101, 1.0, 0.01));
    EXPECT_FALSE(bondBreaks(1.0099, 1.0, 0.01));
    EXPECT_FALSE(bondBreaks(0.5, 1.0, 0.01));   // compression never breaks
    EXPECT_FALSE(bondBreaks(5.0, 1.0, 0.0));    // crit <= 0: disabled
    EXPECT_FALSE(bondBreaks(5.0, 1.0, -1.0));
    const double r2 = std::sqrt(2.0);  // relative to the bond's own rest length
    EXPECT_FALSE(bondBreaks(r2 * 1.0099, r2, 0.01));
    EXPECT_TRUE(bondBreaks(r2 * 1.0101, r2, 0.01));
}

TEST(VcpmPhysics, BondVectorSameLengthFromBothEnds) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int t = 0; t < 100000; ++t) {
        const double sc = std::pow(10.0, 4 * u(rng));
        const Double3 a{sc * u(rng), sc * u(rng), sc * u(rng)};
        const Double3 b{a.x + 1e-3 * sc * u(rng), a.y + 1e-3 * sc * u(rng), a.z + 1e-3 * sc * u(rng)};
        double d1[3], d2[3];
        const double l1 = bondVector(a, b, d1[0], d1[1], d1[2]), l2 = bondVector(b, a, d2[0], d2[1], d2[2]);
        ASSERT_EQ(std::memcmp(&l1, &l2, sizeof l1), 0) << t;
        for (int c = 0; c < 3; ++c) ASSERT_EQ(d1[c], -d2[c]);
    }
}

TEST(VcpmPhysics, BreakageInSumsAndForces) {
    const double dp = 0.01;
    const VcpmMaterial m = vcpmMaterial(2, 1e6, 0.3, 1000.0, dp, 0, 0.01);
    Block b(true, 2, 1, 2, dp, m), cut(b), fresh(b);  // 2x2 square: (0,0)=0 (1,0)=1 (0,1)=2 (1,1)=3
    std::uint32_t k32 = 0;
    for (int q = 0; q < b.count[3]; ++q)
        if (b.partner[b.slot(3, q)] == 2) k32 = b.slot(3, q);
    const std::uint32_t k23 = b.mirror[k32];
    ASSERT_EQ(b.partner[k23], 3u);
    cut.broken[k32] = cut.broken[k23] = 1;  // the same square with 3-2 cut from the start
    std::vector<Double3> x = b.ref;
    // Pull 3 along +x by 1.5% dp: 3-2 stretches 1.5% (breaks), 3-0 0.75% and 3-1 0.01% (intact);
    // then undo most of it (0.5%, below crit): 3-2 stays broken.
    for (double st : {0.015, 0.005}) {
        x[3].x = b.ref[3].x + st * dp;
        const std::vector<Double3> f = forces(b, x), fc = forces(cut, x);
        for (std::size_t k = 0; k < b.broken.size(); ++k)
            EXPECT_EQ(b.broken[k], (k == k32 || k == k23) ? 1 : 0) << k;
        const double s3 = 0.5 * (std::hypot((1 + st) * dp, dp) - std::sqrt(2.0) * dp) + 0.5 * (std::hypot(st * dp, dp) - dp);
        EXPECT_NEAR(b.sum[3], s3, 1e-15 * dp);   // 3-1 and 3-0 only
        EXPECT_NEAR(b.sum[2], 0.0, 1e-15 * dp);  // 2-0 and 2-1 unchanged, 3-2 excluded
        for (std::uint32_t s = 0; s < b.n; ++s) {  // the same bits as the pre-cut square
            EXPECT_EQ(f[s].x, fc[s].x) << s;
            EXPECT_EQ(f[s].z, fc[s].z) << s;
        }
    }
    // An intact square at 0.5% keeps 3-2 (below crit), which pulls 3 back by about k dl more.
    const std::vector<Double3> f = forces(b, x), f2 = forces(fresh, x);
    for (std::uint8_t br : fresh.broken) EXPECT_EQ(br, 0);
    EXPECT_LT(f2[3].x, f[3].x - 0.5 * m.k_first * 0.0025 * dp);
}

TEST(VcpmPhysics, BothEndsDecideBreakageAlike) {
    for (bool two_d : {false, true}) {
        const double dp = 0.01;
        Block b(two_d, 8, 8, 8, dp, vcpmMaterial(two_d ? 2 : 3, 1e6, 0.3, 1000.0, dp, 0, 0.01));
        std::mt19937_64 rng(5);
        std::size_t nbroken = 0, nslots = 0;
        for (int trial = 0; trial < 5; ++trial) {
            std::vector<Double3> x = b.ref;
            perturb(x, 0.006 * dp, two_d, rng);
            forces(b, x);
        }
        for (std::uint32_t s = 0; s < b.n; ++s)
            for (int q = 0; q < b.count[s]; ++q) {
                const std::uint32_t k = b.slot(s, q);
                ++nslots;
                nbroken += b.broken[k];
                ASSERT_EQ(b.broken[k], b.broken[b.mirror[k]]) << s << " slot " << q;
            }
        std::printf("[ break ] %s  %zu of %zu slots broken, mirrors agree\n", two_d ? "2D" : "3D", nbroken, nslots);
        EXPECT_GT(nbroken, 0u);
        EXPECT_LT(nbroken, nslots);
    }
}

// Integrator: one bond. With dl = e/2 and S_I = S_J = dl, the bond force is -(k+T)/2 e, so a
// free pair oscillates at sqrt((k+T)/m) and a particle bonded to a fixed clamp node at
// sqrt((k+T)/(2m)); lattice energy (k+T) e^2/4.

struct Oscillation { std::vector<double> t, e, energy; };

/// Runs `steps` sub-steps of a bond along x (a clamp node at the origin when `clamp`, else a
/// second free particle there), starting from elongation a, at rest.
Oscillation oscillate(bool clamp, const VcpmMaterial& m, double dp, double a, double dt, int steps) {
    Block b(false, clamp ? 1 : 2, 1, 1, dp, m);
    std::vector<std::uint8_t> ccount;
    std::vector<std::uint32_t> cpartner, cslot;
    std::vector<Double3> cpos;
    std::vector<double> csum;
    if (clamp) {  // particle 0 at (dp, 0, 0), its bond slot 0 to clamp node 0 at the origin
        b.count = ccount = {1};
        b.partner = cpartner = cslot = {0};
        b.rest = {dp};
        b.flags = {kBondClamp};
        b.broken = {0};
        b.pos = b.pos_half = {Double3{dp, 0, 0}};
        cpos = {Double3{0, 0, 0}};
        csum = {0.0};
    }
    const ClampNodes cn{clamp ? 1u : 0u, ccount.data(), cpartner.data(), cslot.data(), cpos.data(), cpos.data(), csum.data()};
    const SolidState st = b.state();
    const SolidBonds sb = b.bonds();
    b.pos[b.n - 1].x += a;
    auto sums = [&](const Double3* ep) {
        for (std::uint32_t s = 0; s < b.n; ++s) b.sum[s] = solidSumAt(s, ep, st, sb, cn, 0.0);
        for (std::uint32_t c = 0; c < cn.n; ++c) csum[c] = clampSumAt(c, ep, st, sb, cn, 0.0);
    };
    Oscillation o;
    for (int m_ = 0; m_ <= steps; ++m_) {
        const double e = (clamp ? b.pos[0].x : b.pos[1].x - b.pos[0].x) - dp;
        double ke = 0.0;
        for (const Double3& v : b.vel) ke += 0.5 / m.inv_mass * (v.x * v.x + v.y * v.y + v.z * v.z);
        o.t.push_back(m_ * dt);
        o.e.push_back(e);
        o.energy.push_back(ke + (m.k_first + 2 * m.t_half) * e * e / 4);
        if (m_ == steps) break;
        sums(b.pos.data());
        for (std::uint32_t s = 0; s < b.n; ++s) solidPredictorAt(s, st, sb, cn, 0.0, dt, 0, 0, 0);
        sums(b.pos_half.data());
        for (std::uint32_t s = 0; s < b.n; ++s) solidCorrectorAt(s, st, sb, cn, 0.0, dt, 0, 0, 0);
    }
    return o;
}

/// Mean period from the downward zero crossings (linear interpolation).
double measuredPeriod(const Oscillation& o) {
    std::vector<double> tc;
    for (std::size_t i = 1; i < o.e.size(); ++i)
        if (o.e[i - 1] > 0 && o.e[i] <= 0) tc.push_back(o.t[i - 1] + (o.t[i] - o.t[i - 1]) * o.e[i - 1] / (o.e[i - 1] - o.e[i]));
    return tc.size() < 2 ? 0.0 : (tc.back() - tc.front()) / double(tc.size() - 1);
}

TEST(VcpmPhysics, IntegratorFrequencyAndEnergy) {
    const double dp = 0.01, rho = 2500;
    // nu = 0.45: T = 0.27 k, so a clamp node without its own S (or T/2 missing) shows.
    const VcpmMaterial m = vcpmMaterial(3, 3e6, 0.45, rho, dp, 0, 0);
    const double mass = 1.0 / m.inv_mass, kt = m.k_first + 2 * m.t_half;
    for (bool clamp : {false, true}) {
        const double omega = std::sqrt(kt / ((clamp ? 2 : 1) * mass)), period = 2 * kPi / omega, dt = period / 50;
        const Oscillation o = oscillate(clamp, m, dp, 1e-4 * dp, dt, 500);  // 10 periods
        const double om = 2 * kPi / measuredPeriod(o);
        // Position Verlet on x'' = -w^2 x has the exact discrete frequency (2/dt) asin(w dt/2).
        const double om_verlet = 2 / dt * std::asin(omega * dt / 2);
        double drift = 0.0;
        for (double en : o.energy) drift = std::max(drift, std::fabs(en / o.energy[0] - 1));
        std::printf("[ integ ] %s  omega_meas/omega-1=%+.2e  omega_meas/omega_verlet-1=%+.2e  max|E/E0-1|=%.2e\n",
                    clamp ? "clamp" : "pair ", om / omega - 1, om / om_verlet - 1, drift);
        EXPECT_NEAR(om / omega, 1.0, 0.005);
        EXPECT_NEAR(om / om_verlet, 1.0, 1e-5);
        EXPECT_LT(drift, 0.01);
        double late = 0.0;  // no growth: the last period's energy error is no larger than the first's
        for (std::size_t i = o.energy.size() - 50; i < o.energy.size(); ++i)
            late = std::max(late, std::fabs(o.energy[i] / o.energy[0] - 1));
        EXPECT_LT(late, 1.5 * drift + 1e-12);
    }
}

TEST(VcpmPhysics, DampingDecaysAmplitude) {
    const double dp = 0.01, rho = 2500, E = 3e6;
    const VcpmMaterial m0 = vcpmMaterial(3, E, 0.3, rho, dp, 0, 0);
    const double omega = std::sqrt((m0.k_first + 2 * m0.t_half) * m0.inv_mass / 2);
    const double cd = 0.05 * omega, damping = cd / std::sqrt(E / (rho * dp * dp));
    const VcpmMaterial m = vcpmMaterial(3, E, 0.3, rho, dp, damping, 0);
    EXPECT_NEAR(m.damp_rate, cd, 1e-12 * cd);
    const Oscillation o = oscillate(true, m, dp, 1e-4 * dp, 2 * kPi / omega / 50, 500);
    std::vector<std::size_t> peaks;
    for (std::size_t i = 1; i + 1 < o.e.size(); ++i)
        if (o.e[i] > o.e[i - 1] && o.e[i] >= o.e[i + 1]) peaks.push_back(i);
    ASSERT_GE(peaks.size(), 5u);
    const std::size_t p0 = peaks.front(), p1 = peaks.back();
    const double rate = -2 * std::log(o.e[p1] / o.e[p0]) / (o.t[p1] - o.t[p0]);
    std::printf("[ damp  ] decay rate / c_d = %.4f\n", rate / cd);
    EXPECT_NEAR(rate / cd, 1.0, 0.05);
}

TEST(VcpmPhysics, ClampNodeMovesLinearly) {
    const Double3 a{1.0, -2.0, 0.5}, c{3.0, 2.0, 0.5};
    const ClampNodes cn{1, nullptr, nullptr, nullptr, &a, &c, nullptr};
    const Double3 p = clampPosAt(cn, 0, 0.25);
    EXPECT_DOUBLE_EQ(p.x, 1.5);
    EXPECT_DOUBLE_EQ(p.y, -1.0);
    EXPECT_DOUBLE_EQ(p.z, 0.5);
}

TEST(VcpmPhysics, SubstepCount) {
    EXPECT_EQ(solidSubsteps(1.0, 1.0), 2);  // exact ratio 1: int(1) + 1
    EXPECT_EQ(solidSubsteps(0.5, 1.0), 1);
    EXPECT_EQ(solidSubsteps(3.7, 1.0), 4);
    EXPECT_EQ(solidSubsteps(2e-5, 1e-5), 3);
}

TEST(VcpmPhysics, MaterialConstants) {
    const double E = 3e6, dp = 0.02;
    const struct { double nu, k, t; } table[] = {{0.30, 0.7692, 0.0131}, {0.45, 0.6897, 0.1882},
                                                 {0.40, 0.7143, 0.0731}, {0.38, 0.7246, 0.0536}};
    for (const auto& r : table) {
        const VcpmMaterial m = vcpmMaterial(3, E, r.nu, 2500, dp, 0, 0);
        EXPECT_NEAR(m.k_first / (E * dp), r.k, 5e-5) << r.nu;
        EXPECT_EQ(m.k_second, m.k_first);
        EXPECT_NEAR(2 * m.t_half / (E * dp), r.t, 5e-5) << r.nu;
        EXPECT_NEAR(m.k_first, E * dp / (1 + r.nu), 1e-12 * m.k_first);
    }
    EXPECT_EQ(vcpmMaterial(3, E, 0.25, 2500, dp, 0, 0).t_half, 0.0);
    const VcpmMaterial m2 = vcpmMaterial(2, E, 0.3, 2500, dp, 0.5, 0.02);
    EXPECT_NEAR(m2.k_first, 2 * E / 1.3, 1e-12 * E);
    EXPECT_NEAR(m2.k_second, E / 1.3, 1e-12 * E);
    EXPECT_NEAR(2 * m2.t_half, E * 0.2 / (2 * (3 + 2 * std::sqrt(2.0)) * 1.3 * 0.4), 1e-12 * E);
    EXPECT_NEAR(m2.inv_mass, 1 / (2500 * dp * dp), 1e-9);
    EXPECT_NEAR(m2.damp_rate, 0.5 * std::sqrt(E / (2500 * dp * dp)), 1e-12);
    EXPECT_EQ(m2.crit_stretch, 0.02);
    const VcpmElastic el = vcpmElastic(3e6, 0.3, 2500);
    EXPECT_NEAR(el.wave_speed, 40.19, 0.005);
    EXPECT_NEAR(el.shear, 3e6 / 2.6, 1e-6);
    EXPECT_NEAR(el.bulk, 3e6 / 1.2, 1e-6);
}

TEST(VcpmPhysics, EnergyOfOneBondByHand) {
    // One first-neighbour bond stretched from L0 to L: dl = (L - L0)/2 at each end, S = dl at
    // both sites: U = 2 (1/2 k dl^2) + 2 (1/2 T dl^2) = k dl^2 + 2 t_half dl^2.
    VcpmMaterial m;
    m.k_first = 1000.0;
    m.k_second = 400.0;
    m.t_half = 50.0;
    const double rest = 0.01, len = 0.0102, dl = halfElongation(len, rest);
    EXPECT_NEAR(dl, 1e-4, 1e-15);
    const double k = bondStiffness(m, 0);
    EXPECT_EQ(k, 1000.0);
    EXPECT_EQ(bondStiffness(m, kBondSecond), 400.0);
    EXPECT_EQ(bondStiffness(m, kBondSecond | kBondClamp), 400.0);
    const double site = bondSpringEnergy(k, dl, false) + siteVolumetricEnergy(m.t_half, dl);
    EXPECT_NEAR(2 * site, 1.1e-5, 1e-16);
    // The same bond clamped: seen from the solid end only (k dl^2), plus the two sites'
    // volumetric terms (the clamp node's S = dl too): the same energy.
    const double clamped = bondSpringEnergy(k, dl, true) + siteVolumetricEnergy(m.t_half, dl) +
                           siteVolumetricEnergy(m.t_half, dl);
    EXPECT_NEAR(clamped, 1.1e-5, 1e-16);
    // -dU/dL is bondForce (Eq. 13) with S_I = S_J = dl; dU/dL = dU/d(dl) / 2.
    EXPECT_NEAR(bondForce(k, m.t_half, dl, dl, dl), -(2 * k * dl + 4 * m.t_half * dl) / 2, 1e-14);
    EXPECT_NEAR(bondStrain(len, rest), 0.02, 1e-12);
    EXPECT_NEAR(bondStrain(0.0099, rest), -0.01, 1e-12);
}

TEST(VcpmPhysics, LedgerEnergyEqualsTheLatticeEnergy) {
    // The ledger's sum (bondSpringEnergy over intact bonds + siteVolumetricEnergy per site)
    // against this file's independent energy(), whose gradient the forces match.
    for (bool two_d : {false, true}) {
        const double dp = 0.01;
        Block b(two_d, 5, 4, 5, dp, vcpmMaterial(two_d ? 2 : 3, 1e6, 0.3, 1000.0, dp, 0, 0));
        const std::uint32_t k0 = b.slot(b.at(1, two_d ? 0 : 1, 1), 2);
        b.broken[k0] = b.broken[b.mirror[k0]] = 1;
        std::mt19937_64 rng(5);
        std::vector<Double3> x = b.ref;
        perturb(x, 0.02 * dp, two_d, rng);
        double u = 0.0;
        for (std::uint32_t s = 0; s < b.n; ++s) {
            double springs = 0.0, sum = 0.0;
            for (int q = 0; q < b.count[s]; ++q) {
                const std::uint32_t k = b.slot(s, q);
                if (b.broken[k]) continue;
                double dx, dy, dz;
                const double dl = halfElongation(bondVector(x[s], x[b.partner[k]], dx, dy, dz), b.rest[k]);
                springs += bondSpringEnergy(bondStiffness(b.mat, b.flags[k]), dl, false);
                sum += dl;
            }
            u += springs + siteVolumetricEnergy(b.mat.t_half, sum);
        }
        const double ref = energy(b, x);
        EXPECT_GT(ref, 0.0);
        EXPECT_NEAR(u, ref, 1e-12 * ref) << (two_d ? "2D" : "3D");
    }
}

TEST(VcpmPhysics, ParticleMassAndSubstepLength) {
    EXPECT_NEAR(vcpmParticleMass(3, 2500, 0.02), 0.02, 1e-15);  // rho dp^3
    EXPECT_NEAR(vcpmParticleMass(2, 2500, 0.02), 1.0, 1e-13);   // rho dp^2 (per m of thickness)
    for (int dim : {2, 3})
        EXPECT_EQ(vcpmMaterial(dim, 3e6, 0.3, 2500, 0.02, 0, 0).inv_mass, 1.0 / vcpmParticleMass(dim, 2500, 0.02));
    EXPECT_NEAR(vcpmTimeStep(0.5, 0.02, 40.0), 2.5e-4, 1e-18);
}

}  // namespace
