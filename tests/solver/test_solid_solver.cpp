// SeaSpring — MIT licence.
/// \file test_solid_solver.cpp
/// \brief VCPM solids in the solver (CPU backend, in-process), against analytic solutions:
///        the hanging beam under self-weight (resolution series and observed order), the 2D
///        cantilever under a gravity step load (first natural frequency and static deflection
///        against Euler-Bernoulli), the breaking bar (breakage at the support, free fall, a
///        control that never breaks, thread-count parity). Coupled runs: test_solid_coupling.cpp.
///        The cases' README.md files give the measured numbers that the tolerances come from.
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

using test::brokenSlots;
using test::caseDef;
using test::dist;
using test::finite;
using test::readFile;
using test::replaceOnce;
using test::scratch;

/// Particle id of the partner of bond slot k (solid or clamp node).
std::uint32_t partnerId(const solver::SolidSetup& so, std::size_t k) {
    return (so.flags[k] & physics::kBondClamp) ? so.clamp_id[so.partner[k]] : so.first_solid + so.partner[k];
}

/// Largest relative stretch (|r| - L0)/L0 over the intact bonds of the solid particles in `which`
/// (all when empty).
double maxStretch(const solver::SolidSetup& so, const solver::HostState& st, const std::vector<char>& which = {}) {
    double m = -1e300;
    for (std::uint32_t s = 0; s < so.nsolid; ++s) {
        if (!which.empty() && !which[s]) continue;
        for (int q = 0; q < so.count[s]; ++q) {
            const std::size_t k = std::size_t(q) * so.nsolid + s;
            if (st.bond_broken[k]) continue;
            m = std::max(m, (dist(st.pos[so.first_solid + s], st.pos[partnerId(so, k)]) - so.rest[k]) / so.rest[k]);
        }
    }
    return m;
}

/// Solid particles still connected to a clamp node through intact bonds (1) or detached (0).
std::vector<char> attachedToClamp(const solver::SolidSetup& so, const std::vector<std::uint8_t>& broken) {
    const std::uint32_t n = so.nsolid;
    std::vector<char> att(n, 0);
    std::vector<std::uint32_t> stack;
    for (std::uint32_t s = 0; s < n; ++s)
        for (int q = 0; q < so.count[s]; ++q) {
            const std::size_t k = std::size_t(q) * n + s;
            if ((so.flags[k] & physics::kBondClamp) && !broken[k] && !att[s]) {
                att[s] = 1;
                stack.push_back(s);
            }
        }
    while (!stack.empty()) {
        const std::uint32_t s = stack.back();
        stack.pop_back();
        for (int q = 0; q < so.count[s]; ++q) {
            const std::size_t k = std::size_t(q) * n + s;
            if (broken[k] || (so.flags[k] & physics::kBondClamp)) continue;
            const std::uint32_t j = so.partner[k];
            if (!att[j]) {
                att[j] = 1;
                stack.push_back(j);
            }
        }
    }
    return att;
}

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
// 1. Hanging beam (seed paper 000 §3.1): 0.1 x 0.1 x 0.6 m, rho 2500, E 3 MPa, nu 0.3, damped
//    to its static state in 5 s. Free-end displacement of the 1D bar rho g L^2/(2E) = 1.4715 mm;
//    the clamped lattice converges to it from above (the paper's Fig. 5: order 1 to 2). This is
//    the seed paper's plain lattice (VcpmSurfaceCorrection 0). With the surface correction (the
//    default) the ratios are 0.955 (dp 0.02) and 0.972 (dp 0.01): below 1, because the 1D bar
//    ignores the rigid clamp's lateral constraint (the lattice's clamp bonds now end at the
//    clamp's face), which stiffens a 0.1 m wide bar near its top; the bar formula is then not
//    the limit, so that run is not held to it here (docs/vcpm.md).
// ---------------------------------------------------------------------------------------------

