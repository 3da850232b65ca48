// SeaSpring — MIT licence.
/// \file test_solid_loads.cpp
/// \brief VCPM point loads through the whole chain (gencase <pointload> -> resolved case ->
///        solver): on a free, unclamped block the total momentum grows exactly as the impulse
///        of the applied loads (the bond forces cancel pairwise), for a constant and a ramped
///        load; and a bad <pointload> attribute is an input error with its line.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.h"
#include <fstream>
#include <iterator>
#include <sstream>
#include <algorithm>

#include "io/part_output.h"
#include "solver/solver_case.h"
#include "solver_test_util.h"

using namespace seaspring;

namespace {

std::string scratch(const std::string& tag) { return test::scratch("loads_" + tag); }

/// A free 2D block of 8 x 4 particles (dp 0.01; steel-like, no gravity, no clamp), one or two
/// point loads given as XML, run without fluid.
std::string freeBlock(const std::string& loads) {
    return R"(<?xml version="1.0" encoding="UTF-8" ?>
<case><casedef>
  <constantsdef><gravity x="0" y="0" z="0" /><rhop0 value="1000" /><hswl value="0.1" auto="false" />
    <gamma value="7" /><speedsystem value="1" auto="false" /><coefsound value="20" />
    <speedsound value="0" auto="true" /><coefh value="1.0607" /><cflnumber value="0.2" /></constantsdef>
  <mkconfig boundcount="240" fluidcount="9" />
  <geometry><definition dp="0.01"><pointmin x="-0.1" y="0" z="-0.1" /><pointmax x="0.3" y="0" z="0.2" /></definition>
  <commands><mainlist>
    <setmkbound mk="0" /><drawbox><boxfill>solid</boxfill><point x="0.2" y="0" z="0.15" /><size x="0.01" y="0" z="0" /></drawbox>
    <setmkbound mk="1" /><drawbox><boxfill>solid</boxfill><point x="0" y="0" z="0" /><size x="0.07" y="0" z="0.03" /></drawbox>
  </mainlist></commands></geometry>
</casedef>
<execution><special><vcpmsolids>
  <solid mkbound="1" density="7800" youngmod="2e8" poissratio="0.3">)" + loads + R"(</solid>
</vcpmsolids></special><parameters>
  <parameter key="TimeMax" value="0.01" /><parameter key="TimeOut" value="0.005" /><parameter key="Visco" value="0.01" />
  <simulationdomain><posmin x="default - 1" y="default" z="default - 1" /><posmax x="default + 1" y="default" z="default + 1" /></simulationdomain>
</parameters></execution></case>
)";
}

/// Total momentum of the solid particles (2D: per m of thickness).
physics::Double3 momentum(const test::SolverRun& r) {
    physics::Double3 p{0, 0, 0};
    const double m = 7800 * 0.01 * 0.01;
    for (const physics::Double3& v : r.state.solid_vel) {
        p.x += m * v.x;
        p.y += m * v.y;
        p.z += m * v.z;
    }
    return p;
}

}  // namespace

// Constant load (3, 0, -4) N plus a ramp (0, 0, 500) t on a corner: after T the momentum is
// F T + r T^2 / 2 exactly up to rounding; bond forces are equal and opposite in every pair.
TEST(SolidLoads, FreeBlockMomentumEqualsTheLoadImpulse) {
    const std::string dir = scratch("free");
    const std::string kase = test::generateCase(
        dir, "Block", freeBlock(R"(<pointload x="0.07" y="0" z="0.03" fx="3" fz="-4" /><pointload x="0" y="0" z="0" ratez="500" />)"));
    const test::SolverRun r = test::runCpu(kase, dir + "/out", 2);
    ASSERT_GT(r.summary.solid_substeps, 100);
    const double t = r.summary.physical_time;
    const physics::Double3 p = momentum(r);
    const double px = 3 * t, pz = -4 * t + 0.5 * 500 * t * t;
    std::printf("free block: T = %.6g s, %lld sub-steps, momentum (%.9g, %.3g, %.9g), expected (%.9g, 0, %.9g)\n", t,
                r.summary.solid_substeps, p.x, p.y, p.z, px, pz);
    EXPECT_NEAR(p.x, px, 1e-9 * std::fabs(px));
    EXPECT_NEAR(p.y, 0.0, 1e-15);
    EXPECT_NEAR(p.z, pz, 1e-9 * std::fabs(pz));
    // The block moved: the loads act on it (not only on the momentum sum).
    double disp = 0;
    for (std::uint32_t s = 0; s < r.state.solid_vel.size(); ++s) {
        const std::uint32_t id = std::uint32_t(r.kase.nfixed + r.kase.nmoving + s);
        disp = std::max(disp, std::fabs(r.state.pos[id].x - r.kase.particles.pos[id].x));
    }
    EXPECT_GT(disp, 1e-6);
}

