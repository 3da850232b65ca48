// SeaSpring — MIT licence.
/// \file test_solid_substep.cpp
/// \brief The solids' sub-cycle without the predictor's force evaluation (solver::SolidSubCycle
///        with predictor_force false, physics::predictorForceUsed; the sums pass at r^m kept
///        for breakage, physics::startSumsUsed): the same bits as the four passes of the seed
///        paper's sub-step wherever the force at r^m changes nothing (undamped, no contact),
///        here on a moving, loaded 2D cantilever with the rows' bending, particles leaving the
///        keep box, bonds breaking and cycles of odd and even lengths. Controls: with damping
///        (where the predictor's velocity counts), with one half-position array for both
///        parities (the race the second array avoids) and, for a breakable body, without the
///        sums pass at r^m, the results differ.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "physics/vcpm.h"
#include "physics/vcpm_substep.h"
#include "solver/solid_arrays.h"
#include "solver/solid_setup.h"
#include "solver/solver_case.h"
#include "solver_test_util.h"

using namespace seaspring;
using physics::Double3;

namespace {

/// Runs pass(i) for i in [0, n), one pass after the other (the host's runner on one thread).
struct SerialRun {
    template <class Pass>
    void operator()(std::uint32_t n, const Pass& pass) const {
        for (std::uint32_t i = 0; i < n; ++i) pass(i);
    }
};

/// The 2D cantilever (cases/cantilever2d, 4 particles through the thickness, the default
/// corrections with the rows' bending) as the solver sets it up.
solver::SolidSetup cantileverSetup() {
    static const solver::SolidSetup s = solver::makeSolidSetup(solver::loadSolverCase(test::generateCase(
        test::scratch("substep"), "cl", test::readFile(test::caseDef("cantilever2d/Cantilever2D_Def.xml")), 0.005)));
    return s;
}

struct Outcome {
    std::vector<Double3> pos, vel;
    std::vector<std::uint8_t> broken;
    std::vector<physics::SolidAlarm> alarm;
};

enum class HalfArrays { Two, One };

/// A critical stretch that the moving cantilever's bonds pass (some of them, during the run;
/// there the bonds' strain grows through r^m and r^{m+1/2} alike, so breakage alone does not
/// need the sums at r^m: kick() makes one that does).
constexpr double kCrit = 2e-5;

/// How a run differs from the default: damping, a critical stretch, and which scheme.
struct Variant {
    bool predictor_force = true;
    bool start_sums = true;
    double damp_rate = 0.0;
    double crit_stretch = 0.0;
    HalfArrays halves = HalfArrays::Two;
};

/// The cantilever's solid arrays with the variant's material, and one sub-cycle run over them
/// with the variant's scheme (the end state goes into a boundary block of the rig's own).
struct Rig {
    solver::SolidSetup setup = cantileverSetup();
    solver::SolidArrays<solver::HostBuffer> a;
    std::vector<std::uint32_t> slot;
    std::vector<Double3> bpos;
    std::vector<physics::Float4> bvelrho;

    explicit Rig(const Variant& v) {
        a.init(setup);
        for (physics::VcpmMaterial& m : a.materials) {
            m.damp_rate = v.damp_rate;
            m.crit_stretch = v.crit_stretch;
        }
        a.pos_half_alt = a.pos;  // allocated whatever the set-up decided
        slot.resize(a.n);
        for (std::uint32_t s = 0; s < a.n; ++s) slot[s] = s;
        bpos.resize(a.n);
        bvelrho.resize(a.n);
    }

