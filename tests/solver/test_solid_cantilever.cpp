// SeaSpring — MIT licence.
/// \file test_solid_cantilever.cpp
/// \brief VCPM solids in the solver (CPU backend, in-process): the 2D cantilever under a gravity
///        step load (first natural frequency and static deflection against Euler-Bernoulli and
///        Timoshenko), with and without the surface correction, the rows' bending and plane
///        stress, and the correction's factors and sub-step. The hanging beam and the breaking
///        bar: test_solid_solver.cpp. The case's README.md gives the measured numbers that the
///        tolerances come from.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "solver/solid_setup.h"
#include "solver/solid_stability.h"
#include "solver/solver_case.h"
#include "solver_test_util.h"

using namespace seaspring;

namespace {

using test::caseDef;
using test::scratch;

/// Oscillation of a sampled signal about its mean: the crossings of the mean (linear
/// interpolation) over a whole number of periods, T = 2 (last - first crossing) / (crossings - 1),
/// the mean taken between the first and the last of them (trapezoids; iterated from the plain
/// mean), and the peak-to-peak range of the first and the last period.
struct Oscillation {
    double frequency = 0, mean = 0, first_pp = 0, last_pp = 0;
    int crossings = 0;
};

Oscillation analyseOscillation(const std::vector<double>& t, const std::vector<double>& z) {
    Oscillation o;
    if (t.size() < 4) return o;
    double m = 0;
    for (double v : z) m += v;
    m /= double(z.size());
    std::vector<double> cr;
    for (int it = 0; it < 4; ++it) {
        cr.clear();
        for (std::size_t k = 0; k + 1 < t.size(); ++k) {
            const double a = z[k] - m, b = z[k + 1] - m;
            if (a == 0 || (a < 0) != (b < 0)) cr.push_back(t[k] + (t[k + 1] - t[k]) * a / (a - b));
        }
        if (cr.size() < 3) return o;
        cr.resize((cr.size() - 1) / 2 * 2 + 1);  // whole periods only: the mean of a part period is biased
        double integral = 0, t0 = -1, t1 = -1;
        for (std::size_t k = 0; k + 1 < t.size(); ++k) {
            if (t[k] < cr.front() || t[k + 1] > cr.back()) continue;
            if (t0 < 0) t0 = t[k];
            t1 = t[k + 1];
            integral += 0.5 * (z[k] + z[k + 1]) * (t[k + 1] - t[k]);
        }
        m = integral / (t1 - t0);
    }
    const double period = 2.0 * (cr.back() - cr.front()) / double(cr.size() - 1);
    o.frequency = 1.0 / period;
    o.mean = m;
    o.crossings = int(cr.size());
    auto range = [&](double a, double b) {
        double lo = 1e300, hi = -1e300;
        for (std::size_t k = 0; k < t.size(); ++k)
            if (t[k] >= a && t[k] <= b) {
                lo = std::min(lo, z[k]);
                hi = std::max(hi, z[k]);
            }
        return hi - lo;
    };
    o.first_pp = range(0.0, period);
    o.last_pp = range(t.back() - period, t.back());
    return o;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Cantilever 2D (plane strain) under a gravity step load of 1 m/s^2, no damping: the tip
//    oscillates about its static deflection. Euler-Bernoulli: f1 = 1.8751^2/(2 pi)
//    sqrt(E' I/(rho t L^4)) = 3.9365 Hz, delta = q L^4/(8 E' I) = 2.526 mm, E' = E/(1-nu^2).
// ---------------------------------------------------------------------------------------------

namespace {

struct CantileverResult {
    Oscillation osc;
    std::size_t broken_slots = 0;
    bool finite = true;
    std::uint32_t thickness = 0;  ///< particles through the thickness
};

/// `plane_stress`: the same beam with constitmodel="2" (physics::planeStressEquivalent);
/// `surface`: with VcpmSurfaceCorrection 1 (physics/vcpm_surface.h); `rows`: and the rows' bending
/// (physics/vcpm_rows.h, on by default with the correction; here only when asked).
CantileverResult runCantilever(double dp, bool plane_stress = false, bool surface = false, const char* nu = "0.3975",
                               bool rows = false) {
    const bool other_nu = std::string(nu) != "0.3975";
    const std::string dir = scratch("cl" + std::to_string(int(std::lround(dp * 1e5))) + (plane_stress ? "ps" : "") +
                                    (surface ? "sc" : "") + (rows ? "rows" : "") +
                                    (other_nu ? std::string("nu") + nu : std::string()));
    std::string def = test::readFile(caseDef("cantilever2d/Cantilever2D_Def.xml"));
    def = test::replaceOnce(def, "poissratio=\"0.3975\"",
                            std::string("poissratio=\"") + nu + "\"" + (plane_stress ? " constitmodel=\"2\"" : ""));
    def = test::replaceOnce(def, "<parameters>",
                            std::string("<parameters><parameter key=\"VcpmSurfaceCorrection\" value=\"") +
                                (surface ? "1" : "0") + "\" />" +
                                (surface ? std::string("<parameter key=\"VcpmRowBending\" value=\"") +
                                               (rows ? "1" : "0") + "\" />"
                                         : std::string()));
    const std::string kase = test::generateCase(dir, "cl", def, dp);
    const solver::SolverCase c = solver::loadSolverCase(kase);
    const std::uint32_t first = c.nfixed + c.nmoving, n = c.nsolid;
    const auto& p0 = c.particles.pos;
    double xmax = -1e300;
    for (std::uint32_t i = first; i < first + n; ++i) xmax = std::max(xmax, p0[i].x);
    std::vector<std::uint32_t> tip;
    for (std::uint32_t i = first; i < first + n; ++i)
        if (p0[i].x > xmax - 0.25 * dp) tip.push_back(i);
    CantileverResult res;
    res.thickness = std::uint32_t(tip.size());
    std::vector<double> ts, zs;
    const auto r = test::runCpu(kase, dir + "/out", 2, {}, [&](double t, long long, const solver::HostState& st) {
        double u = 0;
        for (std::uint32_t i : tip) u += st.pos[i].z - p0[i].z;
        ts.push_back(t);
        zs.push_back(u / double(tip.size()));
        for (std::uint32_t i = first; i < first + n; ++i) res.finite = res.finite && test::finite(st.pos[i]);
    });
    res.osc = analyseOscillation(ts, zs);
    res.broken_slots = test::brokenSlots(r.state);
    return res;
}

}  // namespace

TEST(SolidSolver, Cantilever2DFrequencyAndStaticDeflection) {
    const double E = 2e6, nu = 0.3975, rho = 1000, t = 0.02, L = 0.2, g = 1.0;
    const double Ep = E / (1 - nu * nu), I = t * t * t / 12;
    const double pi = std::acos(-1.0);
    const double f_eb = 1.8751 * 1.8751 / (2 * pi) * std::sqrt(Ep * I / (rho * t * std::pow(L, 4)));
    const double d_eb = rho * g * t * std::pow(L, 4) / (8 * Ep * I);
    // First-mode step response: omega1^2 delta_static = (1.8751^4 / 8) g, whatever the stiffness.
    const double w2d = std::pow(1.8751, 4) / 8 * g;
    const double dps[2] = {0.005, 0.0025};
    // Measured (README): f/f_EB - 1 = -13.5 % (4 particles thick), -6.7 % (8); delta/delta_EB - 1 =
    // +30.9 %, +13.4 %: first order in dp (the lattice's free surfaces are softer in bending).
    const double max_ferr[2] = {0.16, 0.08}, max_derr[2] = {0.36, 0.16};
    double ferr[2], derr[2];
    for (int k = 0; k < 2; ++k) {
        const CantileverResult c = runCantilever(dps[k]);
        const Oscillation& o = c.osc;
        ferr[k] = o.frequency / f_eb - 1;
        derr[k] = -o.mean / d_eb - 1;
        const double w = 2 * pi * o.frequency;
        std::printf("cantilever dp %.4f (%u thick): f %.4f Hz (EB %.4f, %+.2f %%), static %.4e m (EB %.4e, %+.2f %%), "
                    "omega^2 delta / (1.8751^4 g/8) = %.4f, crossings %d, peak-to-peak first %.4e last %.4e\n",
                    dps[k], c.thickness, o.frequency, f_eb, 100 * ferr[k], -o.mean, d_eb, 100 * derr[k],
                    w * w * -o.mean / w2d, o.crossings, o.first_pp, o.last_pp);
        ASSERT_GE(o.crossings, 5) << dps[k];
        EXPECT_TRUE(c.finite) << dps[k];
        EXPECT_EQ(c.broken_slots, 0u) << dps[k];
        // The lattice is softer than the beam: frequency below, deflection above.
        EXPECT_LT(ferr[k], 0.0) << dps[k];
        EXPECT_GT(ferr[k], -max_ferr[k]) << dps[k];
        EXPECT_GT(derr[k], 0.0) << dps[k];
        EXPECT_LT(derr[k], max_derr[k]) << dps[k];
        // Frequency and deflection of one run are consistent with one stiffness (measured 0.979, 0.987).
        EXPECT_NEAR(w * w * -o.mean / w2d, 1.0, 0.04) << dps[k];
        // No damping: the oscillation keeps its amplitude (measured within 0.1 % over 3 periods).
        EXPECT_NEAR(o.last_pp / o.first_pp, 1.0, 0.01) << dps[k];
    }
    // Refinement halves the errors (first order; measured ratios 0.50 and 0.43).
    EXPECT_GT(ferr[1] / ferr[0], 0.3);
    EXPECT_LT(ferr[1] / ferr[0], 0.65);
    EXPECT_GT(derr[1] / derr[0], 0.3);
    EXPECT_LT(derr[1] / derr[0], 0.65);
}

// The surface correction's factors (physics/vcpm_surface.h) on the 2D cantilever, 4 particles
// thick: 1 exactly for a bond between two complete sites, the same on both slots of a bond,
// above 1 along the top and bottom rows (their sites lack bonds), never below 1.
TEST(SolidSolver, SurfaceCorrectionFactorsAreSymmetricAndOneInside) {
    const std::string dir = scratch("sc_factors");
    std::string def = test::readFile(caseDef("cantilever2d/Cantilever2D_Def.xml"));
    def = test::replaceOnce(def, "<parameters>", "<parameters><parameter key=\"VcpmSurfaceCorrection\" value=\"1\" />");
    const solver::SolverCase c = solver::loadSolverCase(test::generateCase(dir, "cl", def, 0.005));
    const solver::SolidSetup s = solver::makeSolidSetup(c);
    ASSERT_EQ(s.kfac.size(), s.rest.size());
    std::size_t above = 0, inside = 0;
    for (std::uint32_t r = 0; r < s.nsolid; ++r)
        for (int q = 0; q < s.count[r]; ++q) {
            const std::size_t k = std::size_t(q) * s.nsolid + r;
            EXPECT_GE(s.kfac[k], 1.0);
            if (s.flags[k] & physics::kBondClamp) continue;
            const std::uint32_t j = s.partner[k];
            if (s.count[r] == s.max_bonds && s.count[j] == s.max_bonds) {
                EXPECT_EQ(s.kfac[k], 1.0);
                ++inside;
            }
            above += s.kfac[k] > 1.0;
            bool mirrored = false;
            for (int p = 0; p < s.count[j]; ++p) {
                const std::size_t m = std::size_t(p) * s.nsolid + j;
                if (!(s.flags[m] & physics::kBondClamp) && s.partner[m] == r) {
                    EXPECT_EQ(s.kfac[m], s.kfac[k]) << r << " - " << j;
                    mirrored = true;
                }
            }
            EXPECT_TRUE(mirrored);
        }
    EXPECT_GT(inside, 0u);
    EXPECT_GT(above, 0u);
    // A top-row bond along the beam: its sites miss a third of their bonds.
    double top = -1e300;
    for (std::uint32_t r = 0; r < s.nsolid; ++r) top = std::max(top, s.pos[r].z);
    double g_top = 0;
    for (std::uint32_t r = 0; r < s.nsolid; ++r)
        for (int q = 0; q < s.count[r]; ++q) {
            const std::size_t k = std::size_t(q) * s.nsolid + r;
            if ((s.flags[k] & (physics::kBondClamp | physics::kBondSecond)) || s.pos[r].z < top - 1e-9) continue;
            if (std::fabs(s.pos[s.partner[k]].z - top) < 1e-9 && s.pos[r].x > 0.05 && s.pos[r].x < 0.15) g_top = s.kfac[k];
        }
    std::printf("surface correction: top-row bond factor %.4f\n", g_top);
    EXPECT_GT(g_top, 1.1);
    EXPECT_LT(g_top, 2.0);
}

// The corrected lattice's sub-step (solver::correctedSubStepScales): a beam 4 particles thick
// at nu 0.49 (its surface sites stiffened by the weights and springs, its clamp bonds doubled)
// gets a factor below 1 (measured 0.702) and exactly the scaled elastic sub-step; the plain
// lattice keeps 1. A lattice made stiffer (every spring factor x 4) needs a smaller factor
// (measured 0.654: at nu 0.49 the volumetric term dominates the bound). Broken on
// purpose (the factor forced to 1), the Antoci gate at its coarse resolution blows up at
// t = 0.2 s in validation_coarse (docs/vcpm.md).
TEST(SolidSolver, SurfaceCorrectionScalesTheSubStepToTheStiffestSite) {
    std::string def = test::readFile(caseDef("cantilever2d/Cantilever2D_Def.xml"));
    def = test::replaceOnce(def, "poissratio=\"0.3975\"", "poissratio=\"0.49\"");
    // Gershgorin's factor of the correction alone (the rows' bending, on by default, takes the
    // eigenvalue factor: SolidStability.RowBendingIsInBothSubStepFactors).
    def = test::replaceOnce(def, "<parameters>", "<parameters><parameter key=\"VcpmRowBending\" value=\"0\" />");
    const solver::SolidSetup plain = solver::makeSolidSetup(solver::loadSolverCase(test::generateCase(
        scratch("dtscale0"), "cl",
        test::replaceOnce(def, "<parameters>", "<parameters><parameter key=\"VcpmSurfaceCorrection\" value=\"0\" />"),
        0.005)));
    solver::SolidSetup s = solver::makeSolidSetup(solver::loadSolverCase(test::generateCase(scratch("dtscale1"), "cl", def, 0.005)));
    ASSERT_EQ(plain.dt_scale.size(), 1u);
    ASSERT_EQ(s.dt_scale.size(), 1u);
    EXPECT_EQ(plain.dt_scale[0], 1.0);
    EXPECT_EQ(plain.dt, plain.elastic_dt[0]);
    const double f = s.dt_scale[0];
    std::printf("corrected sub-step factor, nu 0.49, 4 particles thick: %.4f\n", f);
    EXPECT_GT(f, 0.3);
    EXPECT_LT(f, 1.0);
    EXPECT_EQ(s.dt, s.elastic_dt[0] * f);
    for (double& k : s.kfac) k *= 4.0;
    const double f4 = solver::correctedSubStepScales(s, 0)[0];
    std::printf("with every spring x 4: %.4f\n", f4);
    EXPECT_LT(f4, f);
}

namespace {

/// The corrected 2D cantilever (L/t = 10, plane strain) 4 and 8 particles thick, with or
/// without the rows' bending: its first frequency within bound4 / bound8 of Timoshenko's
/// (`timoshenko_over_eb` x Euler-Bernoulli's at this nu).
void expectCantileverNearTimoshenko(const char* nu_text, double timoshenko_over_eb, bool rows, double bound4,
                                    double bound8, bool plane_stress = false) {
    const double E = 2e6, rho = 1000, t = 0.02, L = 0.2, pi = std::acos(-1.0);
    const double nu = std::stod(nu_text);
    const double Ep = plane_stress ? E : E / (1 - nu * nu), I = t * t * t / 12;
    const double f_t = timoshenko_over_eb * 1.8751 * 1.8751 / (2 * pi) * std::sqrt(Ep * I / (rho * t * std::pow(L, 4)));
    const double dps[2] = {0.005, 0.0025};
    for (int k = 0; k < 2; ++k) {
        const CantileverResult c = runCantilever(dps[k], plane_stress, true, nu_text, rows);
        ASSERT_GE(c.osc.crossings, 5) << dps[k];
        EXPECT_TRUE(c.finite) << dps[k];
        const double err = c.osc.frequency / f_t - 1;
        std::printf("%s, %s, nu %s, dp %.4f (%u thick): f %.4f Hz, Timoshenko %.4f Hz: %+.2f %%\n",
                    rows ? "rows' bending" : "surface correction", plane_stress ? "plane stress" : "plane strain",
                    nu_text, dps[k], c.thickness, c.osc.frequency, f_t, 100 * err);
        EXPECT_LT(std::fabs(err), k == 0 ? bound4 : bound8) << nu_text << " dp " << dps[k];
    }
}

}  // namespace

// The surface correction (VcpmSurfaceCorrection 1, physics/vcpm_surface.h: spring factors,
// volumetric weights, clamp bonds) on the same beam (L/t = 10) against Timoshenko's first
// frequency (a converged Timoshenko finite-element beam with Cowper's shear factor, plane
// strain: 0.9907 x Euler-Bernoulli's at nu = 0.3975, 0.9894 at nu = 0.49; docs/vcpm.md).
// Measured, 4 / 8 particles thick: nu 0.3975 -4.84 % / -0.47 % (the plain lattice -13.5 % /
// -6.7 %); nu 0.49 -1.87 % / -0.26 % (the plain lattice +9.0 % / +3.8 %: too stiff). Checked:
// nu 0.49 within 3 % and 1 % (issue 13 asks 4 % at 4 particles and 2 % at 8), nu 0.3975
// within 5.5 % and 1 %. Broken on purpose, each fails: the spring factors' reference state
// set to uniaxial strain (+9.9 % / +11.7 % at nu 0.3975, before the weights); the volumetric
// weights left out (nu 0.49 +9.9 % / +4.2 %); the face sites' alpha_I = alpha rule left out
// (free alpha_I everywhere: nu 0.49 -3.43 % at 4); the clamp bonds' factor 1 in place of 2.
TEST(SolidSolver, Cantilever2DSurfaceCorrectionMeetsTimoshenko) {
    expectCantileverNearTimoshenko("0.3975", 0.9907, false, 0.055, 0.01);
    expectCantileverNearTimoshenko("0.49", 0.9894, false, 0.03, 0.01);
}

// The rows' own bending (VcpmRowBending 1, physics/vcpm_rows.h) on top of the surface
// correction, on the same beam against the same Timoshenko frequencies (0.9917 x Euler-Bernoulli
// at nu = 0.3): issue 13's bars, within 4% at 4 particles through the thickness and 2% at 8,
// for nu 0.3, 0.3975 and 0.49. Measured, 4 / 8 thick: nu 0.3 -1.60% / +0.45%, nu 0.3975 -1.04% /
// +0.61%, nu 0.49 +3.11% / +1.23% (without the rows: -4.92% / -0.45%, -4.83% / -0.46%,
// -1.86% / -0.26%: the first two miss the 4% bar). At 2 particles thick (not checked) nu 0.3975
// goes from -18.95% to -7.10%. Broken on purpose (k_r = E_u/6 in place of E_u/12): this fails
// (nu 0.49 +7.73% / +2.68%). The force's own form is VcpmSurface.RowBendingForceIsMinusEnergyGradient's.
TEST(SolidSolver, Cantilever2DRowBendingMeetsTheIssueBars) {
    expectCantileverNearTimoshenko("0.3", 0.9917, true, 0.04, 0.02);
    expectCantileverNearTimoshenko("0.3975", 0.9907, true, 0.04, 0.02);
    expectCantileverNearTimoshenko("0.49", 0.9894, true, 0.04, 0.02);
}

// The same bars for the plane-stress sheet (constitmodel 2: E in place of E/(1-nu^2) in the beam,
// the same G), against its Timoshenko frequency (the same beam elements and Cowper factor: 0.9923
// x Euler-Bernoulli at nu 0.3, 0.9915 at nu 0.49). Without the rows' bending the sheet is -4.34% /
// -5.00% at 4 particles (docs/vcpm.md); measured with them, 4 / 8 thick: nu 0.3 -1.17% / +0.52%,
// nu 0.49 -1.59% / +0.47%. Broken on purpose (nu 0.3 without the rows): fails at -4.35%.
TEST(SolidSolver, Cantilever2DPlaneStressRowBendingMeetsTheIssueBars) {
    expectCantileverNearTimoshenko("0.3", 0.9923, true, 0.04, 0.02, true);
    expectCantileverNearTimoshenko("0.49", 0.9915, true, 0.04, 0.02, true);
}

// The same beam as a plane-stress sheet (constitmodel 2): Euler-Bernoulli with E instead of
// E/(1-nu^2), i.e. a frequency sqrt(1-nu^2) = 0.918 times and a static deflection 1/(1-nu^2) =
// 1.188 times the plane-strain beam's. At 4 particles through the thickness the lattice's own
// error (first order in dp) comes on top, as for plane strain; the plane-stress over plane-strain
// ratios are checked within 2% (measured: see the printout). Broken on purpose (the mapping's
// nu' = nu/(1-nu)): the ratios fail.
TEST(SolidSolver, Cantilever2DPlaneStressIsTheSheetBeam) {
    const double E = 2e6, nu = 0.3975, rho = 1000, t = 0.02, L = 0.2, g = 1.0, dp = 0.005;
    const double I = t * t * t / 12, pi = std::acos(-1.0);
    const double f_eb = 1.8751 * 1.8751 / (2 * pi) * std::sqrt(E * I / (rho * t * std::pow(L, 4)));
    const CantileverResult ps = runCantilever(dp, true), pe = runCantilever(dp);
    ASSERT_GE(ps.osc.crossings, 5);
    ASSERT_GE(pe.osc.crossings, 5);
    const double fr = ps.osc.frequency / pe.osc.frequency, dr = ps.osc.mean / pe.osc.mean;
    std::printf("plane stress dp %.4f: f %.4f Hz (EB with E %.4f, %+.2f %%); f_ps/f_pe %.4f (sqrt(1-nu^2) %.4f), "
                "delta_ps/delta_pe %.4f (1/(1-nu^2) %.4f)\n",
                dp, ps.osc.frequency, f_eb, 100 * (ps.osc.frequency / f_eb - 1), fr, std::sqrt(1 - nu * nu), dr,
                1 / (1 - nu * nu));
    EXPECT_TRUE(ps.finite);
    EXPECT_NEAR(fr / std::sqrt(1 - nu * nu), 1.0, 0.02);
    EXPECT_NEAR(dr * (1 - nu * nu), 1.0, 0.02);
    EXPECT_LT(ps.osc.frequency / f_eb - 1, 0.0);  // the lattice is softer, as in plane strain
    EXPECT_GT(ps.osc.frequency / f_eb - 1, -0.16);
    (void)g;
}