TEST(SolidLoads, BadPointLoadIsAnInputError) {
    const std::string dir = scratch("bad");
    const std::string def = freeBlock(R"(<pointload x="0.07" y="0" z="0.03" fq="3" />)");
    try {
        test::generateCase(dir, "Bad", def);
        FAIL() << "gencase accepted an unknown <pointload> attribute";
    } catch (const Error& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("fq"), std::string::npos) << msg;
        EXPECT_NE(msg.find("Bad_Def.xml:"), std::string::npos) << msg;
    }
}

// tensilestrength sets the critical stretch of seed 000's Eq. A1; with critstretch too it is an
// error naming the line.
TEST(SolidLoads, TensileStrengthGivesTheSeedCriticalStretch) {
    const std::string dir = scratch("sigma");
    std::string def = freeBlock("");
    const std::string solid = R"(<solid mkbound="1" density="7800" youngmod="2e8" poissratio="0.3">)";
    def.replace(def.find(solid), solid.size(),
                R"(<solid mkbound="1" density="7800" youngmod="2e8" poissratio="0.3" tensilestrength="48e6">)");
    const std::string kase = test::generateCase(dir, "Sigma", def);
    const solver::SolverCase c = solver::loadSolverCase(kase);
    ASSERT_EQ(c.solids.size(), 1u);
    EXPECT_NEAR(c.solids[0].critstretch, 1.25 * 48e6 * 1.3 / (2 * 2e8), 1e-12);
    std::string both = def;
    both.replace(both.find("tensilestrength"), 0, "critstretch=\"0.01\" ");
    try {
        test::generateCase(dir, "Both", both);
        FAIL() << "gencase accepted critstretch and tensilestrength together";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("Both_Def.xml:"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("not both"), std::string::npos) << e.what();
    }
}

// A sub-step far beyond the lattice's stability limit (VcpmDtCoef 2 at nu = 0, limit 0.82)
// blows the solid up: the run stops with a blow-up diagnosis that blames VcpmDtCoef, without
// crashing.
TEST(SolidLoads, UnstableSolidStopsWithAClearError) {
    const std::string dir = scratch("unstable");
    std::string def = freeBlock(R"(<pointload x="0.07" y="0" z="0.03" fx="3" />)");
    const std::string solid = R"(poissratio="0.3")";
    def.replace(def.find(solid), solid.size(), R"(poissratio="0")");
    const std::string params = "<parameters>";
    def.replace(def.find(params), params.size(), params + R"(<parameter key="VcpmDtCoef" value="2" />)");
    const std::string kase = test::generateCase(dir, "Unstable", def);
    const test::SolverRun r = test::runCpu(kase, dir + "/out", 2, [](solver::RunOptions& o) { o.tmax = 0.03; });
    ASSERT_TRUE(r.summary.blowup.has_value()) << "an unstable solid ran to the end";
    EXPECT_EQ(r.summary.exit_code, 1);
    EXPECT_EQ(r.summary.blowup->likely_option.rfind("VcpmDtCoef (2", 0), 0u) << r.summary.blowup->likely_option;
}

