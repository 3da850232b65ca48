// SeaSpring — MIT licence.
/// \file test_solver_parity.cpp
/// \brief Bit-identity across OpenMP thread counts and repeat runs, for every physics option
///        family, in 2D and 3D, with a moving boundary; and hashes that do change when the
///        physics changes (so the comparison can fail).
#include <gtest/gtest.h>

#include <string>

#include "solver/cell_switch.h"
#include "solver/grid_origin.h"
#include "solver_test_util.h"

using namespace seaspring;

namespace {

std::string scratch(const std::string& tag) { return test::scratch("parity_" + tag); }

/// A 2D tank (0.6 x 0.4 m) with a water column 0.2 x 0.2 m and a piston (mkbound 1) moving
/// right at 0.2 m/s, dp = 0.01.
std::string tank2d(const std::string& params) {
    return R"(<?xml version="1.0" encoding="UTF-8" ?>
<case><casedef>
  <constantsdef><gravity x="0" y="0" z="-9.81" /><rhop0 value="1000" /><hswl value="0" auto="true" />
    <gamma value="7" /><speedsystem value="0" auto="true" /><coefsound value="20" />
    <speedsound value="0" auto="true" /><coefh value="1.0" /><cflnumber value="0.2" /></constantsdef>
  <mkconfig boundcount="240" fluidcount="9" />
  <geometry><definition dp="0.01"><pointmin x="-0.05" y="0" z="-0.05" /><pointmax x="0.7" y="0" z="0.5" /></definition>
  <commands><mainlist>
    <setdrawmode mode="full" />
    <setmkfluid mk="0" /><drawbox><boxfill>solid</boxfill><point x="0.05" y="-1" z="0" /><size x="0.2" y="2" z="0.2" /></drawbox>
    <setmkbound mk="0" /><drawbox><boxfill>bottom | left | right</boxfill><point x="0" y="-1" z="0" /><size x="0.6" y="2" z="0.4" /><layers vdp="0,1" /></drawbox>
    <setmkbound mk="1" /><drawbox><boxfill>solid</boxfill><point x="0.02" y="-1" z="0.02" /><size x="0.01" y="2" z="0.25" /></drawbox>
  </mainlist></commands></geometry>
  <motion><objreal ref="1"><begin mov="1" start="0" /><mvrect id="1" duration="10"><vel x="0.2" y="0" z="0" /></mvrect></objreal></motion>
</casedef>
<execution><parameters>)" + params + R"(
  <parameter key="TimeMax" value="1" /><parameter key="TimeOut" value="0.1" />
</parameters></execution></case>
)";
}

struct Variant {
    const char* name;
    const char* params;
};

const Variant kVariants[] = {
    {"sym_wendland_art_ddt3",
     R"(<parameter key="StepAlgorithm" value="2" /><parameter key="Kernel" value="2" /><parameter key="ViscoTreatment" value="1" /><parameter key="Visco" value="0.05" /><parameter key="DensityDT" value="3" />)"},
    {"verlet_cubic_lam_ddt1",
     R"(<parameter key="StepAlgorithm" value="1" /><parameter key="VerletSteps" value="7" /><parameter key="Kernel" value="1" /><parameter key="ViscoTreatment" value="3" /><parameter key="Visco" value="1e-6" /><parameter key="DensityDT" value="1" />)"},
    {"sym_wendland_sps_ddt2",
     R"(<parameter key="StepAlgorithm" value="2" /><parameter key="Kernel" value="2" /><parameter key="ViscoTreatment" value="2" /><parameter key="Visco" value="1e-6" /><parameter key="DensityDT" value="2" /><parameter key="ViscoBoundFactor" value="0.5" />)"},
};

}  // namespace