namespace {

struct BeamResult {
    double tip = 0;          ///< mean axial displacement of the bottom layer at the end [m] (< 0)
    double tip_before = 0;   ///< the same 0.5 s before the end
    double max_antisym = 0;  ///< largest |u_x(x) + u_x(mirror x)|, |u_y(y) + u_y(mirror y)| [m]
    double max_sym = 0;      ///< largest |u_z(x) - u_z(mirror x)| (same for y) [m]
    double clamp_moved = 0;  ///< largest displacement of a fixed boundary particle [m]
    std::uint64_t broken = 0;
    std::size_t broken_slots = 0;
    bool finite = true;
};

BeamResult runHangingBeam(double dp) {
    const std::string tag = "hb" + std::to_string(int(std::lround(dp * 1e4)));
    const std::string dir = scratch(tag);
    // The seed paper's plain lattice (VcpmSurfaceCorrection 0; see the test below).
    const std::string def = test::replaceOnce(test::readFile(caseDef("hanging_beam/HangingBeam_Def.xml")), "<parameters>",
                                              "<parameters><parameter key=\"VcpmSurfaceCorrection\" value=\"0\" />");
    const std::string kase = test::generateCase(dir, "hb", def, dp);
    const solver::SolverCase c = solver::loadSolverCase(kase);
    const std::uint32_t first = c.nfixed + c.nmoving, n = c.nsolid;
    const auto& p0 = c.particles.pos;
    double zmin = 1e300;
    for (std::uint32_t i = first; i < first + n; ++i) zmin = std::min(zmin, p0[i].z);
    std::vector<std::uint32_t> bottom;
    for (std::uint32_t i = first; i < first + n; ++i)
        if (p0[i].z < zmin + 0.25 * dp) bottom.push_back(i);
    auto tipOf = [&](const solver::HostState& st) {
        double u = 0;
        for (std::uint32_t i : bottom) u += st.pos[i].z - p0[i].z;
        return u / double(bottom.size());
    };
    BeamResult res;
    std::vector<double> history;  // the tip at every output (TimeOut 0.5 s)
    const auto r = test::runCpu(kase, dir + "/out", 2, {}, [&](double, long long, const solver::HostState& st) {
        history.push_back(tipOf(st));
    });
    const solver::HostState& st = r.state;
    res.tip = tipOf(st);
    EXPECT_GE(history.size(), 3u);
    if (history.size() >= 2) res.tip_before = history[history.size() - 2];
    res.broken = r.summary.broken_bonds;
    res.broken_slots = brokenSlots(st);
    for (std::uint32_t i = 0; i < c.nfixed; ++i) res.clamp_moved = std::max(res.clamp_moved, dist(st.pos[i], {p0[i].x, p0[i].y, p0[i].z}));
    // Mirror pairs of lattice sites about the beam's axis (x and y).
    std::map<std::tuple<long, long, long>, std::uint32_t> site;
    long imin = 1L << 40, imax = -(1L << 40), jmin = imin, jmax = imax;
    for (std::uint32_t i = first; i < first + n; ++i) {
        const long a = std::lround(p0[i].x / dp), b = std::lround(p0[i].y / dp), k = std::lround(p0[i].z / dp);
        site[{a, b, k}] = i;
        imin = std::min(imin, a);
        imax = std::max(imax, a);
        jmin = std::min(jmin, b);
        jmax = std::max(jmax, b);
        res.finite = res.finite && finite(st.pos[i]);
    }
    for (const auto& [key, i] : site) {
        const auto [a, b, k] = key;
        const auto mx = site.find({imin + imax - a, b, k});
        const auto my = site.find({a, jmin + jmax - b, k});
        EXPECT_TRUE(mx != site.end() && my != site.end()) << "no mirror site for particle " << i;
        if (mx == site.end() || my == site.end()) continue;
        const std::uint32_t ix = mx->second, iy = my->second;
        const double ux = st.pos[i].x - p0[i].x, uxm = st.pos[ix].x - p0[ix].x;
        const double uy = st.pos[i].y - p0[i].y, uym = st.pos[iy].y - p0[iy].y;
        const double uz = st.pos[i].z - p0[i].z;
        res.max_antisym = std::max({res.max_antisym, std::fabs(ux + uxm), std::fabs(uy + uym)});
        res.max_sym = std::max({res.max_sym, std::fabs(uz - (st.pos[ix].z - p0[ix].z)),
                                std::fabs(uz - (st.pos[iy].z - p0[iy].z))});
    }
    return res;
}

}  // namespace