    /// n sub-steps of the set-up's dt from t0, gravity gz.
    void cycle(const Variant& v, double t0, int n, double gz) {
        const double dt = setup.dt;
        a.t0 = t0;
        a.span = dt * n;
        solver::ClampMotion cm;
        cm.pos_initial = a.clamp_pos_initial.data();
        cm.object = a.clamp_object.data();
        cm.pos_start = a.clamp_start.data();
        cm.pos_end = a.clamp_end.data();
        const solver::SolidToBoundaryPass tb{slot.data(), a.pos.data(), a.vel.data(), a.fluid_force.data(), dt * n,
                                             a.impulse.data(), a.work.data(), false, bpos.data(), bvelrho.data()};
        Double3* alt = v.halves == HalfArrays::Two ? a.pos_half_alt.data() : a.pos_half.data();
        const solver::SolidSubCycle<0> body{a.state(), a.bonds(), a.clamps(), cm, n, dt, 0.0, 0.0, gz,
                                            solver::SubCycleContact{}, solver::BondLanes<0>{}, tb, false,
                                            v.predictor_force, alt, v.start_sums};
        SerialRun runner;
        body(runner);
    }

    Outcome outcome() const { return Outcome{a.pos, a.vel, a.broken, a.alarm}; }
};

/// 12 sub-cycles of 3, 2, 1, 3, ... sub-steps from a bent, moving start under a steady
/// hydrodynamic load and gravity; the keep box cuts the free end, so its particles freeze on
/// the way and their bonds break.
Outcome run(const Variant& v) {
    Rig r(v);
    solver::SolidArrays<solver::HostBuffer>& a = r.a;
    double xmin = 1e300, xmax = -1e300, zmax = -1e300;
    for (const Double3& p : a.pos) {
        xmin = std::min(xmin, p.x);
        xmax = std::max(xmax, p.x);
        zmax = std::max(zmax, p.z);
    }
    const double len = xmax - xmin;
    for (std::uint32_t s = 0; s < a.n; ++s) {
        const double xi = (a.pos[s].x - xmin) / len;
        a.vel[s] = Double3{0.01 * xi, 0.0, 0.3 * xi * xi};
        a.fluid_force[s] = Double3{-2e-3 * xi, 0.0, -5e-3 * (1.0 - xi)};
    }
    a.keep.maxz = zmax + 2e-4;  // the rising free end leaves it
    double t = 0;
    for (int c = 0; c < 12; ++c) {
        const int n = 3 - c % 3;
        r.cycle(v, t, n, -9.81);
        t += r.setup.dt * n;
    }
    return r.outcome();
}

/// One bond of an interior particle at rest stretched just past the critical stretch at r^0 while
/// the particle moves back fast enough that the bond is compressed at r^{1/2}: one sub-step.
/// The four passes break it at r^0; a scheme without the sums pass at r^m would not.
Outcome kick(Variant v) {
    const double crit = 1e-3;
    v.crit_stretch = crit;
    Rig r(v);
    solver::SolidArrays<solver::HostBuffer>& a = r.a;
    const std::uint32_t s = a.n / 2, j = a.partner[s];  // slot 0 of s
    EXPECT_EQ(a.flags[s] & physics::kBondClamp, 0);
    const double dx = a.pos[j].x - a.pos[s].x, dz = a.pos[j].z - a.pos[s].z, len = std::sqrt(dx * dx + dz * dz);
    const double ux = dx / len, uz = dz / len, dt = r.setup.dt;
    const double e = 1.01 * crit * len, w = 4.0 * crit * len / dt;  // dt/2 w = 2 crit len
    a.pos[s] = Double3{a.pos[s].x - e * ux, a.pos[s].y, a.pos[s].z - e * uz};
    a.vel[s] = Double3{w * ux, 0.0, w * uz};
    r.cycle(v, 0.0, 1, 0.0);
    return r.outcome();
}

bool sameBits(const Outcome& x, const Outcome& y) {
    auto eq = [](const auto& u, const auto& v) {
        return u.size() == v.size() && std::memcmp(u.data(), v.data(), u.size() * sizeof(u[0])) == 0;
    };
    return eq(x.pos, y.pos) && eq(x.vel, y.vel) && eq(x.broken, y.broken) && eq(x.alarm, y.alarm);
}

std::size_t count(const std::vector<std::uint8_t>& v) {
    std::size_t k = 0;
    for (std::uint8_t b : v) k += b;
    return k;
}

}  // namespace