TEST(SolverParity, ThreadCountsGiveIdenticalHashes2D) {
    for (const Variant& v : kVariants) {
        const std::string dir = scratch(v.name);
        const std::string kase = test::generateCase(dir, "tank", tank2d(v.params));
        auto steps = [](solver::RunOptions& o) { o.nsteps = 60; };
        const auto r1 = test::runCpu(kase, dir + "/out1", 1, steps);
        const auto r2 = test::runCpu(kase, dir + "/out2", 2, steps);
        const auto r1b = test::runCpu(kase, dir + "/out1b", 1, steps);
        EXPECT_EQ(r1.summary.steps, 60) << v.name;
        EXPECT_EQ(r1.summary.state_hash, r2.summary.state_hash) << v.name;
        EXPECT_EQ(r1.summary.state_hash, r1b.summary.state_hash) << v.name;
        EXPECT_EQ(r1.summary.dtmin_hits, 0) << v.name;
        // The piston moved (prescribed motion reached the particles).
        const std::uint32_t first_moving = r1.kase.nfixed;
        ASSERT_GT(r1.kase.nmoving, 0u);
        const double x0 = r1.kase.particles.pos[first_moving].x;
        EXPECT_NEAR(r1.state.pos[first_moving].x - x0, 0.2 * r1.summary.physical_time, 1e-9) << v.name;
        EXPECT_NEAR(r1.state.velrho[first_moving].x, 0.2f, 1e-5) << v.name;
    }
}

// LaminarLatticeCorrection (default 1): the run's laminar nu (fluid and boundary neighbours) is
// the case's divided by physics::laminarLatticeRatio of its kernel, h/dp and dimension
// (tests/unit/test_viscosity_channels.cpp shows what that buys); 0 keeps the case's nu, and the
// artificial viscosity's alpha is never scaled.
TEST(SolverParity, LaminarLatticeCorrectionScalesOnlyTheLaminarNu) {
    const std::string lam = R"(<parameter key="StepAlgorithm" value="2" /><parameter key="Kernel" value="2" /><parameter key="ViscoTreatment" value="3" /><parameter key="Visco" value="1e-6" /><parameter key="ViscoBoundFactor" value="2" /><parameter key="DensityDT" value="0" />)";
    auto setupOf = [](const std::string& tag, const std::string& params) {
        const std::string dir = scratch("latcorr_" + tag);
        const solver::SolverCase c = solver::loadSolverCase(test::generateCase(dir, "tank", tank2d(params)));
        return std::make_pair(solver::makeBackendSetup(c, 0, 0.05), c);
    };
    const auto [on, c] = setupOf("on", lam);
    const double ratio = physics::laminarLatticeRatio(physics::KernelType::Wendland, c.constants.h, c.constants.dp, 2);
    EXPECT_GT(ratio, 0.97);
    EXPECT_LT(ratio, 0.999);
    EXPECT_EQ(on.fluid.visco, float(1e-6 / ratio));
    EXPECT_EQ(on.fluid.visco_bound, float(1e-6 / ratio * 2.0));
    const auto off = setupOf("off", lam + R"(<parameter key="LaminarLatticeCorrection" value="0" />)").first;
    EXPECT_EQ(off.fluid.visco, float(1e-6));
    EXPECT_EQ(off.fluid.visco_bound, float(2e-6));
    const auto art = setupOf("art", kVariants[0].params).first;
    EXPECT_EQ(art.fluid.visco, float(0.05));
}

TEST(SolverParity, HashesDifferBetweenPhysicsOptions) {
    std::string first;
    for (const Variant& v : kVariants) {
        const std::string dir = scratch(std::string("diff_") + v.name);
        const std::string kase = test::generateCase(dir, "tank", tank2d(v.params));
        const auto r = test::runCpu(kase, dir + "/out", 2, [](solver::RunOptions& o) { o.nsteps = 10; });
        if (first.empty()) first = r.summary.state_hash;
        else EXPECT_NE(r.summary.state_hash, first) << v.name;
    }
}

TEST(SolverParity, ThreadCountsGiveIdenticalHashes3D) {
    const std::string dir = scratch("db3d");
    const std::string kase = test::generateCaseFile(
        dir, "db", std::string(SEASPRING_SOURCE_DIR) + "/cases/dambreak3d/DamBreak3D_Def.xml", 0.04);
    auto steps = [](solver::RunOptions& o) { o.nsteps = 25; };
    const auto r1 = test::runCpu(kase, dir + "/out1", 1, steps);
    const auto r2 = test::runCpu(kase, dir + "/out2", 2, steps);
    EXPECT_EQ(r1.summary.state_hash, r2.summary.state_hash);
    EXPECT_GT(r1.summary.physical_time, 0.0);
    // Cells of 2h instead of h change the summation order, not the physics: the hash differs
    // but the state stays close.
    const auto r3 = test::runCpu(kase, dir + "/out3", 2, [](solver::RunOptions& o) {
        o.nsteps = 25;
        o.cell_div = 1;
    });
    EXPECT_NE(r3.summary.state_hash, r1.summary.state_hash);
    double maxdiff = 0;
    for (std::size_t i = 0; i < r1.state.pos.size(); ++i)
        maxdiff = std::max(maxdiff, std::abs(r1.state.pos[i].z - r3.state.pos[i].z));
    EXPECT_LT(maxdiff, 1e-5);
    EXPECT_NE(r1.summary.options.find("cells of dp"), std::string::npos) << r1.summary.options;  // 1.5 dp < h < 2 dp
}

