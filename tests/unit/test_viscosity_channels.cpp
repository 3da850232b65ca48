// SeaSpring — MIT licence.
/// \file test_viscosity_channels.cpp
/// \brief The laminar viscous operator against analytic channel flows: Poiseuille and Couette
///        start-up in an x-periodic channel (the ChannelFlows tests, h = 1.5 dp and 2 dp).
///
/// The harness (frozen lattice, the solver's pair functions, Heun integration, the channel's
/// mirrored wall layers) is in viscosity_lattice.h.
///
/// What the measurements showed (Release, 2-core development VM, 20 particles across):
/// the Lo & Shao term with eta^2 = 0.01 h^2 (as DualSPHysics) acts on a lattice with an
/// effective viscosity nu_eff = lap nu, lap = 0.98488 (h = 1.5 dp) / 0.98492 (h = 2 dp)
/// (handLatticeSums): each pair is lowered by eta^2/(r^2 + eta^2). This 1.5% does not go away
/// with refinement at fixed h/dp (Taylor–Green: rate/(2 nu k^2) = 0.9373, 0.9728, 0.9819 at
/// N = 16, 32, 64, second order towards 0.98493; Poiseuille steady error vs the nu profile
/// 2.19%, 1.69%, 1.57% at 20, 40, 80 across, h = 2 dp, computed outside this file with a
/// row-reduced model of the same sums). So "within 1% of the analytic solution" is asserted
/// against the analytic solution with nu_eff (the hand lattice sum), and against the plain-nu
/// solution within (1 - lap) + 1% where the bias is visible (steady Poiseuille, interior force
/// balance); transients before the bias shows (Poiseuille nu t/L^2 <= 0.1, Couette) are held to
/// 1% of the plain-nu series as well. These tests measure DualSPHysics' operator
/// (LaminarLatticeCorrection 0); the solver's default divides nu by the same lattice sum
/// (physics::laminarLatticeRatio = lap), and PoiseuilleWithTheLatticeCorrectionMeetsPlainNu
/// holds that within 1% of the plain-nu series at every time.
///
/// Measured errors (tolerance in brackets):
///   Poiseuille, max |u - u_exact| / centre-line velocity, at nu t/L^2 = 0.02 0.05 0.1 0.3 2:
///     h = 1.5 dp: vs nu_eff 0.38 0.40 0.41 0.43 0.44% (1%); vs nu 0.41 0.44 0.50% (1%),
///                 then 1.52 1.94% ((1 - lap) + 1% = 2.51%)
///     h = 2 dp:   vs nu_eff 0.70 0.73 0.75 0.78 0.79% (1%); vs nu 0.73 0.78 0.82% (1%),
///                 then 1.69 2.18% (2.51%)
///   Poiseuille force balance of the exact profile: interior rows -a/g = lap within 3.3e-6
///     (1e-4); every row within 3.3e-6 of handMirrorBalance (1e-4); first rows (wall
///     mirror) -a/g = 0.642, 0.966, 0.985 (h = 1.5 dp), 0.538, 0.927, 0.982 (h = 2 dp).
///   Couette, max |u - u_exact| / U at nu t/L^2 = 0.05 0.1 0.2: h = 1.5 dp vs nu 0.63 0.50
///     0.35%, vs nu_eff 0.28 0.14 0.08% (1%); h = 2 dp vs nu 0.80 0.58 0.40%, vs nu_eff 0.45
///     0.23 0.13% (1%); steady (nu t/L^2 = 2) linear within 6e-8 U (1e-4 U).
///   Run time: Poiseuille 0.15 / 0.21 s, Couette 0.15 / 0.20 s, the force balance under 1 ms
///   (measured when these tests and those of test_viscosity_vortex_sps.cpp were one executable,
///   1.2 s in all).
///
/// Break-it-on-purpose checks (each change alone, in a private copy of src/ that these tests
/// were compiled against with the project's flags, when they were one file with those of
/// test_viscosity_vortex_sps.cpp; src/ itself was never edited):
///   A laminarViscosityFactor returns -(...)  (sign flip): all 6 channel tests (3 tests x 2 h)
///     fail (and Taylor–Green): runs blow up (Poiseuille error 1.4e6 x centre-line at
///     nu t/L^2 = 0.02, NaN later); the exact profile's -a/g = -0.985 in the interior
///     (expected 0.985).
///   C laminarViscosityFactor with 2 nu instead of 4 nu (a factor 2 dropped): all 6 channel
///     tests fail (and Taylor–Green): interior -a/g = 0.492; Poiseuille steady error 101% vs
///     nu_eff; Couette 17% at nu t/L^2 = 0.05.
///   Also: visco_bound = 2 visco (ViscoBoundFactor wrong): Poiseuille balance (first row 8.68
///     vs 0.642) and both start-up tests fail (Poiseuille 6.7% vs nu_eff, Couette 4.3%).
///     eta2 = 0: the force balance fails (interior -a/g = 0.9974 vs lap 0.9849; Taylor–Green
///     too). visco x 1.1 for fluid pairs: all channel tests (and Taylor–Green) fail.
///   (B and the SPS checks: test_viscosity_vortex_sps.cpp.)
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "viscosity_lattice.h"

