// SeaSpring — MIT licence.
/// \file test_gauges.cpp
/// \brief `<special><gauges>`: every gauge kind on still water (hydrostatic pressure, zero
///        velocity, the free surface, the top particle, the weight on the tank), thread
///        parity of the CSV files, the solid marker against the final state, the swl surface
///        rule on hand values, and the error paths (file, line and value named).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../unit/error_expect.h"
#include "physics/gauges.h"
#include "solver_test_util.h"

using namespace seaspring;

namespace {

/// The rows of a gauge CSV (header checked), as numbers.
std::vector<std::vector<double>> readCsv(const std::string& path, const std::string& header) {
    std::ifstream f(path);
    std::string line;
    EXPECT_TRUE(std::getline(f, line)) << path;
    EXPECT_EQ(line, header) << path;
    std::vector<std::vector<double>> rows;
    while (std::getline(f, line)) {
        std::vector<double> row;
        std::stringstream s(line);
        std::string item;
        while (std::getline(s, item, ';')) row.push_back(std::stod(item));
        rows.push_back(row);
    }
    return rows;
}

/// The still tank of tests/data/gauges/StillTank_Def.xml (2D, 0.4 m wide, water 0.2 m deep,
/// dp 0.01, one gauge of every fluid kind) with its <gauges> replaced by `gauges` when given.
std::string stillTank(const std::string& gauges = "") {
    std::string xml = test::readFile(std::string(SEASPRING_TEST_DATA_DIR) + "/gauges/StillTank_Def.xml");
    if (gauges.empty()) return xml;
    const std::size_t a = xml.find("<gauges>"), b = xml.find("</gauges>");
    EXPECT_TRUE(a != std::string::npos && b != std::string::npos);
    return xml.replace(a, b + 9 - a, gauges);
}

}  // namespace

/// Tolerances: pressure within 5% of rho0 g (z_top - z) (z_top: the top particle centre, as
/// test_fluid_accuracy); |v| < 0.03 sqrt(g H); the surface within one dp of z_top + dp/2; maxz
/// equal to the highest fluid particle within 2 dp of the line (exact); the tank carries the
/// water's weight within 3% (the plate + wall check of the ledger measured 1.003).
TEST(Gauges, StillWaterEveryKind) {
    const std::string dir = test::scratch("gauges_still");
    const std::string kase = test::generateCase(dir, "tank", stillTank());
    const auto r = test::runCpu(kase, dir + "/out", 2);
    const auto& c = r.kase;
    ASSERT_EQ(c.gauges.gauges.size(), 6u);  // "_velocity" is disabled
    const std::string g = dir + "/out/gauges/";
    double ztop = 0, zline = -1;
    for (std::size_t i = c.nfixed; i < c.particles.size(); ++i) {
        const auto& p = r.state.pos[i];
        ztop = std::max(ztop, p.z);
        if (std::abs(p.x - 0.2) <= 0.02) zline = std::max(zline, p.z);
    }
    const double rho0 = c.constants.rhop0, grav = 9.81, dp = 0.01;

    // Every step (computedt 0), averaged over 0.1-0.3 s: the acoustic oscillation of the
    // weakly-compressible column (period ~4H/c0 = 0.03 s) swings single samples by +-25%.
    const auto p = readCsv(g + "GaugesPress_P.csv", "time;press;posx;posy;posz;wsum");
    ASSERT_EQ(p.size(), std::size_t(r.summary.steps + 1));
    EXPECT_EQ(p[0][0], 0.0);
    double pmean = 0;
    int np = 0;
    for (const auto& row : p)
        if (row[0] >= 0.1) pmean += row[1], ++np;
    pmean /= np;
    EXPECT_NEAR(pmean, rho0 * grav * (ztop - 0.05), 0.05 * rho0 * grav * (ztop - 0.05));
    EXPECT_NEAR(p.back()[5], 1.0, 0.02) << "sum V W inside the fluid";
    const auto out = readCsv(g + "GaugesPress_Out.csv", "time;press;posx;posy;posz;wsum");
    EXPECT_EQ(out.back()[1], 0.0) << "a point outside the domain measures nothing";
    EXPECT_EQ(out.back()[5], 0.0);

    const auto v = readCsv(g + "GaugesVel_V.csv", "time;velx;vely;velz;posx;posy;posz;wsum");
    EXPECT_LT(std::hypot(v.back()[1], v.back()[3]), 0.03 * std::sqrt(grav * 0.2));

    const auto s = readCsv(g + "GaugesSwl_S.csv", "time;swlx;swly;swlz;pos0x;pos0y;pos0z;pos2x;pos2y;pos2z");
    EXPECT_NEAR(s.back()[3], ztop + 0.5 * dp, dp);
    EXPECT_EQ(s.back()[1], 0.2);

    const auto z = readCsv(g + "GaugesMaxZ_Z.csv", "time;zmax;posx;posy;posz");
    EXPECT_NEAR(z.back()[1], zline, 1e-8);

    const auto f = readCsv(g + "GaugesForce_Tank.csv", "time;forcex;forcey;forcez");
    ASSERT_EQ(f.size(), 4u);
    const double weight = double(c.nfluid) * c.constants.massfluid * grav;
    EXPECT_NEAR(f.back()[3], -weight, 0.03 * weight) << "the fluid pushes the tank down with its weight";
    EXPECT_NEAR(f.back()[1], 0.0, 0.01 * weight) << "the side walls' pushes cancel";
    EXPECT_EQ(v.size(), 16u);  // t = 0, 0.02, ..., 0.3
    EXPECT_EQ(r.summary.gauge_rows, 16 * 4 + 4 + (r.summary.steps + 1));
}

