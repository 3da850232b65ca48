// SeaSpring — MIT licence.
/// \file test_post_forces.cpp
/// \brief `seaspring-post forces`: the force on boundary MKs computed from the saved part files
///        equals the in-run force gauge (same function, physics::hydroForceOnBoundary) at the
///        output times; the still tank's walls carry the water's weight; the command line and
///        its errors.
///
/// Broken on purpose once each (then restored), to see these tests fail:
///  - post/forces.cpp summed `fx -= by_id[id].x` instead of `+=`: both EqualsInRunGauge tests
///    failed on every non-zero forcex (18 of 24 printed values left identical: y and zeros) and
///    StillTankCarriesTheWeight on the right wall (-202.6 N);
///  - post/forces.cpp skipped physics::pressureAt (press_ovrho left 0): only the zero forcey
///    values stayed identical (12 of 24) and StillTankCarriesTheWeight failed (Fz = -0.12 N).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../unit/error_expect.h"
#include "io/part_output.h"
#include "post/forces.h"
#include "post/part_series.h"
#include "solver/simulation.h"
#include "solver_test_util.h"

#include "test_files.h"

using namespace seaspring;

namespace {

/// tests/data/gauges/StillTank_Def.xml (2D, dp 0.01, Wendland, artificial viscosity 0.01) with
/// the right wall as its own MK (mkbound 1) and force gauges on both MKs at every TimeOut.
/// `dambreak`: the water only fills x < 0.2 m, so it collapses and runs against the right wall
/// (velocities, hence the viscous terms, are not zero).
std::string tankCase(bool dambreak, const std::string& kernel = "2") {
    std::string xml = test::readFile(std::string(SEASPRING_TEST_DATA_DIR) + "/gauges/StillTank_Def.xml");
    const std::size_t a = xml.find("<gauges>"), b = xml.find("</gauges>");
    EXPECT_TRUE(a != std::string::npos && b != std::string::npos);
    xml.replace(a, b + 9 - a,
                "<gauges><default><computedt value=\"0.1\" /><output value=\"true\" /></default>"
                "<force name=\"Tank\"><target mkbound=\"0\" /></force>"
                "<force name=\"Wall\"><target mkbound=\"1\" /></force></gauges>");
    xml = test::replaceOnce(xml, "<boxfill>bottom | left | right</boxfill><point x=\"0\" y=\"-1\" z=\"0\" /><size x=\"0.4\" y=\"2\" z=\"0.3\" /><layers vdp=\"0,1,2\" /></drawbox>",
                            "<boxfill>bottom | left | right</boxfill><point x=\"0\" y=\"-1\" z=\"0\" /><size x=\"0.4\" y=\"2\" z=\"0.3\" /><layers vdp=\"0,1,2\" /></drawbox>"
                            "<setmkbound mk=\"1\" /><drawbox><boxfill>right</boxfill><point x=\"0\" y=\"-1\" z=\"0\" /><size x=\"0.4\" y=\"2\" z=\"0.3\" /><layers vdp=\"0,1,2\" /></drawbox>");
    if (dambreak)
        xml = test::replaceOnce(xml, "<size x=\"0.4\" y=\"2\" z=\"0.2\" />", "<size x=\"0.2\" y=\"2\" z=\"0.2\" />");
    return test::replaceOnce(xml, "key=\"Kernel\" value=\"2\"", "key=\"Kernel\" value=\"" + kernel + "\"");
}

/// Runs the dam break, computes the forces from the part files and compares with the gauge CSVs
/// (%.9g). With -skin:0 the sort, PosCell and sums are the solver's: every printed value must be
/// identical (measured: 24 of 24). With the default skin a particle may sit in the cell of an
/// earlier sort, whose float offsets round differently: relative to the largest force of the
/// file, 1e-5 (measured: see the printed line).
void compareWithGauge(const std::string& tag, const std::string& kernel, double skin) {
    const std::string dir = test::scratch(tag);
    const std::string kase = test::generateCase(dir, "tank", tankCase(true, kernel));
    const std::string out = dir + "/out";
    test::runCpu(kase, out, 2, [&](solver::RunOptions& o) {
        o.save_h5 = true;
        o.skin = skin;
    });
    const auto parts = post::listPartFiles(out, -1, -1);
    ASSERT_EQ(parts.size(), 4u);  // 0, 0.1, 0.2, 0.3 s
    int same = 0, values = 0;
    double worst = 0;
    for (const char* name : {"Tank", "Wall"}) {
        std::string h;
        const auto g = test::readCsv(out + "/gauges/GaugesForce_" + std::string(name) + ".csv", h);
        ASSERT_EQ(g.size(), parts.size()) << name;
        post::ForcesOptions o;
        o.filexml = kase;
        o.mkbound = {std::string(name) == "Tank" ? 0 : 1};
        std::ostringstream log;
        const auto m = post::makeForceModel(o, log);
        double scale = 0;
        for (const auto& row : g)
            for (int k = 1; k <= 3; ++k) scale = std::max(scale, std::fabs(std::stod(row[k])));
        ASSERT_GT(scale, 1.0) << name;
        for (std::size_t r = 0; r < parts.size(); ++r) {
            const io::PartData d = io::readPartH5(parts[r].second);
            char t[32];
            std::snprintf(t, sizeof t, "%.10g", d.time);
            EXPECT_EQ(g[r][0], std::string(t)) << "the gauge row and the part file are of the same time";
            const physics::Double3 f = post::forcesOfPart(*m, d, parts[r].second);
            const double v[3] = {f.x, f.y, f.z};
            for (int k = 0; k < 3; ++k) {
                char buf[40];
                std::snprintf(buf, sizeof buf, "%.9g", v[k]);
                ++values;
                same += g[r][k + 1] == buf;
                const double e = std::fabs(v[k] - std::stod(g[r][k + 1])) / scale;
                worst = std::max(worst, e);
                if (skin == 0) {
                    EXPECT_EQ(std::string(buf), g[r][k + 1]) << tag << " " << name << " part " << r << " component " << k;
                } else {
                    EXPECT_LE(e, 1e-5) << tag << " " << name << " part " << r << ": " << buf << " vs gauge " << g[r][k + 1];
                }
            }
        }
    }
    std::printf("[ forces ] %s (skin %g): %d of %d printed values identical to the gauge CSV, worst difference %.3g of "
                "the largest force\n", tag.c_str(), skin, same, values, worst);
}

}  // namespace