using namespace seaspring::physics;
using namespace seaspring::test::visc;

namespace {

/// Body-force driven channel flow from rest (plates at z = 0 and L, no slip):
///   u(z, t) = g/(2 nu) z (L - z) - sum_{n odd} 4 g L^2/(nu pi^3 n^3) sin(n pi z/L) exp(-n^2 pi^2 nu t/L^2)
/// (Morris, Fox & Zhu 1997, eq. 23, written from rest with the body force along +x).
double poiseuilleSeries(double z, double t, double L, double g, double nu) {
    double u = g / (2.0 * nu) * z * (L - z);
    for (int n = 1; n < 2000; n += 2) {
        const double e = std::exp(-double(n) * n * kPi * kPi * nu * t / (L * L));
        if (e == 0.0) break;
        u -= 4.0 * g * L * L / (nu * kPi * kPi * kPi * double(n) * n * n) * std::sin(n * kPi * z / L) * e;
    }
    return u;
}

/// Couette start-up (bottom plate fixed, top plate moving at U from t = 0):
///   u(z, t) = U z/L + sum_{n>=1} 2U (-1)^n/(n pi) sin(n pi z/L) exp(-n^2 pi^2 nu t/L^2)
/// (Morris, Fox & Zhu 1997, eq. 22).
double couetteSeries(double z, double t, double L, double U, double nu) {
    double u = U * z / L;
    for (int n = 1; n < 20000; ++n) {
        const double e = std::exp(-double(n) * n * kPi * kPi * nu * t / (L * L));
        if (e == 0.0) break;
        u += 2.0 * U * (n % 2 ? -1.0 : 1.0) / (n * kPi) * std::sin(n * kPi * z / L) * e;
    }
    return u;
}

/// Hand evaluation (double, dp = 1, nu = 1, g = 1, V = 1, from the Wendland formula and the
/// Lo & Shao pair term cv = m_b 4 nu (r . grad W)/((rho_a + rho_b)(r^2 + eta^2)) = 2 F r^2/(r^2 +
/// 0.01 h^2) at rho = rho0) of -a_x/g in fluid row k of an n-row channel holding the exact
/// steady Poiseuille profile u = z (n - z)/2, with the wall particles' mirrored velocities
/// (-u of the mirror row: both walls fixed): -sum_b cv (u_a - u_b).
double handMirrorBalance(double hdp, int n, int k) {
    const double h = hdp, ad = 7.0 / (4.0 * kPi * h * h);
    const int m = int(std::ceil(2.0 * h));
    auto u = [n](double z) { return z * (n - z) / 2.0; };
    const double za = k + 0.5;
    double a = 0;
    for (int dx = -m; dx <= m; ++dx)
        for (int dz = -m; dz <= m; ++dz) {
            const double r2 = double(dx * dx + dz * dz);
            if (r2 == 0 || r2 > 4.0 * h * h) continue;
            const double q = std::sqrt(r2) / h, w = 1.0 - 0.5 * q;
            const double f = -5.0 * ad / (h * h) * w * w * w;
            const double zb = za - dz;  // r_ab = r_a - r_b
            const double ub = zb < 0 ? -u(-zb) : zb > n ? -u(2.0 * n - zb) : u(zb);
            a += 2.0 * f * r2 / (r2 + 0.01 * h * h) * (u(za) - ub);
        }
    return -a;
}

// Morris et al. (1997) parameters: L = 1 mm, nu = 1e-6 m^2/s, g = 2e-4 m/s^2 (Poiseuille,
// centre-line velocity g L^2/(8 nu) = 2.5e-5 m/s), U = 1.25e-5 m/s (Couette); Re << 1.
constexpr double kL = 1e-3, kNu = 1e-6, kG = 2e-4, kU = 1.25e-5;
constexpr int kAcross = 20;  // fluid particles across the channel
constexpr int kColumns = 8;  // x period of the channel lattice, in dp (images are exact anyway)

class ChannelFlows : public ::testing::TestWithParam<double> {};

}  // namespace

