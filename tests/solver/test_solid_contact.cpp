// SeaSpring — MIT licence.
/// \file test_solid_contact.cpp
/// \brief Contact of VCPM solids (issue 13, physics/solid_contact.h): the pair law (repulsive
///        inside dp only, Newton's third law bit for bit, damping and friction that oppose the
///        motion); a block dropped on a floor comes to rest on it (penetration < 0.1 dp) with its
///        energy bounded and the ledger's energy balance closed; a fragment (a piece of the same
///        body with no bond to the other) and a second body falling on a block rest on it
///        instead of passing through; contact runs give one hash on 1 and 2 threads; contact
///        off lets the block fall through the floor (the tests' own failure mode).
/// Broken on purpose, each caught: the normal force's sign flipped (the block falls through:
/// ABlockDroppedOnAFloorComesToRest), the dashpot's sign flipped (the energy grows),
/// the contact work left out of the ledger (the balance fails by the drop's energy).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "../test_files.h"
#include "physics/solid_contact.h"
#include "solver_test_util.h"

using namespace seaspring;

namespace {

constexpr double kDp = 0.01;

/// A 2D solid-only case: a fixed floor (two rows, top at z = 0) and blocks of `nx` x `nz`
/// particles, each given as "x0 z0 mk nx nz" (lower-left particle); `solids`: the <solid>
/// lines; VcpmContact `contact` with the given damping and friction (friction keeps a block from
/// sliding into the valleys between the floor's particles, 0.134 dp deep).
std::string dropCase(const std::vector<std::string>& blocks, const std::string& solids, int contact,
                     double tmax = 0.5, double damping = 0.5, double friction = 0.3) {
    const double gravity = -9.81;
    std::string draw;
    for (const std::string& b : blocks) {
        double x0, z0;
        int mk, nx, nz;
        std::sscanf(b.c_str(), "%lf %lf %d %d %d", &x0, &z0, &mk, &nx, &nz);
        char box[512];
        std::snprintf(box, sizeof box,
                      "<setmkbound mk=\"%d\" /><drawbox><boxfill>solid</boxfill><point x=\"%.6g\" y=\"0\" z=\"%.6g\" />"
                      "<size x=\"%.6g\" y=\"0\" z=\"%.6g\" /></drawbox>\n",
                      mk, x0, z0, (nx - 1) * kDp, (nz - 1) * kDp);
        draw += box;
    }
    char g[64];
    std::snprintf(g, sizeof g, "%g", gravity);
    return std::string(R"(<?xml version="1.0" encoding="UTF-8" ?>
<case><casedef>
  <constantsdef>
    <gravity x="0" y="0" z=")") + g + R"(" /><rhop0 value="1000" /><hswl value="0.1" auto="false" />
    <gamma value="7" /><speedsystem value="0" auto="true" /><coefsound value="20" />
    <speedsound value="0" auto="true" /><coefh value="1.0607" /><cflnumber value="0.2" />
  </constantsdef>
  <mkconfig boundcount="240" fluidcount="9" />
  <geometry>
    <definition dp="0.01"><pointmin x="-0.1" y="0" z="-0.1" /><pointmax x="0.4" y="0" z="0.4" /></definition>
    <commands><mainlist>
      <setshapemode>dp | bound</setshapemode><setdrawmode mode="full" />
      <setmkbound mk="0" /><drawbox><boxfill>solid</boxfill><point x="-0.05" y="0" z="-0.01" /><size x="0.35" y="0" z="0.01" /></drawbox>
)" + draw + R"(    </mainlist></commands>
  </geometry></casedef>
  <execution><special><vcpmsolids>)" +
           solids + R"(</vcpmsolids></special>
    <parameters>
      <parameter key="TimeMax" value=")" +
           std::to_string(tmax) + R"(" /><parameter key="TimeOut" value="0.01" />
      <parameter key="Visco" value="0.01" /><parameter key="VcpmContact" value=")" +
           std::to_string(contact) + R"(" /><parameter key="VcpmContactDamping" value=")" + std::to_string(damping) +
           R"(" /><parameter key="VcpmContactFriction" value=")" + std::to_string(friction) + R"(" />
      <simulationdomain><posmin x="default" y="default" z="default - 0.2" /><posmax x="default" y="default" z="default + 0.1" /></simulationdomain>
    </parameters>
  </execution>
</case>
)";
}

const char* kRubber = R"(<solid mkbound="1" density="1000" youngmod="1e6" poissratio="0.3" damping="0" />)";