// The cells' switch (solver/cell_switch.h): the 3D dam break's cells of dp go over to cells of h
// once 5% of its fluid shares its cells (at step 188 of 250), at the same divide with 1 and 2
// threads and with the same bits after it; without the switch (-cellswitch:0) the hash differs
// (the neighbour order) and the state stays close.
TEST(SolverParity, CellSwitchKeepsThreadCountsIdentical) {
    const std::string dir = scratch("switch");
    const std::string kase = test::generateCaseFile(
        dir, "db", std::string(SEASPRING_SOURCE_DIR) + "/cases/dambreak3d/DamBreak3D_Def.xml", 0.04);
    auto run = [&](const std::string& out, int threads, double fraction) {
        return test::runCpu(kase, dir + "/" + out, threads, [fraction](solver::RunOptions& o) {
            o.nsteps = 250;
            o.cell_switch = fraction;
        });
    };
    const auto r1 = run("out1", 1, 0.05), r2 = run("out2", 2, 0.05), r0 = run("out0", 2, 0.0);
    EXPECT_GT(r1.summary.cell_switch_divide, 0u);
    EXPECT_LT(r1.summary.cell_switch_divide, 480u);
    EXPECT_EQ(r1.summary.cell_switch_divide, r2.summary.cell_switch_divide);
    EXPECT_GT(r1.summary.cell_switch_time, 0.0);
    EXPECT_EQ(r1.summary.state_hash, r2.summary.state_hash);
    EXPECT_NE(r1.summary.options.find("cells of dp with a skin of 0.25 cell (h once 0.05 of the fluid shares them)"),
              std::string::npos)
        << r1.summary.options;
    EXPECT_EQ(r0.summary.cell_switch_divide, 0u);
    EXPECT_EQ(r0.summary.options.find("h once"), std::string::npos) << r0.summary.options;
    EXPECT_NE(r0.summary.state_hash, r1.summary.state_hash);
    double maxdiff = 0;
    for (std::size_t i = 0; i < r1.state.pos.size(); ++i)
        maxdiff = std::max(maxdiff, std::abs(r1.state.pos[i].z - r0.state.pos[i].z));
    EXPECT_LT(maxdiff, 1e-5);
    // Where it does not apply: 2D, an explicit cell mode, cells of h/2 (h = 2 dp).
    EXPECT_EQ(solver::resolveCellSwitch(r1.kase, 0, 0.3), 0.3);
    EXPECT_EQ(solver::resolveCellSwitch(r1.kase, physics::kCellDivSpacing, 0.3), 0.0);
    EXPECT_EQ(solver::resolveCellSwitch(r1.kase, 0, 0.0), 0.0);
    solver::SolverCase fat = r1.kase;
    fat.constants.h = 2.0 * fat.constants.dp;
    EXPECT_EQ(solver::resolveCellSwitch(fat, 0, 0.3), 0.0);
    const auto flat = test::runCpu(test::generateCase(dir, "tank", tank2d(kVariants[0].params)), dir + "/o2d", 1,
                                   [](solver::RunOptions& o) { o.nsteps = 1; });
    EXPECT_EQ(solver::resolveCellSwitch(flat.kase, 0, 0.3), 0.0);
}