/// The CSV files are the same bytes with 1 and 2 threads (the sums run in neighbour order).
TEST(Gauges, ThreadParityOfTheFiles) {
    const std::string dir = test::scratch("gauges_parity");
    const std::string kase = test::generateCase(dir, "tank", stillTank());
    auto tweak = [](solver::RunOptions& o) { o.tmax = 0.06; };
    test::runCpu(kase, dir + "/t1", 1, tweak);
    test::runCpu(kase, dir + "/t2", 2, tweak);
    for (const char* name : {"GaugesPress_P.csv", "GaugesVel_V.csv", "GaugesSwl_S.csv", "GaugesMaxZ_Z.csv",
                             "GaugesForce_Tank.csv"}) {
        const std::string a = test::readFile(dir + "/t1/gauges/" + name);
        EXPECT_FALSE(a.empty()) << name;
        EXPECT_EQ(a, test::readFile(dir + "/t2/gauges/" + name)) << name;
    }
}

/// The marker follows the solid particle nearest to its point: its last row is that particle's
/// final position and its displacement from the start (breaking bar, 20 ms).
TEST(Gauges, SolidMarkerFollowsItsParticle) {
    const std::string dir = test::scratch("gauges_marker");
    const std::string xml = test::replaceOnce(test::readFile(test::caseDef("breaking_bar/BreakingBar_Def.xml")),
                                              "<vcpmsolids>", R"(<gauges><default><output value="true" /></default>
      <solidmarker name="End"><computedt value="0.005" /><point x="10" y="0" z="0" /></solidmarker></gauges>
      <vcpmsolids>)");
    const std::string kase = test::generateCase(dir, "bar", xml);
    const auto r = test::runCpu(kase, dir + "/out", 2, [](solver::RunOptions& o) { o.tmax = 0.02; });
    const auto m = readCsv(dir + "/out/gauges/GaugesMarker_End.csv", "time;posx;posy;posz;dispx;dispy;dispz");
    ASSERT_EQ(m.size(), 5u);
    // The nearest solid particle to a far point in +x: the largest x, lowest id among ties.
    const auto& c = r.kase;
    std::uint32_t best = 0;
    double bx = -1e300, bd = 1e300;
    for (std::uint32_t i = 0; i < c.particles.size(); ++i) {
        if (c.particles.type[i] != ParticleType::Solid) continue;
        const auto& q = c.particles.pos[i];
        const double d = (q.x - 10) * (q.x - 10) + q.y * q.y + q.z * q.z;
        if (d < bd) bd = d, best = i, bx = q.x;
    }
    ASSERT_GT(bx, -1e300);
    const auto& fin = r.state.pos[best];
    EXPECT_NEAR(m.back()[1], fin.x, 1e-9);
    EXPECT_NEAR(m.back()[3], fin.z, 1e-9);
    EXPECT_NEAR(m.back()[6], fin.z - c.particles.pos[best].z, 1e-7);
    EXPECT_LT(m.back()[6], 0.0) << "the bar sags under gravity";
    EXPECT_EQ(m[0][6], 0.0);
}