/// The smallest distance between a particle of ids [a0, a1) and one of [b0, b1).
double closest(const solver::HostState& st, std::uint32_t a0, std::uint32_t a1, std::uint32_t b0, std::uint32_t b1) {
    double best = 1e300;
    for (std::uint32_t i = a0; i < a1; ++i)
        for (std::uint32_t j = b0; j < b1; ++j) best = std::min(best, test::dist(st.pos[i], st.pos[j]));
    return best;
}

}  // namespace

// The pair law: nothing at or beyond r_c, repulsion inside, damping against the approach,
// friction against the sliding, and F(b on a) = -F(a on b) bit for bit.
TEST(SolidContact, PairLawRepelsInsideTheRangeOnlyAndIsAntisymmetric) {
    physics::ContactParams cp;
    cp.range = kDp;
    cp.list_range = 1.5 * kDp;
    cp.stiffness = 0.5;
    cp.damping = 0.2;
    cp.friction = 0.3;
    const double k = 1e5, m = 0.1;
    const physics::Double3 still{0, 0, 0};
    auto f = [&](double dx, double dz, physics::Double3 v) {
        return physics::contactPairForce(physics::Double3{dx, 0, dz}, v, k, m, cp);
    };
    EXPECT_EQ(f(0, kDp, still).z, 0.0);
    EXPECT_EQ(f(0, 1.2 * kDp, still).z, 0.0);
    const physics::Double3 push = f(0, 0.9 * kDp, still);
    EXPECT_NEAR(push.z, k * 0.1 * kDp, 1e-9);  // k x overlap, along +n
    EXPECT_EQ(push.x, 0.0);
    // Approaching (v_n < 0): the dashpot adds to the repulsion; separating: it takes away.
    EXPECT_GT(f(0, 0.9 * kDp, physics::Double3{0, 0, -0.1}).z, push.z);
    EXPECT_LT(f(0, 0.9 * kDp, physics::Double3{0, 0, 0.01}).z, push.z);
    // Separating fast: no pull.
    EXPECT_EQ(f(0, 0.9 * kDp, physics::Double3{0, 0, 10}).z, 0.0);
    // Sliding along +x: friction along -x, capped by mu F_n.
    const physics::Double3 slide = f(0, 0.9 * kDp, physics::Double3{1, 0, 0});
    EXPECT_LT(slide.x, 0.0);
    EXPECT_LE(-slide.x, cp.friction * slide.z * (1 + 1e-12));
    // Antisymmetric, bit for bit, for an oblique approach with sliding.
    const physics::Double3 d{0.0031, 0.0007, 0.0072}, v{0.13, -0.02, -0.31};
    const physics::Double3 a = physics::contactPairForce(d, v, k, m, cp);
    const physics::Double3 b = physics::contactPairForce(physics::Double3{-d.x, -d.y, -d.z},
                                                         physics::Double3{-v.x, -v.y, -v.z}, k, m, cp);
    EXPECT_EQ(a.x, -b.x);
    EXPECT_EQ(a.y, -b.y);
    EXPECT_EQ(a.z, -b.z);
    EXPECT_GT(a.z, 0.0);
}

