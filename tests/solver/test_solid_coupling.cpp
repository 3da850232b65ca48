// SeaSpring — MIT licence.
/// \file test_solid_coupling.cpp
/// \brief The fluid-solid coupling of VCPM solids (CPU backend, in-process), on the hydrostatic
///        plate (cases/hydrostatic_plate, dp 0.025: the plate is 2 particles thick): the
///        hydrodynamic force carries the weight of the water; the plate stays near its static
///        deflection (VcpmCoupling 2); thread-count parity with breakage; with a fixed fluid step
///        below the solid limit, forced multi-step sub-cycles converge to the single-step one as
///        the step shrinks; the coupling ledger's work equals the solid's energy change and its
///        impulse the time integral of the force. The case's README.md gives measured numbers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "solver/solid_setup.h"
#include "solver/solver_case.h"
#include "solver_test_util.h"

using namespace seaspring;

namespace {

using test::caseDef;
using test::readFile;
using test::replaceOnce;

std::string scratch(const std::string& tag) { return test::scratch("coupling_" + tag); }

const char* const kPlateDef = "hydrostatic_plate/HydrostaticPlate_Def.xml";

/// Solid particles at mid-span (x = 0.5 m).
std::vector<std::uint32_t> midSpan(const solver::SolverCase& c) {
    std::vector<std::uint32_t> mid;
    for (std::uint32_t i = c.nfixed + c.nmoving; i < c.nfixed + c.nmoving + c.nsolid; ++i)
        if (std::fabs(c.particles.pos[i].x - 0.5) < 0.25 * c.constants.dp) mid.push_back(i);
    return mid;
}

/// Mean vertical displacement of the particles `mid` [m].
double deflection(const solver::SolverCase& c, const std::vector<std::uint32_t>& mid, const solver::HostState& st) {
    double u = 0;
    for (std::uint32_t i : mid) u += st.pos[i].z - c.particles.pos[i].z;
    return u / double(mid.size());
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// 1. The hydrodynamic force on the hydrostatic plate carries the weight of the water.
// ---------------------------------------------------------------------------------------------

TEST(SolidCoupling, HydrostaticPlateCarriesTheWaterWeight) {
    const std::string dir = scratch("plate_force");
    const std::string kase = test::generateCaseFile(dir, "plate", caseDef(kPlateDef), 0.025);
    const solver::SolverCase c = solver::loadSolverCase(kase);
    const double g = -c.constants.gravity.z;
    const double column = 1000.0 * g * 2.0 * 1.0;                       // rho g H x 1 m [N/m]
    const double water = double(c.nfluid) * c.constants.massfluid * g;  // the weight of the fluid particles
    double sum_fz = 0, max_fx = 0, lo = 1e300, hi = -1e300;
    int samples = 0;
    const double t_from = 0.01;
    const auto r = test::runCpu(
        kase, dir + "/out", 2,
        [](solver::RunOptions& o) {
            o.tmax = 0.1;
            o.tout = 0.0005;
        },
        [&](double t, long long, const solver::HostState& st) {
            double fx = 0, fz = 0;
            for (const physics::Double3& f : st.solid_force) {
                fx += f.x;
                fz += f.z;
            }
            if (t < t_from) return;
            sum_fz += fz;
            ++samples;
            lo = std::min(lo, -fz);
            hi = std::max(hi, -fz);
            max_fx = std::max(max_fx, std::fabs(fx));
        });
    ASSERT_GT(samples, 50);
    const double mean = -sum_fz / samples;
    std::printf("hydrostatic plate dp 0.025, %lld steps to %.3f s: mean force on the plate from %.2f s %.1f N/m = "
                "%.4f rho g H = %.4f water weight (%.1f N/m); range %.4f..%.4f of the water weight; |Fx| <= %.2e N/m\n",
                r.summary.steps, r.summary.physical_time, t_from, mean, mean / column, mean / water, water,
                lo / water, hi / water, max_fx);
    EXPECT_EQ(r.summary.excluded_not_finite + r.summary.excluded_density + r.summary.excluded_position, 0u);
    // The water's weight is carried by the plate and, near the bottom corners, by the side walls
    // (DBC). The column rings acoustically (period 4H/c0 = 91 ms, +-25 % on the instantaneous
    // force), so the force is averaged over one period, 10-100 ms: measured 0.991 of the water
    // weight (0.966 rho g H: the fluid spans 1 - dp of the 1 m width); averaged over two and
    // three periods 0.9955 and 0.9945, so the walls carry about 0.5 %.
    EXPECT_NEAR(mean / water, 1.0, 0.03);
    EXPECT_GT(lo / water, 0.6);
    EXPECT_LT(hi / water, 1.4);
    // Symmetric case: no net horizontal force.
    EXPECT_LT(max_fx, 1e-4 * water);
}

// ---------------------------------------------------------------------------------------------
// 2. The plate stays near its static deflection for 0.5 s (VcpmCoupling 2, the default). With
//    the seed's staggered scheme (VcpmCoupling 1) a plate oscillation near 1 kHz grows after
//    0.2 s (docs/vcpm.md, Fluid-solid coupling). 9 s on 2 threads.
// ---------------------------------------------------------------------------------------------

TEST(SolidCoupling, HydrostaticPlateStaysNearItsStaticDeflection) {
    const std::string dir = scratch("plate_long");
    const std::string kase = test::generateCaseFile(dir, "plate", caseDef(kPlateDef), 0.025);
    const solver::SolverCase c = solver::loadSolverCase(kase);
    const std::vector<std::uint32_t> mid = midSpan(c);
    ASSERT_FALSE(mid.empty());
    std::vector<double> ts, zs;
    test::runCpu(
        kase, dir + "/out", 2,
        [](solver::RunOptions& o) {
            o.tmax = 0.5;
            o.tout = 0.0005;
        },
        [&](double t, long long, const solver::HostState& st) {
            ts.push_back(t);
            zs.push_back(deflection(c, mid, st));
        });
    double ref = 0, dev = 0;
    int m = 0;
    for (std::size_t k = 0; k < ts.size(); ++k)
        if (ts[k] >= 0.05 && ts[k] <= 0.15) {
            ref += zs[k];
            ++m;
        }
    ref /= m;
    for (std::size_t k = 0; k < ts.size(); ++k)
        if (ts[k] >= 0.4) dev = std::max(dev, std::fabs(zs[k] - ref));
    std::printf("hydrostatic plate dp 0.025: mid-span deflection %.3e m (50-150 ms), largest deviation from it "
                "over 400-500 ms %.3e m\n", ref, dev);
    EXPECT_LT(ref, 0.0);
    EXPECT_LT(dev, 0.5 * std::fabs(ref));
}

// ---------------------------------------------------------------------------------------------
// 3. Thread-count parity of a coupled run with bonds breaking; a different critstretch changes
//    the hash.
// ---------------------------------------------------------------------------------------------

TEST(SolidCoupling, ThreadCountsGiveIdenticalHashesWithBreakage) {
    // The hydrostatic plate at dp 0.025 (plate 2 particles thick) with critstretch 3e-5: 10 bonds
    // break within 80 steps (26 without the rows' bending, which stiffens the thin plate).
    const std::string base = readFile(caseDef(kPlateDef));
    auto plate = [&](const char* crit) {
        return replaceOnce(base, R"(poissratio="0.34")", std::string(R"(poissratio="0.34" critstretch=")") + crit + "\"");
    };
    const std::string dir = scratch("parity_plate");
    const std::string kase = test::generateCase(dir + "/a", "plate", plate("3e-5"), 0.025);
    auto steps = [](solver::RunOptions& o) { o.nsteps = 80; };
    const auto r1 = test::runCpu(kase, dir + "/out1", 1, steps);
    const auto r2 = test::runCpu(kase, dir + "/out2", 2, steps);
    std::printf("coupled plate, critstretch 3e-5, 80 steps: %llu bonds broken, %lld solid sub-steps, hash %s\n",
                (unsigned long long)r1.summary.broken_bonds, r1.summary.solid_substeps, r1.summary.state_hash.c_str());
    EXPECT_EQ(r1.summary.steps, 80);
    EXPECT_GT(r1.summary.broken_bonds, 0u);
    EXPECT_GT(r1.summary.solid_substeps, 80);
    EXPECT_EQ(r1.summary.broken_bonds, r2.summary.broken_bonds);
    EXPECT_EQ(r1.state.bond_broken, r2.state.bond_broken);
    EXPECT_EQ(r1.summary.state_hash, r2.summary.state_hash);
    const std::string kase3 = test::generateCase(dir + "/b", "plate", plate("2.5e-5"), 0.025);
    const auto r3 = test::runCpu(kase3, dir + "/out3", 2, steps);
    EXPECT_GT(r3.summary.broken_bonds, 0u);
    EXPECT_NE(r3.summary.state_hash, r1.summary.state_hash);
}

// ---------------------------------------------------------------------------------------------
// 4. Sub-cycling: with a fixed fluid step d below the solid limit dt_S, the run with the solid
//    sub-steps forced to omega = 4 converges to the run with omega = 1 as d -> 0 (the issue's
//    requirement). Both integrate the same frozen force over each step; they differ by the
//    position-Verlet error of the solid over one step, O(d^2). Compared over the first 0.25 ms:
//    over 1 ms the highest lattice modes (through the 2-particle thickness, Omega d ~ 1 at
//    d = 2.5e-6 s) drift O(1) radian apart in phase, so the difference saturates at their
//    amplitude (~1e-9 m; measured orders 0.6, 0.8, then 2.9, 3.1 below d = 6.25e-7 s), and at
//    d = 1.6e-7 s it meets the noise of the float fluid (~5e-11 m).
// ---------------------------------------------------------------------------------------------

namespace {

struct PlateHistory {
    std::vector<double> t, w;                 ///< output times and mid-span deflection [m]
    std::vector<physics::Double3> solid_pos;  ///< solid positions at the end (solid-index order)
    solver::RunSummary summary;
    bool finite = true;
};

PlateHistory runFixedStep(const std::string& kase, const std::string& outdir, double tmax, double tout, double dt,
                          int omega, int coupling) {
    const solver::SolverCase c = solver::loadSolverCase(kase);
    const std::vector<std::uint32_t> mid = midSpan(c);
    PlateHistory h;
    const auto r = test::runCpu(
        kase, outdir, 2,
        [&](solver::RunOptions& o) {
            o.tmax = tmax;
            o.tout = tout;
            o.dt_fixed = dt;
            o.solid_substeps = omega;
            o.vcpm_coupling = coupling;
        },
        [&](double t, long long, const solver::HostState& st) {
            h.t.push_back(t);
            h.w.push_back(deflection(c, mid, st));
        });
    const std::uint32_t first = c.nfixed + c.nmoving;
    h.solid_pos.assign(r.state.pos.begin() + first, r.state.pos.begin() + first + c.nsolid);
    for (const physics::Double3& p : h.solid_pos) h.finite = h.finite && test::finite(p);
    h.summary = r.summary;
    return h;
}

}  // namespace

TEST(SolidCoupling, ForcedSubstepsConvergeToTheSingleStepRun) {
    const std::string dir = scratch("substeps");
    const std::string kase = test::generateCaseFile(dir, "plate", caseDef(kPlateDef), 0.025);
    const solver::SolverCase c = solver::loadSolverCase(kase);
    const solver::SolidSetup so = solver::makeSolidSetup(c);
    const double d0 = 1.25e-6, tmax = 2.5e-4, tout = 1e-5;  // 200, 400 and 800 steps; 26 outputs
    ASSERT_LT(d0, so.dt);  // dt_S = 3.224e-6 s x the correction's 0.86: omega = 1 is within the solid's limit
    for (int coupling : {2, 1}) {
        double eh[3], ep[3], scale = 0;
        for (int k = 0; k < 3; ++k) {
            const double d = d0 / double(1 << k);
            const std::string tag = "/c" + std::to_string(coupling) + "_" + std::to_string(k);
            const PlateHistory a = runFixedStep(kase, dir + tag + "_w1", tmax, tout, d, 1, coupling);
            const PlateHistory b = runFixedStep(kase, dir + tag + "_w4", tmax, tout, d, 4, coupling);
            ASSERT_TRUE(a.finite && b.finite);
            EXPECT_EQ(a.summary.omega_max, 1);
            EXPECT_EQ(b.summary.omega_max, 4);
            EXPECT_EQ(a.summary.steps, std::lround(tmax / d));
            ASSERT_EQ(a.t.size(), b.t.size());
            ASSERT_GE(a.t.size(), 25u);
            eh[k] = 0;
            for (std::size_t j = 0; j < a.t.size(); ++j) {
                ASSERT_NEAR(a.t[j], b.t[j], 1e-12);
                eh[k] = std::max(eh[k], std::fabs(a.w[j] - b.w[j]));
                scale = std::max(scale, std::fabs(a.w[j]));
            }
            ep[k] = 0;
            for (std::size_t s = 0; s < a.solid_pos.size(); ++s)
                ep[k] = std::max(ep[k], test::dist(a.solid_pos[s], b.solid_pos[s]));
            std::printf("VcpmCoupling %d, d = %.4e s (%lld steps to %.2e s): omega 1 vs 4: mid-span deflection "
                        "history differs by <= %.3e m (%.2e of its largest, %.3e m), final solid positions by "
                        "<= %.3e m\n",
                        coupling, d, a.summary.steps, a.summary.physical_time, eh[k], eh[k] / scale, scale, ep[k]);
        }
        const double oh[2] = {std::log2(eh[0] / eh[1]), std::log2(eh[1] / eh[2])};
        const double op[2] = {std::log2(ep[0] / ep[1]), std::log2(ep[1] / ep[2])};
        std::printf("VcpmCoupling %d: observed order, deflection history %.2f %.2f (overall %.2f), final positions "
                    "%.2f %.2f (overall %.2f)\n",
                    coupling, oh[0], oh[1], 0.5 * (oh[0] + oh[1]), op[0], op[1], 0.5 * (op[0] + op[1]));
        // Measured with the surface correction (the default; VcpmCoupling 2 / 1): history 2.14 2.01 /
        // 2.17 1.98, final positions 2.19 1.74 / 2.09 2.19. The plain lattice started at d = 2.5e-6 s
        // (history 2.18 1.77, positions 3.10 2.27); the corrected one's stiffest modes are faster
        // (its sub-step limit is 0.86 x the plain one's here), and from 2.5e-6 s its final positions'
        // first halving was not yet asymptotic (order -0.21): the test starts one halving lower.
        for (int k = 0; k < 2; ++k) {
            EXPECT_GT(oh[k], 1.4) << coupling;
            EXPECT_GT(op[k], 1.4) << coupling;
        }
        EXPECT_NEAR(0.5 * (oh[0] + oh[1]), 2.0, 0.3) << coupling;
        EXPECT_GT(0.5 * (op[0] + op[1]), 1.7) << coupling;
        EXPECT_LT(0.5 * (op[0] + op[1]), 3.2) << coupling;
        // Small: measured 3.6e-5 of the deflection at d = 1.25e-6 s (8.9e-11 m); positions 4.1e-10 m.
        EXPECT_LT(eh[0], 1e-3 * scale) << coupling;
        EXPECT_LT(ep[0], 5e-3 * scale) << coupling;
    }
}

// ---------------------------------------------------------------------------------------------
// 5. The coupling ledger (OUTDIR/ledger.csv, written whenever the case has solids, also with
//    part saving off). Per fluid step, the impulse grows by F dt and the work by F . dr, F the
//    force that moved the solid over the step (exact bookkeeping). Over the run, the work equals
//    the solid's kinetic + elastic + gravitational energy change (no damping, no breakage; the
//    solid integrator conserves energy to O(dt^2)); the energies are recomputed here from the
//    state. The plate's momentum balance also needs the clamp bonds' impulse, which neither the
//    state nor the ledger holds, and the fluid's the walls' (DBC) force: neither is checked.
// ---------------------------------------------------------------------------------------------

namespace {

/// Lattice energy U = sum_bonds k dl^2 + T/2 sum_nodes S^2 (dl half the elongation, S the sum
/// of dl over the node's intact bonds, nodes = solid particles and clamp nodes): each bond
/// summed once, here, rather than per end as the ledger does.
double latticeEnergy(const solver::SolidSetup& so, const solver::HostState& st) {
    std::vector<double> s_solid(so.nsolid, 0.0);
    std::map<std::uint32_t, double> s_clamp;
    double springs = 0;
    for (std::uint32_t s = 0; s < so.nsolid; ++s)
        for (int q = 0; q < so.count[s]; ++q) {
            const std::size_t k = std::size_t(q) * so.nsolid + s;
            if (st.bond_broken[k]) continue;
            const bool clamp = (so.flags[k] & physics::kBondClamp) != 0;
            const std::uint32_t j = clamp ? so.clamp_id[so.partner[k]] : so.first_solid + so.partner[k];
            const double dl = 0.5 * (test::dist(st.pos[so.first_solid + s], st.pos[j]) - so.rest[k]);
            const physics::VcpmMaterial& m = so.materials[so.body[s]];
            // The surface correction (on by default): the bond's stiffness factor and the
            // site's volumetric weight (a clamp node's sum is unweighted).
            const double kk = ((so.flags[k] & physics::kBondSecond) ? m.k_second : m.k_first) *
                              (so.kfac.empty() ? 1.0 : so.kfac[k]);
            if (clamp || so.partner[k] > s) springs += kk * dl * dl;
            s_solid[s] += so.vw.empty() ? dl : so.vw[k] * dl;
            if (clamp) s_clamp[j] += dl;
        }
    const double t_half = so.materials[0].t_half;  // one body
    double volumetric = 0;
    for (double v : s_solid) volumetric += t_half * v * v;
    for (const auto& [id, v] : s_clamp) volumetric += t_half * v * v;
    // The rows' bending (VcpmRowBending 1): 1/2 k_r |r+ - 2 r + r-|^2 wherever a particle has
    // intact first-neighbour bonds on both sides along an axis of the lattice (the sides found
    // from the initial positions, not from the set-up's row slots).
    double rows = 0;
    for (std::uint32_t s = 0; !so.row_slot.empty() && s < so.nsolid; ++s)
        for (int c = 0; c < 3; ++c) {
            std::int64_t side[2] = {-1, -1};
            for (int q = 0; q < so.count[s]; ++q) {
                const std::size_t k = std::size_t(q) * so.nsolid + s;
                if (st.bond_broken[k] || (so.flags[k] & physics::kBondSecond)) continue;
                const bool clamp = (so.flags[k] & physics::kBondClamp) != 0;
                const physics::Double3 p0 = clamp ? so.clamp_pos[so.partner[k]] : so.pos[so.partner[k]];
                const double v[3] = {p0.x - so.pos[s].x, p0.y - so.pos[s].y, p0.z - so.pos[s].z};
                if (std::fabs(v[c]) < 0.5 * so.rest[k]) continue;
                side[v[c] > 0 ? 1 : 0] = clamp ? std::int64_t(so.clamp_id[so.partner[k]]) : std::int64_t(so.first_solid + so.partner[k]);
            }
            if (side[0] < 0 || side[1] < 0) continue;
            const physics::Double3 a = st.pos[std::size_t(side[0])], b = st.pos[std::size_t(side[1])], o = st.pos[so.first_solid + s];
            const double dx = a.x + b.x - 2 * o.x, dy = a.y + b.y - 2 * o.y, dz = a.z + b.z - 2 * o.z;
            rows += 0.5 * so.materials[so.body[s]].row_k * (dx * dx + dy * dy + dz * dz);
        }
    return springs + volumetric + rows;
}

/// Column `name` of a CSV file with a header row.
std::vector<double> csvColumn(const std::string& text, const std::string& name) {
    std::istringstream in(text);
    std::string line, cell;
    std::getline(in, line);
    int col = -1, k = 0;
    for (std::istringstream h(line); std::getline(h, cell, ';'); ++k)
        if (cell == name) col = k;
    std::vector<double> v;
    while (col >= 0 && std::getline(in, line)) {
        std::istringstream r(line);
        for (int i = 0; i <= col; ++i) std::getline(r, cell, ';');
        v.push_back(std::stod(cell));
    }
    return v;
}

}  // namespace

TEST(SolidCoupling, LedgerWorkEqualsTheSolidEnergyChange) {
    // Both couplings on the corrected lattice without the rows' bending (VcpmRowBending 0), and
    // VcpmCoupling 2 with it (the default: its energy, 1/2 k_r |d|^2 per row triplet, in the
    // ledger and above).
    for (int rows : {0, 1}) {
        const std::string dir = scratch(rows ? "ledger_rows" : "ledger");
        const std::string kase =
            rows ? test::generateCaseFile(dir, "plate", caseDef(kPlateDef), 0.025)
                 : test::generateCase(dir, "plate",
                                      test::replaceOnce(readFile(caseDef(kPlateDef)), "<parameters>",
                                                        "<parameters><parameter key=\"VcpmRowBending\" value=\"0\" />"),
                                      0.025);
        const solver::SolverCase c = solver::loadSolverCase(kase);
        const solver::SolidSetup so = solver::makeSolidSetup(c);
        ASSERT_EQ(so.materials.size(), 1u);
        ASSERT_EQ(so.materials[0].damp_rate, 0.0);
        ASSERT_LE(so.materials[0].crit_stretch, 0.0);
        ASSERT_EQ(so.row_slot.empty(), rows == 0);
        const double gz = c.constants.gravity.z;
        for (int coupling : {2, 1}) {
            if (rows && coupling == 1) continue;
            const std::string out = dir + "/out" + std::to_string(coupling);
            std::vector<double> ts, work, energy, solid_work;
            double e0 = 0, max_dj = 0, max_dw = 0, jscale = 0, wscale = 0, t_prev = 0, w_prev = 0;
            physics::Double3 j_prev{0, 0, 0};
            std::vector<physics::Double3> r_prev(so.pos);
            std::size_t broken = 0;
            // An output after every fluid step (TimeOut below the step).
            const auto r = test::runCpu(
                kase, out, 2,
                [&](solver::RunOptions& o) {
                    o.tmax = 0.02;
                    o.tout = 1e-6;
                    o.vcpm_coupling = coupling;
                },
                [&](double t, long long, const solver::HostState& st) {
                    double kin = 0, pot = 0, w = 0;
                    physics::Double3 j{0, 0, 0}, jstep{0, 0, 0};
                    double wstep = 0;
                    for (std::uint32_t s = 0; s < so.nsolid; ++s) {
                        const physics::Double3 v = st.solid_vel[s], p = st.pos[so.first_solid + s], f = st.solid_force[s];
                        kin += 0.5 * so.mass[s] * (v.x * v.x + v.y * v.y + v.z * v.z);
                        pot -= so.mass[s] * gz * (p.z - so.pos[s].z);
                        w += st.solid_work[s];
                        j = {j.x + st.solid_impulse[s].x, j.y + st.solid_impulse[s].y, j.z + st.solid_impulse[s].z};
                        jstep = {jstep.x + f.x, jstep.y + f.y, jstep.z + f.z};
                        wstep += f.x * (p.x - r_prev[s].x) + f.y * (p.y - r_prev[s].y) + f.z * (p.z - r_prev[s].z);
                        r_prev[s] = p;
                    }
                    const double e = kin + latticeEnergy(so, st) + pot;
                    if (ts.empty()) e0 = e;
                    if (!ts.empty()) {  // the step from the previous output to this one
                        const double dt = t - t_prev;
                        max_dj = std::max({max_dj, std::fabs(j.x - j_prev.x - jstep.x * dt),
                                           std::fabs(j.z - j_prev.z - jstep.z * dt)});
                        max_dw = std::max(max_dw, std::fabs(w - w_prev - wstep));
                    }
                    jscale = std::max(jscale, std::fabs(j.z));
                    wscale = std::max(wscale, std::fabs(w));
                    ts.push_back(t);
                    work.push_back(w);
                    energy.push_back(e - e0);
                    t_prev = t;
                    w_prev = w;
                    j_prev = j;
                    broken = std::max(broken, test::brokenSlots(st));
                });
            ASSERT_EQ(ts.size(), std::size_t(r.summary.steps + 1));
            EXPECT_EQ(broken, 0u);
            double max_de = 0;
            for (std::size_t k = 0; k < ts.size(); ++k) max_de = std::max(max_de, std::fabs(work[k] - energy[k]));
            std::printf("ledger, VcpmRowBending %d, VcpmCoupling %d, %lld steps to %.4f s: work %.6f J, energy change %.6f J; largest "
                        "|work - energy change| %.3e J = %.2e of the largest work %.4f J; per-step bookkeeping: "
                        "|dJ - F dt| <= %.2e N s (impulse %.2f N s), |dW - F.dr| <= %.2e J\n",
                        rows, coupling, r.summary.steps, ts.back(), work.back(), energy.back(), max_de, max_de / wscale, wscale,
                        max_dj, jscale, max_dw);
            // Measured 1.5e-6 (VcpmCoupling 2) and 1.6e-6 (1) of the largest work over 0.02 s; at the
            // end 0.526174 J against 0.526175 J (dp 0.0125: 0.412166 J against 0.412166 J, 7e-7).
            EXPECT_GT(wscale, 0.1);
            EXPECT_LT(max_de, 2e-5 * wscale) << coupling;
            EXPECT_LT(max_dj, 1e-12 * jscale) << coupling;
            EXPECT_LT(max_dw, 1e-12 * wscale) << coupling;
            // The ledger file: one row per output, its columns as recomputed here (printed to 9 digits).
            const std::string csv = readFile(out + "/ledger.csv");
            const std::vector<double> lw = csvColumn(csv, "work"), lt = csvColumn(csv, "time");
            const std::vector<double> lk = csvColumn(csv, "solid_kinetic"), lu = csvColumn(csv, "solid_elastic");
            const std::vector<double> lp = csvColumn(csv, "solid_potential");
            ASSERT_EQ(lw.size(), ts.size());
            ASSERT_EQ(lk.size(), ts.size());
            for (std::size_t k = 0; k < ts.size(); ++k) {
                EXPECT_NEAR(lt[k], ts[k], 1e-8 * ts.back());
                EXPECT_NEAR(lw[k], work[k], 1e-8 * wscale) << k;
                EXPECT_NEAR(lk[k] + lu[k] + lp[k], energy[k] + e0, 1e-8 * wscale) << k;
            }
        }
    }
}