// ---------------------------------------------------------------------------------------------
// 1. Poiseuille.

TEST_P(ChannelFlows, PoiseuilleExactProfileBalancesBodyForce) {
    // The laminar acceleration of the exact steady profile u = g/(2 nu) z (L - z), row by row,
    // against -g: in rows farther than 2h from both walls (no mirror in reach) -a/g is the hand
    // lattice sum `lap` = 0.98488 (h = 1.5 dp) / 0.98492 (h = 2 dp), 1.5% short of balance
    // whatever the resolution (eta^2, see handLatticeSums); asserted within 1e-4 of `lap`, and
    // within (1 - lap) + 1% of 1. Near the walls the mirrored wall particles carry the odd
    // extension of u, whose u'' jumps from -g/nu to +g/nu at the wall, so the first rows are
    // far from balance (-a/g = 0.64 in the first row at h = 1.5 dp); every row, walls included,
    // is asserted within 1e-4 of a hand evaluation of the same sum (handMirrorBalance).
    const double hdp = GetParam(), dp = kL / kAcross;
    Channel ch(kAcross, kColumns, dp, hdp, kNu);
    Velocities v{std::vector<double>(ch.lat.nfluid), std::vector<double>(ch.lat.nfluid, 0.0)};
    for (std::uint32_t a = 0; a < ch.lat.nfluid; ++a) v.u[a] = kG / (2 * kNu) * ch.lat.z[a] * (kL - ch.lat.z[a]);
    ch.load(v);
    const double lap = handLatticeSums(hdp, 2).lap;
    double worst_interior = 0, worst_hand = 0;
    std::vector<double> ratio(kAcross);
    for (int k = 0; k < kAcross; ++k) {
        for (int i = 0; i < kColumns; ++i) {
            const FluidAccum acc = ch.lat.forces<OptLam2>(std::uint32_t(k * kColumns + i));
            EXPECT_NEAR(-double(acc.ax) / kG, handMirrorBalance(hdp, kAcross, k), 1e-4)
                << "row " << k << " column " << i;
            EXPECT_EQ(acc.az, 0.f);
            if (i == 0) ratio[k] = -double(acc.ax) / kG;  // 1 would balance the body force exactly
        }
        worst_hand = worse(worst_hand, std::fabs(ratio[k] - handMirrorBalance(hdp, kAcross, k)));
        const bool interior = ch.zOfRow(k) >= 2 * ch.lat.h && kL - ch.zOfRow(k) >= 2 * ch.lat.h;
        if (interior) {
            worst_interior = worse(worst_interior, std::fabs(ratio[k] - lap));
            EXPECT_NEAR(ratio[k], lap, 1e-4) << "row " << k;
            EXPECT_NEAR(ratio[k], 1.0, (1.0 - lap) + 0.01) << "row " << k;
        }
    }
    // The hand sum itself (the bias of the Lo & Shao operator with eta^2 = 0.01 h^2 on the lattice).
    EXPECT_NEAR(lap, hdp == 1.5 ? 0.984879 : 0.984923, 2e-6);
    std::printf("[poiseuille balance hdp=%.2f] interior rows: -a/g = lap = %.6f (worst difference %.1e); rows 0, 1, 2: "
                "-a/g = %.4f %.4f %.4f; worst difference from the hand sum %.1e\n",
                hdp, lap, worst_interior, ratio[0], ratio[1], ratio[2], worst_hand);
}

