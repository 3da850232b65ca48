// SeaSpring — MIT licence.
/// \file test_solid_elastica.cpp
/// \brief VCPM solids far from the linear regime: a slender 2D cantilever (L/t = 20, plane
///        strain) settled under a dead tip load with alpha = P L^2 / (E' I) = 3, its free end
///        60% of L below the clamp and rotated by 56 degrees, against the elastica (the
///        inextensible beam with M = E' I kappa; Bisshopp & Drucker 1945, Mattiasson 1981), at 4
///        and 8 particles through the thickness, nu 0.3 and 0.49, with the default corrections.
///        Only the lattice's geometric nonlinearity (bonds along the current positions) and its
///        bending stiffness can make it follow the curve: a linear model would put the end at
///        alpha/3 = 100% of L below the clamp and not move it back in x.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include "solver/solver_case.h"
#include "solver_test_util.h"

using namespace seaspring;

namespace {

/// The elastica's free end under a dead load normal to the undeformed beam: theta'' = -alpha
/// cos(theta) on s in [0, 1], theta(0) = 0 (clamp), theta'(1) = 0 (no moment at the end),
/// solved by shooting on theta'(0) (bisection, RK4 over 4000 steps, Simpson for the position).
/// Returns (v, u)/L: the end's displacement along the load and its shortening along the beam.
struct ElasticaTip {
    double v = 0, u = 0;
};
ElasticaTip elasticaTip(double alpha) {
    const int n = 4000;
    const double h = 1.0 / n;
    auto shoot = [&](double k0, double& x, double& y) {
        double th = 0.0, k = k0;
        x = 0.0;
        y = 0.0;
        for (int i = 0; i < n; ++i) {
            const double a1 = k, b1 = -alpha * std::cos(th);
            const double a2 = k + 0.5 * h * b1, b2 = -alpha * std::cos(th + 0.5 * h * a1);
            const double a3 = k + 0.5 * h * b2, b3 = -alpha * std::cos(th + 0.5 * h * a2);
            const double a4 = k + h * b3, b4 = -alpha * std::cos(th + h * a3);
            const double th1 = th + h / 6 * (a1 + 2 * a2 + 2 * a3 + a4);
            k += h / 6 * (b1 + 2 * b2 + 2 * b3 + b4);
            x += h / 6 * (std::cos(th) + 4 * std::cos(0.5 * (th + th1)) + std::cos(th1));
            y += h / 6 * (std::sin(th) + 4 * std::sin(0.5 * (th + th1)) + std::sin(th1));
            th = th1;
        }
        return k;  // theta'(1)
    };
    double lo = 0.0, hi = alpha + 1e-9, x = 0, y = 0;
    for (int it = 0; it < 100; ++it) {
        const double mid = 0.5 * (lo + hi);
        (shoot(mid, x, y) > 0 ? hi : lo) = mid;
    }
    shoot(0.5 * (lo + hi), x, y);
    return ElasticaTip{y, 1.0 - x};
}

struct Bent {
    double v = 0, u = 0;  ///< the loaded particles' mean displacement along -z and -x, over L - dp/2
};

/// The cantilever of tests/data/elastica/TipLoad2D_Def.xml, `thick` particles through the
/// thickness, settled (1.2 s, 2 threads) under the dead tip load of `alpha`.
Bent settle(int thick, double nu, double alpha) {
    const double E = 2e6, rho = 1000, t = 0.01, L = 0.2, dp = t / thick;
    const double e_plane = E / (1 - nu * nu), inertia = t * t * t / 12, arm = L - 0.5 * dp;
    const double load = alpha * e_plane * inertia / (arm * arm);  // the clamp face is at x = dp/2
    const double w1 = 1.8751 * 1.8751 / (arm * arm) * std::sqrt(e_plane * inertia / (rho * t));
    const double damping = 1.5 * w1 / std::sqrt(E / (rho * dp * dp));  // c_d = damping sqrt(E/(rho dp^2))
    const double z1 = (thick / 2 - 1) * dp, z2 = (thick / 2) * dp;
    auto num = [](double v) {
        char b[40];
        std::snprintf(b, sizeof b, "%.17g", v);
        return std::string(b);
    };
    std::string xml = test::readFile(std::string(SEASPRING_SOURCE_DIR) + "/tests/data/elastica/TipLoad2D_Def.xml");
    xml = test::replaceOnce(xml, "dp=\"DP\"", "dp=\"" + num(dp) + "\"");
    xml = test::replaceOnce(xml, "\"NU\"", "\"" + num(nu) + "\"");
    xml = test::replaceOnce(xml, "\"DAMPING\"", "\"" + num(damping) + "\"");
    xml = test::replaceOnce(xml, "z=\"Z1\" fz=\"HALF_LOAD\"", "z=\"" + num(z1) + "\" fz=\"" + num(-0.5 * load) + "\"");
    xml = test::replaceOnce(xml, "z=\"Z2\" fz=\"HALF_LOAD\"", "z=\"" + num(z2) + "\" fz=\"" + num(-0.5 * load) + "\"");
    const std::string tag = std::to_string(thick) + "_" + num(nu);
    const std::string dir = test::scratch("elastica_" + tag);
    const std::string kase = test::generateCase(dir, "tip", xml);
    const test::SolverRun r = test::runCpu(kase, dir + "/out", 2);
    Bent b;
    int loaded = 0;
    const auto& p0 = r.kase.particles;
    for (std::uint32_t i = 0; i < p0.size(); ++i) {
        if (p0.type[i] != ParticleType::Solid) continue;
        const auto& q = p0.pos[i];
        if (std::fabs(q.x - L) > 0.25 * dp) continue;
        if (std::fabs(q.z - z1) > 0.25 * dp && std::fabs(q.z - z2) > 0.25 * dp) continue;
        b.v += q.z - r.state.pos[i].z;
        b.u += q.x - r.state.pos[i].x;
        ++loaded;
    }
    EXPECT_EQ(loaded, 2);
    b.v /= 2 * arm;
    b.u /= 2 * arm;
    const ElasticaTip e = elasticaTip(alpha);
    std::printf("elastica, %d particles thick, nu %.2f, alpha %.1f: v/L %.5f (elastica %.5f, ratio %.4f), u/L %.5f "
                "(elastica %.5f, ratio %.4f)\n",
                thick, nu, alpha, b.v, e.v, b.v / e.v, b.u, e.u, b.u / e.u);
    return b;
}

/// The beam `thick` particles through at nu 0.3 and 0.49 under alpha 3: v and u within the
/// relative tolerances of the elastica's.
void expectElastica(int thick, double v_tol, double u_tol) {
    const ElasticaTip e = elasticaTip(3.0);
    for (double nu : {0.3, 0.49}) {
        const Bent b = settle(thick, nu, 3.0);
        EXPECT_NEAR(b.v / e.v, 1.0, v_tol) << thick << " particles, nu " << nu;
        EXPECT_NEAR(b.u / e.u, 1.0, u_tol) << thick << " particles, nu " << nu;
    }
}

}  // namespace