// h = 2 dp (SPHERIC Test 2's choice) and cells of h/2 = dp: the cell grid starts half a spacing
// below the fluid's lattice (solver/grid_origin.h). Thread counts still give the same bits, and
// the run stays close to one with the lattice on the cell faces (cells of 2h/3, from the
// domain's minimum): only the rounding of the cell-relative positions and the summation order differ.
TEST(SolverParity, ThreadCountsGiveIdenticalHashesOnALatticeCentredGrid) {
    const std::string dir = scratch("centred");
    std::string def = test::readFile(std::string(SEASPRING_SOURCE_DIR) + "/cases/dambreak3d/DamBreak3D_Def.xml");
    const std::string coefh = "<coefh value=\"1.0\"";
    const std::size_t at = def.find(coefh);
    ASSERT_NE(at, std::string::npos);
    def.replace(at, coefh.size(), "<hdp value=\"2\"");
    const std::string kase = test::generateCase(dir, "db", def, 0.04);
    auto steps = [](solver::RunOptions& o) { o.nsteps = 25; };
    const auto r1 = test::runCpu(kase, dir + "/out1", 1, steps);
    const auto r2 = test::runCpu(kase, dir + "/out2", 2, steps);
    ASSERT_NEAR(r1.kase.constants.h, 2.0 * r1.kase.constants.dp, 1e-12);
    EXPECT_NE(r1.summary.options.find("cells of h/2"), std::string::npos) << r1.summary.options;
    const solver::GridOrigin o = solver::latticeCentredGridOrigin(r1.kase, r1.kase.constants.dp);
    EXPECT_TRUE(o.centred[0] && o.centred[1] && o.centred[2]);
    EXPECT_EQ(r1.summary.state_hash, r2.summary.state_hash);
    const auto r3 = test::runCpu(kase, dir + "/out3", 2, [](solver::RunOptions& o) {
        o.nsteps = 25;
        o.cell_div = 3;
    });
    EXPECT_FALSE(solver::latticeCentredGridOrigin(r3.kase, 2.0 * r3.kase.constants.h / 3.0).any());
    EXPECT_NE(r3.summary.state_hash, r1.summary.state_hash);
    double maxdiff = 0;
    for (std::size_t i = 0; i < r1.state.pos.size(); ++i)
        maxdiff = std::max(maxdiff, std::abs(r1.state.pos[i].z - r3.state.pos[i].z));
    EXPECT_LT(maxdiff, 1e-5);
}

// -cellmode:auto: in 3D cells of h/2, or of dp where h/2 would be narrower and 2h/3 wider than dp,
// or 2h/3, and h in 2D,
// coarser when the grid would be too large for the particles; explicit modes pass through.
TEST(SolverParity, AutoCellModeFollowsDimensionAndGridSize) {
    const std::string dir = scratch("autocells");
    const auto r3d = test::runCpu(test::generateCaseFile(dir, "db", std::string(SEASPRING_SOURCE_DIR) +
                                                                        "/cases/dambreak3d/DamBreak3D_Def.xml", 0.04),
                                  dir + "/o3", 1, [](solver::RunOptions& o) { o.nsteps = 1; });
    const auto r2d = test::runCpu(test::generateCase(dir, "tank", tank2d(kVariants[0].params)), dir + "/o2", 1,
                                  [](solver::RunOptions& o) { o.nsteps = 1; });
    EXPECT_NEAR(r3d.kase.constants.h / r3d.kase.constants.dp, std::sqrt(3.0), 1e-9);  // coefh 1
    EXPECT_EQ(solver::resolveCellDiv(r3d.kase, 0), physics::kCellDivSpacing);  // h/2 = 0.87 dp, 2h/3 = 1.15 dp: dp
    EXPECT_EQ(solver::resolveCellDiv(r2d.kase, 0), 2);
    EXPECT_EQ(solver::resolveCellDiv(r3d.kase, 2), 2);
    EXPECT_EQ(solver::resolveCellDiv(r3d.kase, 4), 4);
    EXPECT_EQ(solver::resolveCellDiv(r2d.kase, 3), 3);
    solver::SolverCase fat = r3d.kase;  // h = 2 dp (SPHERIC Test 2's): h/2 = dp
    fat.constants.h = 2.0 * fat.constants.dp;
    EXPECT_EQ(solver::resolveCellDiv(fat, 0), 4);
    fat.constants.h = 1.99 * fat.constants.dp;
    EXPECT_EQ(solver::resolveCellDiv(fat, 0), physics::kCellDivSpacing);
    fat.constants.h = 1.5 * fat.constants.dp;  // 2h/3 = dp (the 3D sluice gate's): 2h/3
    EXPECT_EQ(solver::resolveCellDiv(fat, 0), 3);
    fat.constants.h = 1.4 * fat.constants.dp;  // 2h/3 < dp too: still 2h/3
    EXPECT_EQ(solver::resolveCellDiv(fat, 0), 3);
    // -cellmode:dp where 2h spans more than 8 spacings (the near flags' window): an error
    // naming the option and the values, not a grid that misses neighbours.
    solver::SolverCase wide_h = r3d.kase;
    wide_h.constants.h = 4.5 * wide_h.constants.dp;
    try {
        (void)solver::makeBackendSetup(wide_h, physics::kCellDivSpacing, 0.05);
        ADD_FAILURE() << "-cellmode:dp with h = 4.5 dp was accepted";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("-cellmode:dp needs dp <= 2h <= 8 dp"), std::string::npos) << e.what();
    }
    fat.constants.h = 2.0 * fat.constants.dp;
    // The same particles in a domain 150 times longer: h/2 cells exceed 16 per particle + 2^20.
    solver::SolverCase wide = fat;
    wide.domain_max.x = wide.domain_min.x + 150.0 * (wide.domain_max.x - wide.domain_min.x);
    const int d = solver::resolveCellDiv(wide, 0);
    EXPECT_LT(d, 4);
    physics::CellGrid g;
    ASSERT_TRUE(physics::makeCellGrid(wide.domain_min.x, wide.domain_min.y, wide.domain_min.z, wide.domain_max.x,
                                      wide.domain_max.y, wide.domain_max.z, wide.constants.h, d, g));
    EXPECT_LE(double(g.cellCount()), 16.0 * double(wide.particles.size()) + 1048576.0);
}