TEST(SolidSolver, HangingBeamConvergesToTheBarSolution) {
    const double analytic = 2500.0 * 9.81 * 0.6 * 0.6 / (2.0 * 3e6);  // 1.4715e-3 m
    const double dps[2] = {0.02, 0.01};
    double err[2];
    for (int k = 0; k < 2; ++k) {
        const BeamResult b = runHangingBeam(dps[k]);
        const double ratio = -b.tip / analytic;
        err[k] = ratio - 1.0;
        std::printf("hanging beam dp %.3f: free-end displacement %.6e m, / analytic = %.4f (0.5 s earlier %.4f); "
                    "symmetry: antisym %.2e m, sym %.2e m\n",
                    dps[k], -b.tip, ratio, -b.tip_before / analytic, b.max_antisym, b.max_sym);
        // Measured 1.168 (dp 0.02) and 1.075 (dp 0.01): converging from above.
        EXPECT_GT(ratio, 0.98) << dps[k];
        EXPECT_LT(ratio, 1.25) << dps[k];
        // Settled: the last 0.5 s changed the displacement by less than 0.1 % (measured 3e-5 at dp 0.01).
        EXPECT_LT(std::fabs(b.tip - b.tip_before), 1e-3 * std::fabs(b.tip)) << dps[k];
        EXPECT_EQ(b.broken, 0u) << dps[k];
        EXPECT_EQ(b.broken_slots, 0u) << dps[k];
        EXPECT_TRUE(b.finite) << dps[k];
        // The clamp plate (fixed boundary) does not move at all.
        EXPECT_EQ(b.clamp_moved, 0.0) << dps[k];
        // Lateral symmetry about the beam's axis: the lattice and the clamp bonds are symmetric and
        // only the summation order differs between mirror particles (measured 3e-16 m).
        EXPECT_LT(b.max_antisym, 1e-12) << dps[k];
        EXPECT_LT(b.max_sym, 1e-12) << dps[k];
    }
    EXPECT_LT(std::fabs(err[1]), std::fabs(err[0]));
    const double order = std::log(err[0] / err[1]) / std::log(dps[0] / dps[1]);
    std::printf("hanging beam: observed order %.3f\n", order);
    EXPECT_GT(order, 0.8);
    EXPECT_LT(order, 2.5);
}

