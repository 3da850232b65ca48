// SeaSpring — MIT licence.
/// \file test_solid_substep.cpp
/// \brief The solids' sub-cycle without the predictor's force evaluation (solver::SolidSubCycle
///        with predictor_force false, physics::predictorForceUsed): the same bits as the four
///        passes of the seed paper's sub-step wherever the evaluation at r^m changes nothing
///        (undamped, unbreakable, no contact), here on a moving, loaded 2D cantilever with the
///        rows' bending, particles leaving the keep box and cycles of odd and even lengths.
///        Controls: with damping (where the predictor's velocity counts) and with one half-position
///        array for both parities (the race the second array avoids), the results differ.
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

/// `cycles` sub-cycles of n_k sub-steps (lengths cycling through 3, 2, 1) from a bent, moving
/// start under a steady hydrodynamic load; the keep box cuts the free end, so its particles
/// freeze on the way and their bonds break.
Outcome run(bool predictor_force, double damp_rate, HalfArrays halves) {
    const solver::SolidSetup setup = cantileverSetup();
    solver::SolidArrays<solver::HostBuffer> a;
    a.init(setup);
    for (physics::VcpmMaterial& m : a.materials) m.damp_rate = damp_rate;
    a.pos_half_alt = a.pos;  // allocated whatever the set-up decided
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
    std::vector<std::uint32_t> slot(a.n);
    for (std::uint32_t s = 0; s < a.n; ++s) slot[s] = s;
    std::vector<Double3> bpos(a.n);
    std::vector<physics::Float4> bvelrho(a.n);
    solver::ClampMotion cm;
    cm.pos_initial = a.clamp_pos_initial.data();
    cm.object = a.clamp_object.data();
    cm.pos_start = a.clamp_start.data();
    cm.pos_end = a.clamp_end.data();
    const double dt = setup.dt;
    double t = 0;
    for (int c = 0; c < 12; ++c) {
        const int n = 3 - c % 3;
        a.t0 = t;
        a.span = dt * n;
        const solver::SolidToBoundaryPass tb{slot.data(), a.pos.data(), a.vel.data(), a.fluid_force.data(), dt * n,
                                             a.impulse.data(), a.work.data(), false, bpos.data(), bvelrho.data()};
        Double3* alt = halves == HalfArrays::Two ? a.pos_half_alt.data() : a.pos_half.data();
        const solver::SolidSubCycle<0> body{a.state(), a.bonds(), a.clamps(), cm, n, dt, 0.0, 0.0, -9.81,
                                            solver::SubCycleContact{}, solver::BondLanes<0>{}, tb, false,
                                            predictor_force, alt};
        SerialRun runner;
        body(runner);
        t += dt * n;
    }
    return Outcome{a.pos, a.vel, a.broken, a.alarm};
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

// The cantilever's set-up (undamped, unbreakable, no contact) takes the two-pass sub-step.
TEST(SolidSubStep, UndampedUnbreakableBodiesSkipThePredictorForce) {
    const solver::SolidSetup s = cantileverSetup();
    EXPECT_FALSE(physics::predictorForceUsed(s.materials.data(), s.materials.size(), false));
    EXPECT_TRUE(physics::predictorForceUsed(s.materials.data(), s.materials.size(), true));  // contact
    std::vector<physics::VcpmMaterial> m = s.materials;
    m[0].damp_rate = 1.0;
    EXPECT_TRUE(physics::predictorForceUsed(m.data(), m.size(), false));
    m[0].damp_rate = 0.0;
    m[0].crit_stretch = 0.01;
    EXPECT_TRUE(physics::predictorForceUsed(m.data(), m.size(), false));
}

// Two passes per sub-step give the four passes' bits: positions, velocities, the bonds the keep
// box broke and the alarms. The run must move, freeze particles and break bonds, or the
// comparison would be empty.
TEST(SolidSubStep, TwoPassesGiveTheFourPassesBits) {
    const Outcome full = run(true, 0.0, HalfArrays::Two);
    const Outcome lean = run(false, 0.0, HalfArrays::Two);
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
    EXPECT_GT(count(full.broken), 0u);
}

// Controls: where the predictor's velocity counts (damping) the skipped evaluation changes the
// result, and so does one half-position array for both parities (a corrector would read the
// half positions its neighbours' correctors are overwriting).
TEST(SolidSubStep, TheComparisonSeesTheDampingTermAndTheSharedArray) {
    EXPECT_FALSE(sameBits(run(true, 50.0, HalfArrays::Two), run(false, 50.0, HalfArrays::Two)));
    EXPECT_FALSE(sameBits(run(true, 0.0, HalfArrays::Two), run(false, 0.0, HalfArrays::One)));
}