TEST_P(ChannelFlows, PoiseuilleStartUpAndSteadyProfile) {
    const auto t0 = std::chrono::steady_clock::now();
    const double hdp = GetParam(), dp = kL / kAcross;
    Channel ch(kAcross, kColumns, dp, hdp, kNu);
    const double nu_eff = kNu * handLatticeSums(hdp, 2).lap;
    Velocities v{std::vector<double>(ch.lat.nfluid, 0.0), std::vector<double>(ch.lat.nfluid, 0.0)};
    ch.load(v);
    const double dt = ch.lat.stableDt();
    double t = 0;
    const double tscale = kL * kL / kNu;  // 1 s
    // Errors: max over the channel of |u - u_exact(t)| / centre-line steady velocity g L^2/(8 nu)
    // of the same viscosity. Against the series with nu (transient, until the eta^2 bias of the
    // operator shows) and with nu_eff = lap nu (every time, steady state included).
    for (double tt : {0.02, 0.05, 0.1, 0.3, 2.0}) {
        integrate(ch.lat, v, t, tt * tscale, dt, kG, [&](const Velocities& s) { ch.load(s); });
        double spread = 0;
        const std::vector<double> p = ch.profile(v, &spread);
        double e_nu = 0, e_eff = 0;
        for (int k = 0; k < kAcross; ++k) {
            e_nu = worse(e_nu, std::fabs(p[k] - poiseuilleSeries(ch.zOfRow(k), t, kL, kG, kNu)));
            e_eff = worse(e_eff, std::fabs(p[k] - poiseuilleSeries(ch.zOfRow(k), t, kL, kG, nu_eff)));
        }
        e_nu /= kG * kL * kL / (8 * kNu);
        e_eff /= kG * kL * kL / (8 * nu_eff);
        std::printf("[poiseuille hdp=%.2f] nu t/L^2 = %.2f: error vs series(nu) %.4f, vs series(nu_eff) %.4f, "
                    "column spread %.1e\n",
                    hdp, tt, e_nu, e_eff, spread / (kG * kL * kL / (8 * kNu)));
        EXPECT_LT(e_eff, 0.01) << "t = " << t;
        if (tt <= 0.1) {
            EXPECT_LT(e_nu, 0.01) << "t = " << t;
        }
        // Steady state against the plain analytic profile: the operator's eta^2 bias (1 - lap)
        // plus the brief's 1%.
        EXPECT_LT(e_nu, (1.0 - handLatticeSums(hdp, 2).lap) + 0.01) << "t = " << t;
        EXPECT_LT(spread, 1e-6 * kG * kL * kL / (8 * kNu));
    }
    std::printf("[poiseuille hdp=%.2f] dt = %.3e s, %.2f s wall\n", hdp, dt, seconds(t0));
}