// The solid fields of the part files and the XDMF series, on the breaking bar: damage is the
// lost fraction of a particle's bonds (0 where nothing broke), displacements are zero outside
// the solid.
TEST(SolidLoads, PartFilesCarryTheSolidFields) {
    const std::string dir = scratch("fields");
    const std::string kase = test::generateCaseFile(
        dir, "bar", std::string(SEASPRING_SOURCE_DIR) + "/cases/breaking_bar/BreakingBar_Def.xml");
    const test::SolverRun r = test::runCpu(kase, dir + "/out", 2, [](solver::RunOptions& o) {
        o.save_h5 = true;
        o.tmax = 0.05;
        o.tout = 0.025;
    });
    ASSERT_GT(r.summary.broken_bonds, 0u);
    const io::PartData d = io::readPartH5(dir + "/out/data/part_0002.h5");
    ASSERT_EQ(d.damage.size(), d.np());
    std::size_t damaged = 0;
    for (std::size_t i = 0; i < d.np(); ++i) {
        const bool solid = d.type[i] == std::uint8_t(ParticleType::Solid);
        EXPECT_GE(d.damage[i], 0.f);
        EXPECT_LE(d.damage[i], 1.f);
        EXPECT_EQ(d.broken[i] > 0, d.damage[i] > 0.f) << i;
        if (!solid) {
            EXPECT_EQ(d.disp[3 * i] + d.disp[3 * i + 1] + d.disp[3 * i + 2], 0.f) << i;
        }
        damaged += d.damage[i] > 0.f ? 1 : 0;
    }
    EXPECT_GT(damaged, 0u);
    std::ifstream x(dir + "/out/parts.xdmf");
    const std::string xdmf((std::istreambuf_iterator<char>(x)), std::istreambuf_iterator<char>());
    for (const char* name : {"disp", "strain", "broken", "damage"})
        EXPECT_NE(xdmf.find(std::string("Attribute Name=\"") + name + "\""), std::string::npos) << name;
}

// The coupling ledger's wall column: on the hydrostatic plate the plate and the walls together
// carry the water's weight (time mean over the column's acoustic period, 10-100 ms), closer
// than the plate alone; the horizontal wall forces cancel by symmetry.
TEST(SolidLoads, LedgerWallsAndPlateCarryTheWaterWeight) {
    const std::string dir = scratch("walls");
    const std::string kase = test::generateCaseFile(
        dir, "plate", std::string(SEASPRING_SOURCE_DIR) + "/cases/hydrostatic_plate/HydrostaticPlate_Def.xml", 0.025);
    const test::SolverRun r = test::runCpu(kase, dir + "/out", 2, [](solver::RunOptions& o) {
        o.tmax = 0.1;
        o.tout = 0.002;
    });
    const double weight = -9.81 * r.kase.constants.massfluid * r.kase.nfluid;  // N/m, negative
    std::ifstream in(dir + "/out/ledger.csv");
    std::string line;
    std::getline(in, line);
    std::vector<std::string> names;
    for (std::istringstream h(line); std::getline(h, line, ';');) names.push_back(line);
    auto column = [&](const std::string& n) { return std::size_t(std::find(names.begin(), names.end(), n) - names.begin()); };
    const std::size_t ct = column("time"), cp = column("force_z"), cw = column("wall_fz"), cx = column("wall_fx");
    ASSERT_LT(cx, names.size());
    double plate = 0, walls = 0, wx = 0;
    int rows = 0;
    while (std::getline(in, line)) {
        std::vector<double> v;
        std::string cell;
        for (std::istringstream s(line); std::getline(s, cell, ';');) v.push_back(std::stod(cell));
        if (v[ct] < 0.01) continue;
        plate += v[cp];
        walls += v[cw];
        wx = std::max(wx, std::fabs(v[cx]));
        ++rows;
    }
    ASSERT_GT(rows, 20);
    plate /= rows;
    walls /= rows;
    std::printf("plate %.1f N/m, walls %.1f N/m, together %.4f of the water weight %.1f N/m; |wall Fx| <= %.3g\n",
                plate, walls, (plate + walls) / weight, weight, wx);
    EXPECT_LT(walls, 0.0);  // the side walls carry part of the column through the corners
    EXPECT_NEAR((plate + walls) / weight, 1.0, 0.02);
    EXPECT_LT(std::fabs((plate + walls) / weight - 1.0), std::fabs(plate / weight - 1.0));
    EXPECT_LT(wx, 1e-3 * std::fabs(weight));
}