// ---------------------------------------------------------------------------------------------
// 2. Cantilever 2D (plane strain) under a gravity step load of 1 m/s^2, no damping: the tip
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
/// `surface`: with VcpmSurfaceCorrection 1 (physics/vcpm_surface.h).
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
                                (rows ? "<parameter key=\"VcpmRowBending\" value=\"1\" />" : ""));
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
        for (std::uint32_t i = first; i < first + n; ++i) res.finite = res.finite && finite(st.pos[i]);
    });
    res.osc = analyseOscillation(ts, zs);
    res.broken_slots = brokenSlots(r.state);
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
                                    double bound8) {
    const double E = 2e6, rho = 1000, t = 0.02, L = 0.2, pi = std::acos(-1.0);
    const double nu = std::stod(nu_text);
    const double Ep = E / (1 - nu * nu), I = t * t * t / 12;
    const double f_t = timoshenko_over_eb * 1.8751 * 1.8751 / (2 * pi) * std::sqrt(Ep * I / (rho * t * std::pow(L, 4)));
    const double dps[2] = {0.005, 0.0025};
    for (int k = 0; k < 2; ++k) {
        const CantileverResult c = runCantilever(dps[k], false, true, nu_text, rows);
        ASSERT_GE(c.osc.crossings, 5) << dps[k];
        EXPECT_TRUE(c.finite) << dps[k];
        const double err = c.osc.frequency / f_t - 1;
        std::printf("%s, nu %s, dp %.4f (%u thick): f %.4f Hz, Timoshenko %.4f Hz: %+.2f %%\n",
                    rows ? "rows' bending" : "surface correction", nu_text, dps[k], c.thickness, c.osc.frequency, f_t,
                    100 * err);
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

// ---------------------------------------------------------------------------------------------
// 3. Breaking bar: a 2D bar hanging from a clamp plate, released under gravity with no damping;
//    critstretch 0.012 lies between the static stretch at mid-length (0.0089) and at the
//    support (0.0179). Bonds break at the support first, the bar detaches and falls freely.
// ---------------------------------------------------------------------------------------------

namespace {

struct BarHistory {
    double t_first_break = -1;   ///< first output with a broken bond
    std::size_t first_broken = 0;
    std::size_t first_not_near_clamp = 0;  ///< of those, bonds with no end in the top row
    double t_detach = -1;        ///< first output with detached particles
    std::vector<char> detached;  ///< the detached set then
    double vz_detach = 0;        ///< its mean vertical velocity then
    double t_end = 0, vz_end = 0;
    std::size_t ndetached_end = 0;
    double max_stretch_top = -1e300;  ///< largest stretch of intact bonds of the top row
    bool finite = true;
};

BarHistory observeBar(const solver::SolverCase& c, const solver::SolidSetup& so, const std::string& kase,
                      const std::string& outdir, int threads, solver::RunSummary* summary = nullptr) {
    const std::uint32_t n = so.nsolid, first = so.first_solid;
    const auto& p0 = c.particles.pos;
    const double dp = c.constants.dp;
    double zmax = -1e300;
    for (std::uint32_t s = 0; s < n; ++s) zmax = std::max(zmax, p0[first + s].z);
    std::vector<char> top(n, 0);
    for (std::uint32_t s = 0; s < n; ++s) top[s] = p0[first + s].z > zmax - 0.25 * dp;
    auto nearClamp = [&](std::uint32_t s, std::size_t k) {
        if (so.flags[k] & physics::kBondClamp) return true;
        return bool(top[s] || top[so.partner[k]]);
    };
    auto meanVz = [&](const solver::HostState& st, const std::vector<char>& set) {
        double v = 0;
        std::size_t m = 0;
        for (std::uint32_t s = 0; s < n; ++s)
            if (set[s]) {
                v += st.solid_vel[s].z;
                ++m;
            }
        return v / double(m);
    };
    BarHistory h;
    // An output at every sub-step (TimeOut below the sub-step), so that the first broken bonds are
    // seen in the sub-step that breaks them.
    auto every_step = [](solver::RunOptions& o) { o.tout = 1e-4; };
    const auto r = test::runCpu(kase, outdir, threads, every_step, [&](double t, long long, const solver::HostState& st) {
        for (std::uint32_t s = 0; s < n; ++s) h.finite = h.finite && finite(st.pos[first + s]) && finite(st.solid_vel[s]);
        h.max_stretch_top = std::max(h.max_stretch_top, maxStretch(so, st, top));
        const std::size_t nb = brokenSlots(st);
        if (nb > 0 && h.t_first_break < 0) {
            h.t_first_break = t;
            h.first_broken = nb;
            for (std::uint32_t s = 0; s < n; ++s)
                for (int q = 0; q < so.count[s]; ++q) {
                    const std::size_t k = std::size_t(q) * n + s;
                    if (st.bond_broken[k] && !nearClamp(s, k)) ++h.first_not_near_clamp;
                }
        }
        if (nb > 0) {
            std::vector<char> det = attachedToClamp(so, st.bond_broken);
            std::size_t nd = 0;
            for (char& a : det) {
                a = !a;
                nd += a;
            }
            if (nd > 0 && h.t_detach < 0) {
                h.t_detach = t;
                h.detached = det;
                h.vz_detach = meanVz(st, det);
            }
            h.ndetached_end = nd;
        }
        if (h.t_detach >= 0) {
            h.t_end = t;
            h.vz_end = meanVz(st, h.detached);
        }
    });
    if (summary) *summary = r.summary;
    return h;
}

}  // namespace

TEST(SolidSolver, BreakingBarBreaksAtTheSupportAndFallsFreely) {
    const std::string dir = scratch("bar");
    const std::string kase = test::generateCaseFile(dir, "bar", caseDef("breaking_bar/BreakingBar_Def.xml"));
    const solver::SolverCase c = solver::loadSolverCase(kase);
    const solver::SolidSetup so = solver::makeSolidSetup(c);
    ASSERT_EQ(so.nsolid, 240u);
    ASSERT_EQ(so.materials.size(), 1u);
    const double crit = so.materials[0].crit_stretch;
    ASSERT_EQ(crit, 0.012);
    solver::RunSummary sum;
    const BarHistory h = observeBar(c, so, kase, dir + "/out", 2, &sum);
    std::printf("breaking bar: first break at t = %.4f s (%zu slots, %zu not at the top row), detached at t = %.4f s "
                "(%zu of %u particles at the end), broken bonds %llu; free fall from %.4f to %.4f s: a = %.9f m/s^2\n",
                h.t_first_break, h.first_broken, h.first_not_near_clamp, h.t_detach, h.ndetached_end, so.nsolid,
                (unsigned long long)sum.broken_bonds, h.t_detach, h.t_end,
                (h.vz_end - h.vz_detach) / (h.t_end - h.t_detach));
    EXPECT_GT(sum.broken_bonds, 0u);
    EXPECT_EQ(sum.excluded_not_finite, 0u);
    EXPECT_TRUE(h.finite);
    // The first bonds to break are at the support: clamp bonds or bonds of the top row.
    ASSERT_GT(h.t_first_break, 0.0);
    EXPECT_GT(h.first_broken, 0u);
    EXPECT_EQ(h.first_not_near_clamp, 0u);
    // The undamped step load reaches crit at the support at t = crit c / g ~ 13 ms (c = 10.5 m/s,
    // plane-strain bar speed); measured first break at 13.8 ms.
    EXPECT_GT(h.t_first_break, 0.008);
    EXPECT_LT(h.t_first_break, 0.020);
    // The bar detaches (measured: 232 of 240 particles at t = 37 ms; the top row stays on the
    // clamp) and the detached part falls freely: its momentum changes only by its weight.
    ASSERT_GT(h.t_detach, 0.0);
    EXPECT_GE(h.ndetached_end, std::size_t(0.9 * so.nsolid));
    ASSERT_GT(h.t_end - h.t_detach, 0.05);
    const double a = (h.vz_end - h.vz_detach) / (h.t_end - h.t_detach);
    EXPECT_NEAR(a / -9.81, 1.0, 0.02);
}

TEST(SolidSolver, BreakingBarControlWithoutBreakageBreaksNothing) {
    const std::string dir = scratch("bar0");
    const std::string xml = replaceOnce(readFile(caseDef("breaking_bar/BreakingBar_Def.xml")), R"(critstretch="0.012")",
                                        R"(critstretch="0")");
    const std::string kase = test::generateCase(dir, "bar", xml);
    const solver::SolverCase c = solver::loadSolverCase(kase);
    const solver::SolidSetup so = solver::makeSolidSetup(c);
    ASSERT_EQ(so.materials[0].crit_stretch, 0.0);
    solver::RunSummary sum;
    const BarHistory h = observeBar(c, so, kase, dir + "/out", 2, &sum);
    std::printf("breaking bar control (critstretch 0): broken %llu, largest stretch at the top row %.4f\n",
                (unsigned long long)sum.broken_bonds, h.max_stretch_top);
    EXPECT_EQ(sum.broken_bonds, 0u);
    EXPECT_LT(h.t_first_break, 0.0);
    EXPECT_LT(h.t_detach, 0.0);
    EXPECT_TRUE(h.finite);
    // The stretch at the support does exceed 0.012 (so the breaking run breaks by the criterion):
    // the undamped step load doubles the static support stretch rho g L (1 - nu^2)/E = 0.01785
    // (measured largest 0.0361 = 1.011 x 2 x static).
    EXPECT_GT(h.max_stretch_top, 0.012);
    EXPECT_NEAR(h.max_stretch_top / (2 * 1000 * 9.81 * 0.2 * (1 - 0.09) / 1e5), 1.0, 0.1);
}

// ---------------------------------------------------------------------------------------------
// 4. Thread-count parity with bonds breaking: the breaking bar (solid only); a different
//    critstretch changes the hash. The coupled counterpart is in test_solid_coupling.cpp.
// ---------------------------------------------------------------------------------------------

TEST(SolidSolver, ThreadCountsGiveIdenticalHashesWithBreakage) {
    const std::string dir = scratch("parity_bar");
    const std::string kase = test::generateCaseFile(dir, "bar", caseDef("breaking_bar/BreakingBar_Def.xml"));
    const auto r1 = test::runCpu(kase, dir + "/out1", 1);
    const auto r2 = test::runCpu(kase, dir + "/out2", 2);
    EXPECT_GT(r1.summary.broken_bonds, 0u);
    EXPECT_EQ(r1.summary.broken_bonds, r2.summary.broken_bonds);
    EXPECT_EQ(r1.state.bond_broken, r2.state.bond_broken);
    EXPECT_EQ(r1.summary.state_hash, r2.summary.state_hash);
    const std::string xml = replaceOnce(readFile(caseDef("breaking_bar/BreakingBar_Def.xml")),
                                        R"(critstretch="0.012")", R"(critstretch="0.013")");
    const std::string kase3 = test::generateCase(dir + "/c13", "bar", xml);
    const auto r3 = test::runCpu(kase3, dir + "/out3", 2);
    EXPECT_NE(r3.summary.state_hash, r1.summary.state_hash);
}