// The shooting solution reproduces the published table (Mattiasson 1981: alpha 1, 2, 5, 10).
TEST(SolidElastica, ShootingGivesThePublishedTable) {
    const double table[4][3] = {{1, 0.30172, 0.05643}, {2, 0.49346, 0.16064}, {5, 0.71379, 0.38763},
                                {10, 0.81061, 0.55500}};
    for (const auto& row : table) {
        const ElasticaTip e = elasticaTip(row[0]);
        EXPECT_NEAR(e.v, row[1], 1e-5) << "alpha " << row[0];
        EXPECT_NEAR(e.u, row[2], 1e-5) << "alpha " << row[0];
    }
}

// alpha = 3 (elastica: v/L 0.60325, u/L 0.25442). Measured (this VM, 2026-11-27): 4 particles
// thick, nu 0.3: v 1.015, u 1.030 of the elastica; nu 0.49: v 0.977, u 0.942; 8 particles:
// nu 0.3 v 0.999, u 0.993; nu 0.49 v 0.996, u 0.987 (docs/vcpm.md has alpha 0.2 to 5). Broken on
// purpose (4 particles): without the rows' bending v is 1.043 (nu 0.3), without the surface
// correction 1.108 and 0.921. In the linear regime (alpha
// 0.2) the 4-particle beam's deflection is 1.030 (nu 0.3) and 0.943 (nu 0.49) of Euler-Bernoulli,
// the static face of its first frequency's -1.6% and +3.1% (test_solid_cantilever.cpp); large
// rotations make the end's position less sensitive to the stiffness. Bars: v within 3% and u
// within 7% at 4 particles, v within 1% and u within 2% at 8.
TEST(SolidElastica, FourParticlesThickFollowTheElastica) { expectElastica(4, 0.03, 0.07); }

TEST(SolidElastica, EightParticlesThickFollowTheElastica) { expectElastica(8, 0.01, 0.02); }