TEST(PostForces, EqualsInRunGaugeWendlandNoSkin) { compareWithGauge("post_forces_wendland", "2", 0.0); }
TEST(PostForces, EqualsInRunGaugeCubicDefaultSkin) { compareWithGauge("post_forces_cubic", "1", 0.05); }

/// Still water 0.4 x 0.2 m (800 particles of 0.1 kg): the walls (tank + right wall) carry its
/// weight, 784.8 N downwards, and the side forces cancel; the right wall (MK 1) carries the
/// hydrostatic thrust rho g H^2 / 2 = 196.2 N per metre of width.
TEST(PostForces, StillTankCarriesTheWeight) {
    const std::string dir = test::scratch("post_forces_still");
    const std::string kase = test::generateCase(dir, "tank", tankCase(false));
    const std::string out = dir + "/out";
    test::runCpu(kase, out, 2, [&](solver::RunOptions& o) { o.save_h5 = true; });
    post::ForcesOptions o;
    o.filexml = kase;
    o.mkbound = {0, 1};
    std::ostringstream log;
    const auto m = post::makeForceModel(o, log);
    const auto parts = post::listPartFiles(out, 3, 3);
    const io::PartData d = io::readPartH5(parts[0].second);
    const physics::Double3 f = post::forcesOfPart(*m, d, parts[0].second);
    std::printf("[ forces ] still tank at t = %g s: total (%.4g, %.4g) N, weight 784.8 N\n", d.time, f.x, f.z);
    EXPECT_NEAR(f.z, -784.8, 0.02 * 784.8);  // measured -787.4 N
    EXPECT_NEAR(f.x, 0.0, 0.01 * 784.8);
    o.mkbound = {1};
    const auto w = post::makeForceModel(o, log);
    const physics::Double3 fw = post::forcesOfPart(*w, d, parts[0].second);
    const double thrust = 1000 * 9.81 * 0.2 * 0.2 / 2;
    std::printf("[ forces ] right wall: %.4g N (hydrostatic %.4g N)\n", fw.x, thrust);
    EXPECT_NEAR(fw.x, thrust, 0.06 * thrust);  // measured 202.6 N
}