// The cantilever's set-up (undamped, unbreakable, no contact) takes the two-pass sub-step;
// damping or contact keep the four passes, a critical stretch the sums pass at r^m.
TEST(SolidSubStep, UndampedBodiesWithoutContactSkipThePredictorForce) {
    const solver::SolidSetup s = cantileverSetup();
    EXPECT_FALSE(physics::predictorForceUsed(s.materials.data(), s.materials.size(), false));
    EXPECT_FALSE(physics::startSumsUsed(s.materials.data(), s.materials.size()));
    EXPECT_NE(std::find_if(s.body_lines.begin(), s.body_lines.end(),
                           [](const std::string& l) { return l.rfind("sub-step: 2 passes", 0) == 0; }),
              s.body_lines.end());  // the run log says which
    EXPECT_TRUE(physics::predictorForceUsed(s.materials.data(), s.materials.size(), true));  // contact
    std::vector<physics::VcpmMaterial> m = s.materials;
    m[0].damp_rate = 1.0;
    EXPECT_TRUE(physics::predictorForceUsed(m.data(), m.size(), false));
    m[0].damp_rate = 0.0;
    m[0].crit_stretch = 0.01;
    EXPECT_FALSE(physics::predictorForceUsed(m.data(), m.size(), false));
    EXPECT_TRUE(physics::startSumsUsed(m.data(), m.size()));
}

// Two passes per sub-step (an unbreakable body) and three (a breakable one) give the four
// passes' bits: positions, velocities, the bonds broken (by the keep box; by strain) and the
// alarms. The runs must move, freeze particles and break bonds, or the comparison would be empty.
TEST(SolidSubStep, FewerPassesGiveTheFourPassesBits) {
    const Outcome full = run(Variant{});
    const Outcome lean = run(Variant{false, false});
    EXPECT_TRUE(sameBits(full, lean));
    const solver::SolidSetup s = cantileverSetup();
    double moved = 0;
    std::size_t frozen = 0;
    for (std::uint32_t i = 0; i < s.nsolid; ++i) {
        moved = std::max(moved, test::dist(full.pos[i], s.pos[i]));
        frozen += full.vel[i].x == 0.0 && full.vel[i].z == 0.0 ? 1u : 0u;
    }
    EXPECT_GT(moved, 1e-4);
    EXPECT_GT(frozen, 0u);
    const std::size_t by_keep = count(full.broken);
    EXPECT_GT(by_keep, 0u);
    const Outcome full_b = run(Variant{true, true, 0.0, kCrit});
    EXPECT_TRUE(sameBits(full_b, run(Variant{false, true, 0.0, kCrit})));
    EXPECT_GT(count(full_b.broken), by_keep);  // bonds broke by strain too
    const Outcome full_k = kick(Variant{});
    EXPECT_TRUE(sameBits(full_k, kick(Variant{false, true})));
    EXPECT_EQ(count(full_k.broken), 2u);  // the kicked bond, at both ends
}

// Controls: where the predictor's velocity counts (damping) the skipped force changes the
// result, and so do one half-position array for both parities (a corrector would read the
// half positions its neighbours' correctors are overwriting) and, for a breakable body, leaving
// out the sums pass at r^m (where bonds break first).
TEST(SolidSubStep, TheComparisonSeesDampingTheSharedArrayAndEarlyBreakage) {
    EXPECT_FALSE(sameBits(run(Variant{true, true, 50.0}), run(Variant{false, false, 50.0})));
    EXPECT_FALSE(sameBits(run(Variant{}), run(Variant{false, false, 0.0, 0.0, HalfArrays::One})));
    EXPECT_FALSE(sameBits(kick(Variant{}), kick(Variant{false, false})));
}