// The default skin follows the case's size (resolveSkin): 0.25 of a cell below 262,144
// particles, 0.05 from there; -skin wins over both; the run's physics line says which.
TEST(SolverParity, DefaultSkinFollowsTheCaseSize) {
    const std::string dir = scratch("autoskin");
    const auto r = test::runCpu(test::generateCase(dir, "tank", tank2d(kVariants[0].params)), dir + "/o", 1,
                                [](solver::RunOptions& o) { o.nsteps = 1; });
    solver::RunOptions o;
    ASSERT_LT(r.kase.particles.size(), solver::kSmallRunParticles);
    EXPECT_EQ(solver::resolveSkin(r.kase, o), solver::kSmallRunSkinFraction);
    EXPECT_EQ(solver::kSmallRunSkinFraction, 0.25);
    EXPECT_NE(r.summary.options.find("with a skin of 0.25 cell"), std::string::npos) << r.summary.options;
    solver::SolverCase large = r.kase;
    large.particles.resize(solver::kSmallRunParticles);  // only the count is read
    EXPECT_EQ(solver::resolveSkin(large, o), physics::kDefaultSkinFraction);
    large.particles.resize(solver::kSmallRunParticles - 1);
    EXPECT_EQ(solver::resolveSkin(large, o), solver::kSmallRunSkinFraction);
    for (double f : {0.0, 0.05, 0.4}) {
        o.skin = f;
        EXPECT_EQ(solver::resolveSkin(r.kase, o), f);
        EXPECT_EQ(solver::resolveSkin(large, o), f);
    }
}

// DtAllParticles = 1: a piston moving at 5 m/s (10 |v| = 50 m/s above c0 = 28 m/s) limits the
// time step to CFL h / (10 |v|); with 0 only the fluid's velocities count.
TEST(SolverParity, DtAllParticlesLetsMovingWallsLimitTheTimeStep) {
    std::string def = tank2d(R"(<parameter key="StepAlgorithm" value="2" /><parameter key="Visco" value="0.05" />)");
    const std::string slow = R"(<vel x="0.2" y="0" z="0" />)";
    def.replace(def.find(slow), slow.size(), R"(<vel x="5" y="0" z="0" />)");
    std::string all = def;
    const std::string params = "<execution><parameters>";
    all.replace(all.find(params), params.size(), params + R"(<parameter key="DtAllParticles" value="1" />)");
    const std::string dir = scratch("dtall");
    auto steps = [](solver::RunOptions& o) { o.nsteps = 5; };
    const auto r0 = test::runCpu(test::generateCase(dir, "fluid", def), dir + "/out0", 2, steps);
    const auto r1 = test::runCpu(test::generateCase(dir, "all", all), dir + "/out1", 2, steps);
    const double h = r1.kase.constants.h, cfl = r1.kase.params.cfl_number;
    std::printf("dt fluid-only %.4e s, all particles %.4e s, CFL h/(10*5 m/s) = %.4e s\n", r0.summary.dt_last,
                r1.summary.dt_last, cfl * h / 50.0);
    EXPECT_GT(r0.summary.dt_last, 1.3 * r1.summary.dt_last);
    EXPECT_NEAR(r1.summary.dt_last, cfl * h / 50.0, 0.05 * cfl * h / 50.0);
}