TEST(PostForces, CommandLineAndErrors) {
    const std::string dir = test::scratch("post_forces_cli");
    const std::string kase = test::generateCase(dir, "tank", tankCase(true));
    test::runCpu(kase, dir + "/out", 2, [](solver::RunOptions& o) {
        o.save_h5 = true;
        o.tmax = 0.1;
    });
    const std::string bin = std::string("'") + SEASPRING_POST_BIN + "' forces -dirin '" + dir + "/out' ";
    auto run = [&](const std::string& args) {
        const int rc = std::system((bin + args + " >'" + dir + "/log.txt' 2>&1").c_str());
        return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
    };
    // mkbound 1 is the absolute MK 1 + fluidcount 9 + 1 = 11.
    EXPECT_EQ(run("-filexml '" + kase + ".xml' -onlymk:11 -first:1 -savecsv '" + dir + "/f.csv'"), 0)
        << test::readFile(dir + "/log.txt");
    std::string h;
    const auto a = test::readCsv(dir + "/f.csv", h);
    EXPECT_EQ(h, "part;time;forcex;forcey;forcez");
    ASSERT_EQ(a.size(), 1u);
    EXPECT_EQ(a[0][0], "1");
    EXPECT_EQ(run("-filexml '" + kase + "' -mkbound 1 -first:1 -savecsv '" + dir + "/g.csv'"), 0);
    const auto b = test::readCsv(dir + "/g.csv", h);
    ASSERT_EQ(b.size(), 1u);
    EXPECT_EQ(a[0], b[0]);
    const std::string gauge = test::readFile(dir + "/out/gauges/GaugesForce_Wall.csv");
    EXPECT_HAS(gauge, a[0][1] + ";" + a[0][2] + ";" + a[0][3] + ";" + a[0][4]);  // the gauge's row, digit for digit
    // An MK the case does not have: the case file and the MKs it has.
    EXPECT_EQ(run("-filexml '" + kase + "' -onlymk:21 -savecsv '" + dir + "/e.csv'"), 2);
    std::string log = test::readFile(dir + "/log.txt");
    EXPECT_HAS(log, kase + ".xml");
    EXPECT_HAS(log, "-onlymk:21");
    EXPECT_HAS(log, "10, 11");
    EXPECT_FALSE(std::ifstream(dir + "/e.csv").good());
    EXPECT_EQ(run("-filexml '" + kase + "' -onlymk:1x -savecsv '" + dir + "/e.csv'"), 2);
    EXPECT_HAS(test::readFile(dir + "/log.txt"), "'1x' is not a non-negative integer");
    // Another case (dp 0.02): the part files do not belong to it.
    const std::string other = test::generateCase(dir + "/other", "tank", tankCase(true), 0.02);
    EXPECT_EQ(run("-filexml '" + other + "' -mkbound 0 -savecsv '" + dir + "/e.csv'"), 2);
    log = test::readFile(dir + "/log.txt");
    EXPECT_HAS(log, "part_0000.h5: np = ");
    EXPECT_HAS(log, "is -filexml this run's case?");
    EXPECT_NE(run("-mkbound 0 -savecsv '" + dir + "/e.csv'"), 0);  // -filexml missing: a usage error
}