/// JGaugeSwl's rule on hand values: masses 1, 1, 0.6, 0.2 with limit 0.4 cross between points
/// 2 and 3 at s = 2 + (0.4-0.6)/(0.2-0.6) = 2.5; all above: the last point; none: point0.
TEST(Gauges, SwlSurfaceRule) {
    const physics::Double3 p0{0, 0, 1}, dir{0, 0, 0.1};
    const double m1[] = {1, 1, 0.6, 0.2};
    EXPECT_DOUBLE_EQ(physics::swlSurface(m1, 4, p0, dir, 0.4).z, 1.25);
    const double m2[] = {1, 1, 1};
    EXPECT_DOUBLE_EQ(physics::swlSurface(m2, 3, p0, dir, 0.4).z, 1.2);
    const double m3[] = {0, 0.1, 0};
    EXPECT_DOUBLE_EQ(physics::swlSurface(m3, 3, p0, dir, 0.4).z, 1.0);
    EXPECT_DOUBLE_EQ(physics::shepard(2.0, 0.5, 0.5), 4.0);
    EXPECT_DOUBLE_EQ(physics::shepard(2.0, 0.4, 0.5), 0.0);
}

/// Bad gauge definitions stop gencase with the file, line and value.
TEST(Gauges, ErrorsNameFileLineAndValue) {
    const std::string dir = test::scratch("gauges_errors");
    struct Bad {
        const char* gauges;
        const char* part;
    };
    const Bad bad[] = {
        {R"(<gauges><mesh name="M" /></gauges>)", "is not a gauge SeaSpring supports"},
        {R"(<gauges><velocity name="V" /></gauges>)", "<point>"},
        {R"(<gauges><velocity name="V"><point x="0.2" y="0" z="0.1" /></velocity><pressure name="V"><point x="0.2" y="0" z="0.1" /></pressure></gauges>)",
         "name=\"V\" is used by another gauge"},
        {R"(<gauges><velocity name="a/b"><point x="0.2" y="0" z="0.1" /></velocity></gauges>)", "name=\"a/b\""},
        {R"(<gauges><force name="F"><target mkbound="7" /></force></gauges>)", "target mkbound=7 has no boundary particles"},
        {R"(<gauges><solidmarker name="M"><point x="0" y="0" z="0" /></solidmarker></gauges>)", "has no VCPM solid"},
        {R"(<gauges><swl name="S"><point0 x="0" y="0" z="0" /><point2 x="0" y="0" z="0" /></swl></gauges>)",
         "point0 and point2 are the same point"},
        {R"(<gauges><maxz name="Z"><point0 x="0" y="0" z="0" /><height value="0.3" /><distlimit value="-1" /></maxz></gauges>)",
         "value=\"-1\": the length must be > 0"},
        {R"(<gauges><default><computedt value="-0.1" /></default></gauges>)", "value=\"-0.1\": must be >= 0"},
        {R"(<gauges><velocity name="V"><point x="0.2" y="0" z="0.1" /><computetime start="1" end="0.5" /></velocity></gauges>)",
         "is before start"},
    };
    int k = 0;
    for (const Bad& b : bad) {
        const std::string msg = test::errorOf([&] { test::generateCase(dir, "bad" + std::to_string(k++), stillTank(b.gauges)); });
        EXPECT_HAS(msg, b.part);
        EXPECT_HAS(msg, "_Def.xml:");
    }
}