// The SPS stress reaches the run: laminar+SPS and laminar alone, otherwise alike, end in
// different states (the stress is computed in the dt reduction's launch, DtMaximaPass<true>;
// with that call left out, the two runs gave one hash: checked).
TEST(SolverParity, SpsStressChangesTheRun) {
    const std::string common = R"(<parameter key="StepAlgorithm" value="2" /><parameter key="Kernel" value="2" /><parameter key="Visco" value="1e-6" /><parameter key="DensityDT" value="0" />)";
    std::string hash[2];
    for (int sps = 0; sps < 2; ++sps) {
        const std::string dir = scratch(std::string("sps_wired_") + char('0' + sps));
        const std::string kase = test::generateCase(
            dir, "tank", tank2d(common + (sps ? R"(<parameter key="ViscoTreatment" value="2" />)"
                                              : R"(<parameter key="ViscoTreatment" value="3" />)")));
        hash[sps] = test::runCpu(kase, dir + "/out", 2, [](solver::RunOptions& o) { o.nsteps = 20; }).summary.state_hash;
    }
    EXPECT_NE(hash[0], hash[1]);
}

// Pair lanes (-pairlanes, physics/fluid_interaction.h): a fluid particle's sums split over N
// partial sums added pairwise at the end. Only the rounding changes: the hash differs between
// lane counts, the state stays close to one lane's. -pairlanes:0 (auto) gives this small case
// (400 fluid particles) the most lanes auto takes, 4. Thread counts with lanes:
// ThreadCountsGiveIdenticalHashes2D (auto lanes).
TEST(SolverParity, PairLanesChangeOnlyTheSummationOrder) {
    for (int v : {0, 2}) {  // artificial + DDT 3; laminar+SPS + DDT 2
        const std::string dir = scratch(std::string("lanes_") + kVariants[v].name);
        const std::string kase = test::generateCase(dir, "tank", tank2d(kVariants[v].params));
        auto with = [&](int lanes, int threads, const std::string& tag) {
            return test::runCpu(kase, dir + "/" + tag, threads, [lanes](solver::RunOptions& o) {
                o.nsteps = 60;
                o.pair_lanes = lanes;
            });
        };
        const auto one = with(1, 2, "l1"), eight = with(8, 2, "l8"), autol = with(0, 1, "auto"), four = with(4, 2, "l4");
        EXPECT_EQ(autol.summary.state_hash, four.summary.state_hash) << kVariants[v].name;
        EXPECT_NE(autol.summary.options.find("4 pair lanes"), std::string::npos) << autol.summary.options;
        EXPECT_EQ(one.summary.options.find("pair lanes"), std::string::npos) << one.summary.options;
        EXPECT_NE(one.summary.state_hash, eight.summary.state_hash) << kVariants[v].name;
        EXPECT_NE(four.summary.state_hash, eight.summary.state_hash) << kVariants[v].name;
        double dpos = 0, dvel = 0, vmax = 0;
        for (std::size_t i = one.kase.nfixed + one.kase.nmoving; i < one.state.pos.size(); ++i) {
            dpos = std::max({dpos, std::abs(one.state.pos[i].x - eight.state.pos[i].x),
                             std::abs(one.state.pos[i].z - eight.state.pos[i].z)});
            dvel = std::max({dvel, double(std::abs(one.state.velrho[i].x - eight.state.velrho[i].x)),
                             double(std::abs(one.state.velrho[i].z - eight.state.velrho[i].z))});
            vmax = std::max({vmax, double(std::abs(one.state.velrho[i].x)), double(std::abs(one.state.velrho[i].z))});
        }
        std::printf("%s: 1 against 8 lanes after 60 steps: max |dx| %.3g m, max |dv| %.3g m/s (max |v| %.3g)\n",
                    kVariants[v].name, dpos, dvel, vmax);
        EXPECT_LT(dpos, 1e-7) << kVariants[v].name;
        EXPECT_LT(dvel, 1e-4 * vmax) << kVariants[v].name;
    }
}