// A rubber block (10 x 6 particles, no material damping) dropped 3 dp onto a floor (contact
// damping 0.5, friction 0.3). With contact it bounces, settles and rests with no pair closer
// than 0.9 dp (penetration < 0.1 dp into the contact range) and no closer than 0.8 dp at any
// output during the impact; the solid's mechanical energy never exceeds the start's, and it
// equals the start's plus the contact work (the ledger) within 2% of the drop energy (the
// integration error of the bounces). Without contact it falls through the floor.
TEST(SolidContact, ABlockDroppedOnAFloorComesToRest) {
    const std::string dir = test::scratch("contact_drop");
    const std::vector<std::string> block = {"0.05 0.04 1 10 6"};
    const std::string kase = test::generateCase(dir, "Drop", dropCase(block, kRubber, 1, 0.6));
    const solver::SolverCase c = solver::loadSolverCase(kase);
    ASSERT_EQ(c.nsolid, 60u);
    // The floor is MK 0 (the ids before the block), the block the solid particles.
    const std::uint32_t f0 = 0, f1 = c.bonds->first_solid, b0 = f1, b1 = b0 + c.nsolid;
    double worst = 1e300;  // the closest approach to the floor at any output
    const test::SolverRun r = test::runCpu(kase, dir + "/out", 2, {}, [&](double, long long, const solver::HostState& st) {
        worst = std::min(worst, closest(st, b0, b1, f0, f1));
    });
    ASSERT_FALSE(r.summary.blowup.has_value()) << r.summary.stop_reason;
    EXPECT_GT(worst, 0.8 * kDp) << "the impact pushed the block " << (kDp - worst) / kDp << " dp into the floor";
    const double rest_gap = closest(r.state, b0, b1, f0, f1);
    EXPECT_GT(rest_gap, 0.9 * kDp) << "penetration " << (kDp - rest_gap) / kDp << " dp";
    EXPECT_LE(rest_gap, 1.0 * kDp) << "the block is not resting on the floor";
    // Energy from the ledger: E = kinetic + elastic + potential (0 at t = 0).
    std::string header;
    const auto rows = test::readCsv(dir + "/out/ledger.csv", header);
    ASSERT_GE(rows.size(), 50u);
    ASSERT_NE(header.find("contact_work"), std::string::npos) << header;
    const double drop = 60 * 1000 * kDp * kDp * 9.81 * 0.03;  // m g h: the bottom row falls 0.03 m to dp above the floor [J/m]
    double e_max = -1e300, balance_worst = 0;
    for (const auto& row : rows) {
        const double e = std::stod(row[14]) + std::stod(row[15]) + std::stod(row[16]);
        const double w = std::stod(row[24]);
        e_max = std::max(e_max, e);
        balance_worst = std::max(balance_worst, std::fabs(e - w));
    }
    EXPECT_LT(e_max, 0.01 * drop) << "the solid gained energy";
    EXPECT_LT(balance_worst, 0.02 * drop) << "kinetic + elastic + potential != contact work";
    // The bounces were damped: the block ends at rest (kinetic and elastic energy below 0.1% of
    // the drop's).
    EXPECT_LT(std::stod(rows.back()[14]) + std::stod(rows.back()[15]), 1e-3 * drop);

    // Contact off: through the floor.
    const std::string off = test::generateCase(dir, "DropOff", dropCase(block, kRubber, 0, 0.2));
    const test::SolverRun r_off = test::runCpu(off, dir + "/out_off", 2);
    const solver::SolverCase& co = r_off.kase;
    double highest = -1e300;
    for (std::uint32_t i = co.bonds->first_solid; i < co.bonds->first_solid + co.nsolid; ++i)
        highest = std::max(highest, r_off.state.pos[i].z);
    EXPECT_LT(highest, -0.01 - kDp) << "without contact the block should have fallen through the floor";
}

// A second piece falling on a block resting on the floor: a fragment of the same body (no bond
// across the 4 dp gap) and a second body of another stiffness (the harmonic-mean pair). Each
// lands on the block and rests there (within 5% of the contact range at the end), never closer
// than 0.85 dp to it; the runs on 1 and 2
// threads end with the same state hash.
TEST(SolidContact, APieceFallingOnABlockRestsOnIt) {
    for (const bool same_body : {true, false}) {
        const std::string tag = same_body ? "fragment" : "body";
        const std::string dir = test::scratch("contact_stack_" + tag);
        const std::vector<std::string> blocks = {"0.05 0.01 1 12 4", same_body ? "0.08 0.08 1 6 4" : "0.08 0.08 2 6 4"};
        const std::string solids = same_body ? std::string(kRubber)
                                             : std::string(kRubber) +
                                                   R"(<solid mkbound="2" density="1000" youngmod="4e6" poissratio="0.3" damping="0" />)";
        const std::string kase = test::generateCase(dir, "Stack", dropCase(blocks, solids, 1, 0.4));
        std::uint32_t lo0 = 0, lo1 = 0, up0 = 0, up1 = 0;
        double closest_seen = 1e300;
        auto ranges = [&](const solver::SolverCase& c) {
            // Lower block drawn first: its 48 particles, then the upper piece's 24.
            lo0 = c.bonds->first_solid;
            lo1 = lo0 + 48;
            up0 = lo1;
            up1 = up0 + 24;
        };
        solver::SolverCase kc = solver::loadSolverCase(kase);
        ranges(kc);
        ASSERT_EQ(kc.nsolid, 72u);
        const test::SolverRun r = test::runCpu(kase, dir + "/out", 2, {}, [&](double, long long, const solver::HostState& st) {
            closest_seen = std::min(closest_seen, closest(st, lo0, lo1, up0, up1));
        });
        ASSERT_FALSE(r.summary.blowup.has_value()) << tag << ": " << r.summary.stop_reason;
        EXPECT_GT(closest_seen, 0.85 * kDp) << tag;
        const double rest = closest(r.state, lo0, lo1, up0, up1);
        EXPECT_LT(rest, 1.05 * kDp) << tag << ": the piece is not resting on the block";
        EXPECT_EQ(r.summary.broken_bonds, 0u) << tag;
        const test::SolverRun r1 = test::runCpu(kase, dir + "/out1", 1);
        EXPECT_EQ(r1.summary.state_hash, r.summary.state_hash) << tag << ": 1 against 2 threads";
    }
}
