// SeaSpring — MIT licence.
/// \file test_solid_solver.cpp
/// \brief VCPM solids in the solver (CPU backend, in-process), against analytic solutions:
///        the hanging beam under self-weight (resolution series and observed order), the breaking
///        bar (breakage at the support, free fall, a control that never breaks, thread-count
///        parity). The 2D cantilever: test_solid_cantilever.cpp. Coupled runs:
///        test_solid_coupling.cpp.
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
// 2. Breaking bar: a 2D bar hanging from a clamp plate, released under gravity with no damping;
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
// 3. Thread-count parity with bonds breaking: the breaking bar (solid only); a different
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