// The same start-up with LaminarLatticeCorrection (the solver's default): nu divided by the
// solver's lattice ratio (physics::laminarLatticeRatio, checked against the hand sum `lap`), so
// the operator's lattice bias (eta^2 and the lattice's second moment) is gone and the profile
// meets the plain-nu series within the brief's 1% at every time, the steady state included
// (measured 0.40/0.43/0.44% at h = 1.5 dp, 0.73/0.78/0.79% at h = 2 dp; without the correction
// 2.2% at h = 2 dp, above).
// Broken on purpose (the scale left at 1) the steady error is back to 1.9-2.2% and this fails
// (checked).
TEST_P(ChannelFlows, PoiseuilleWithTheLatticeCorrectionMeetsPlainNu) {
    const double hdp = GetParam(), dp = kL / kAcross;
    const double ratio = laminarLatticeRatio<WendlandKernel>(hdp * dp, dp, 2);
    EXPECT_NEAR(ratio, handLatticeSums(hdp, 2).lap, 1e-5);
    EXPECT_NEAR(laminarLatticeRatio(KernelType::Wendland, 2.0 * dp, dp, 3), 0.98863, 1e-5);  // 3D, h = 2 dp
    Channel ch(kAcross, kColumns, dp, hdp, kNu, 1.0 / ratio);
    Velocities v{std::vector<double>(ch.lat.nfluid, 0.0), std::vector<double>(ch.lat.nfluid, 0.0)};
    ch.load(v);
    const double dt = ch.lat.stableDt();
    double t = 0;
    const double tscale = kL * kL / kNu;
    for (double tt : {0.05, 0.3, 2.0}) {
        integrate(ch.lat, v, t, tt * tscale, dt, kG, [&](const Velocities& s) { ch.load(s); });
        const std::vector<double> p = ch.profile(v, nullptr);
        double e_nu = 0;
        for (int k = 0; k < kAcross; ++k)
            e_nu = worse(e_nu, std::fabs(p[k] - poiseuilleSeries(ch.zOfRow(k), t, kL, kG, kNu)));
        e_nu /= kG * kL * kL / (8 * kNu);
        std::printf("[poiseuille lattice-corrected hdp=%.2f] nu t/L^2 = %.2f: error vs series(nu) %.4f (ratio %.6f)\n", hdp,
                    tt, e_nu, ratio);
        EXPECT_LT(e_nu, 0.01) << "t = " << t;
    }
}

// ---------------------------------------------------------------------------------------------
// 2. Couette.

TEST_P(ChannelFlows, CouetteStartUpAndLinearSteadyProfile) {
    const auto t0 = std::chrono::steady_clock::now();
    const double hdp = GetParam(), dp = kL / kAcross;
    Channel ch(kAcross, kColumns, dp, hdp, kNu);
    ch.u_top = kU;
    const double nu_eff = kNu * handLatticeSums(hdp, 2).lap;
    Velocities v{std::vector<double>(ch.lat.nfluid, 0.0), std::vector<double>(ch.lat.nfluid, 0.0)};
    ch.load(v);
    const double dt = ch.lat.stableDt();
    double t = 0;
    const double tscale = kL * kL / kNu;
    for (double tt : {0.05, 0.1, 0.2, 2.0}) {
        integrate(ch.lat, v, t, tt * tscale, dt, 0.0, [&](const Velocities& s) { ch.load(s); });
        double spread = 0;
        const std::vector<double> p = ch.profile(v, &spread);
        double e_nu = 0, e_eff = 0, e_lin = 0;
        for (int k = 0; k < kAcross; ++k) {
            const double zk = ch.zOfRow(k);
            e_nu = worse(e_nu, std::fabs(p[k] - couetteSeries(zk, t, kL, kU, kNu)) / kU);
            e_eff = worse(e_eff, std::fabs(p[k] - couetteSeries(zk, t, kL, kU, nu_eff)) / kU);
            e_lin = worse(e_lin, std::fabs(p[k] - kU * zk / kL) / kU);
        }
        std::printf("[couette hdp=%.2f] nu t/L^2 = %.2f: error/U vs series(nu) %.4f, vs series(nu_eff) %.4f, "
                    "vs linear %.2e\n",
                    hdp, tt, e_nu, e_eff, e_lin);
        EXPECT_LT(e_nu, 0.01) << "t = " << t;
        EXPECT_LT(e_eff, 0.01) << "t = " << t;
        if (tt >= 2.0) {
            EXPECT_LT(e_lin, 1e-4);  // exp(-2 pi^2) = 3e-9: steady; linear is exact
        }
        EXPECT_LT(spread, 1e-6 * kU);
    }
    std::printf("[couette hdp=%.2f] dt = %.3e s, %.2f s wall\n", hdp, dt, seconds(t0));
}

INSTANTIATE_TEST_SUITE_P(Hdp, ChannelFlows, ::testing::Values(1.5, 2.0),
                         [](const ::testing::TestParamInfo<double>& i) { return i.param == 1.5 ? "h1_5dp" : "h2dp"; });
