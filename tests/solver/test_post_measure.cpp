// SeaSpring — MIT licence.
/// \file test_post_measure.cpp
/// \brief `seaspring-post measure`: the kernel sums measured from the saved part files equal
///        the in-run gauges' (same function, physics::gaugeSampleAt) at the output times; the
///        points file's forms and errors (file and line named); the program's command line.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../unit/error_expect.h"
#include "io/part_output.h"
#include "post/measure.h"
#include "post/points_file.h"
#include "solver/simulation.h"
#include "solver_test_util.h"

#include "test_files.h"

using namespace seaspring;

namespace {

/// Still water (tests/data/gauges/StillTank_Def.xml, 2D, Wendland) with gauges computed at
/// every TimeOut (0.1 s) and part files at the same times.
const char* kGauges =
    "<gauges><default><computedt value=\"0.1\" /><output value=\"true\" /></default>"
    "<pressure name=\"P\"><point x=\"0.2\" y=\"0\" z=\"0.05\" /></pressure>"
    "<pressure name=\"Top\"><point x=\"0.1\" y=\"0\" z=\"0.19\" /></pressure>"
    "<velocity name=\"V\"><point x=\"0.2\" y=\"0\" z=\"0.1\" /></velocity>"
    "<pressure name=\"Out\"><point x=\"2\" y=\"0\" z=\"0.05\" /></pressure>"
    "<swl name=\"S\"><point0 x=\"0.2\" y=\"0\" z=\"0\" /><point2 x=\"0.2\" y=\"0\" z=\"0.3\" />"
    "<pointdp coefdp=\"0.5\" /></swl></gauges>";

std::string stillTankWith(const std::string& gauges, const std::string& kernel) {
    std::string xml = test::readFile(std::string(SEASPRING_TEST_DATA_DIR) + "/gauges/StillTank_Def.xml");
    const std::size_t a = xml.find("<gauges>"), b = xml.find("</gauges>");
    EXPECT_TRUE(a != std::string::npos && b != std::string::npos);
    xml.replace(a, b + 9 - a, gauges);
    return test::replaceOnce(xml, "key=\"Kernel\" value=\"2\"", "key=\"Kernel\" value=\"" + kernel + "\"");
}

double relDiff(double a, double b) { return std::fabs(a - b) / std::max(std::fabs(b), 1e-300); }

/// Runs the tank, measures the gauges' points from the part files and compares with the gauge
/// CSV (9 significant digits, %.9g). Two grids:
///  - the measure's own (the fluid's box grown by 4h, cells of 2h): the float pair offsets round
///    differently from the solver's, so the sums differ at float round-off; measured worst
///    relative differences (wsum, pressure) 1.2e-7, velocities ~1e-10 m/s: tolerance 1e-6
///    relative (velocities relative to 1e-3 m/s);
///  - the solver's grid (its domain minimum and cell size): with -skin:0 the sort, the PosCell
///    and the sums are the solver's, so every printed value is identical (required; measured:
///    28 of 28, worst difference 4.7e-9 = the print rounding); with the default skin a solver's
///    particle may sit in the cell of an earlier sort, whose offsets round differently: the same
///    tolerance as above is required (measured on still water: 28 of 28 identical as well).
void compareWithGauges(const std::string& tag, const std::string& kernel, double skin) {
    const std::string dir = test::scratch(tag);
    const std::string kase = test::generateCase(dir, "tank", stillTankWith(kGauges, kernel));
    const std::string out = dir + "/out";
    const auto run = test::runCpu(kase, out, 2, [&](solver::RunOptions& o) {
        o.save_h5 = true;
        o.skin = skin;
    });
    post::MeasureGrid solver_grid;
    solver_grid.cell_div = solver::resolveCellDiv(run.kase, 0);
    solver_grid.has_min = true;
    solver_grid.min = run.kase.domain_min;
    const std::vector<Vec3d> pts{{0.2, 0, 0.05}, {0.1, 0, 0.19}, {0.2, 0, 0.1}, {2, 0, 0.05}};
    std::string hp, ht, hv, ho;
    const auto gp = test::readCsv(out + "/gauges/GaugesPress_P.csv", hp);
    const auto gt = test::readCsv(out + "/gauges/GaugesPress_Top.csv", ht);
    const auto gv = test::readCsv(out + "/gauges/GaugesVel_V.csv", hv);
    const auto go = test::readCsv(out + "/gauges/GaugesPress_Out.csv", ho);
    const auto parts = post::listPartFiles(out, -1, -1);
    ASSERT_EQ(parts.size(), 4u);  // 0, 0.1, 0.2, 0.3 s
    ASSERT_EQ(gp.size(), parts.size());
    ASSERT_EQ(gv.size(), parts.size());
    double worst[2] = {0, 0};
    int same_text[2] = {0, 0}, values = 0;
    for (std::size_t r = 0; r < parts.size(); ++r) {
        const io::PartData d = io::readPartH5(parts[r].second);
        char t[32];
        std::snprintf(t, sizeof t, "%.10g", d.time);
        EXPECT_EQ(gp[r][0], std::string(t)) << "the gauge row and the part file are of the same time";
        const std::vector<post::PointSums> s[2] = {post::measurePart(d, pts, {}, parts[r].second),
                                                   post::measurePart(d, pts, solver_grid, parts[r].second)};
        const double kc = 0.5;
        for (int k = 0; k < 2; ++k) {
            auto check = [&](double mine, const std::string& text, double scale) {
                char buf[40];
                std::snprintf(buf, sizeof buf, "%.9g", mine);
                same_text[k] += text == buf;
                const double ref = std::stod(text);
                const double e = std::fabs(mine - ref) / std::max(std::fabs(ref), scale);
                worst[k] = std::max(worst[k], e);
                EXPECT_LE(e, 1e-6) << tag << " part " << r << ": measured " << buf << ", gauge " << text;
                if (k == 1 && skin == 0) {
                    EXPECT_EQ(std::string(buf), text) << tag << " part " << r << ", solver's grid";
                }
            };
            if (k == 0) values += 7;
            const physics::GaugeSample& p = s[k][0].g;
            check(physics::shepard(p.press, p.wsum, kc), gp[r][1], 1.0);
            check(p.wsum, gp[r][5], 1.0);
            const physics::GaugeSample& q = s[k][1].g;
            check(physics::shepard(q.press, q.wsum, kc), gt[r][1], 1.0);
            check(q.wsum, gt[r][5], 1.0);
            const physics::GaugeSample& v = s[k][2].g;
            check(physics::shepard(v.vx, v.wsum, kc), gv[r][1], 1e-3);
            check(physics::shepard(v.vz, v.wsum, kc), gv[r][3], 1e-3);
            check(v.wsum, gv[r][7], 1.0);
            EXPECT_EQ(s[k][3].g.wsum, 0.0);  // outside the fluid, as the in-run gauge
            // rhop (Shepard): ~rho0 at the bottom point.
            EXPECT_NEAR(physics::shepard(s[k][0].rhop, p.wsum, kc), 1000.0, 5.0);
        }
        EXPECT_EQ(std::stod(go[r][1]), 0.0);
    }
    std::printf("[ measure ] %s (skin %g): worst relative difference to the gauge CSV: own grid %.3g (%d of %d printed "
                "values identical), solver's grid %.3g (%d of %d identical)\n",
                tag.c_str(), skin, worst[0], same_text[0], values, worst[1], same_text[1], values);

    // The whole subcommand: its CSV holds the gauges' printed values.
    std::ofstream(dir + "/pts.txt") << "POINTS\n# x y z\n0.2 0 0.05\n0.1 0 0.19\n";
    post::MeasureOptions o;
    o.dirin = out;
    o.points = dir + "/pts.txt";
    o.vars = post::parseMeasureVars("press,wsum");
    o.savecsv = dir + "/m.csv";
    o.first = 1;
    std::ostringstream log;
    EXPECT_EQ(post::runMeasure(o, log), 3);
    std::string h;
    const auto m = test::readCsv(o.savecsv, h);
    EXPECT_EQ(h, "part;time;press_0;press_1;wsum_0;wsum_1");
    ASSERT_EQ(m.size(), 3u);
    for (std::size_t r = 0; r < 3; ++r) {
        EXPECT_EQ(m[r][0], std::to_string(r + 1));
        EXPECT_EQ(m[r][1], gp[r + 1][0]);
        EXPECT_LE(relDiff(std::stod(m[r][2]), std::stod(gp[r + 1][1])), 1e-6);
        EXPECT_LE(relDiff(std::stod(m[r][3]), std::stod(gt[r + 1][1])), 1e-6);
        EXPECT_LE(relDiff(std::stod(m[r][4]), std::stod(gp[r + 1][5])), 1e-6);
    }

    // height (MeasureTool's -height): the SWL gauge's line and surface rule from the point up,
    // spaced dp/2 as the gauge S; the same surface as the gauge's CSV to round-off (broken on
    // purpose: the 3D default mass limit, 0.5 m, in this 2D case moves it by 1.9 mm).
    std::ofstream(dir + "/col.txt") << "POINTS\n0.2 0 0\n";
    o.points = dir + "/col.txt";
    o.vars = post::parseMeasureVars("height");
    o.savecsv = dir + "/h.csv";
    o.first = -1;
    EXPECT_EQ(post::runMeasure(o, log), 4);
    const auto hm = test::readCsv(o.savecsv, h);
    EXPECT_EQ(h, "part;time;height_0");
    std::string hs;
    const auto gs = test::readCsv(out + "/gauges/GaugesSwl_S.csv", hs);
    ASSERT_EQ(gs.size(), hm.size());
    double worst_h = 0;
    for (std::size_t r = 0; r < hm.size(); ++r) {
        const double mine = std::stod(hm[r][2]), gauge = std::stod(gs[r][3]);
        worst_h = std::max(worst_h, std::fabs(mine - gauge));
        EXPECT_NEAR(mine, gauge, 1e-6) << tag << " part " << r;
        EXPECT_NEAR(mine, 0.2, 0.01) << tag << " part " << r;  // the still water's surface
    }
    std::printf("[ measure ] %s: height against the SWL gauge: worst difference %.3g m\n", tag.c_str(), worst_h);
}

}  // namespace

TEST(PostMeasure, EqualsInRunGaugesWendland) { compareWithGauges("post_measure_wendland", "2", 0.0); }
TEST(PostMeasure, EqualsInRunGaugesCubicDefaultSkin) { compareWithGauges("post_measure_cubic", "1", 0.05); }

TEST(PostMeasure, PointsFileForms) {
    const auto a = post::parsePoints("POINTS # x y z\n1 2 3\n  # comment\n\n4,5,6  # trailing\n", "a.txt");
    ASSERT_EQ(a.size(), 2u);
    EXPECT_EQ(a[1].z, 6.0);
    const auto b = post::parsePoints("pointslist\n0.5 0 0.02\n0.1 0 0.02\n2 1 3\n\n#BeginX BeginY BeginZ\n", "b.txt");
    ASSERT_EQ(b.size(), 6u);
    EXPECT_DOUBLE_EQ(b[1].x, 0.6);  // x fastest
    EXPECT_DOUBLE_EQ(b[5].z, 0.06);
    const std::string shared = std::string(SEASPRING_SHARED_DIR) + "/dualsphysics-cases/CaseDambreak_PointsPressure_Correct.txt";
    if (std::ifstream(shared)) {
        const auto c = post::readPointsFile(shared);
        ASSERT_EQ(c.size(), 5u);
        EXPECT_DOUBLE_EQ(c[4].z, 0.1);
    }
}

TEST(PostMeasure, PointsFileErrorsNameFileAndLine) {
    auto err = [](const std::string& text) { return test::errorOf([&] { post::parsePoints(text, "pts.txt"); }); };
    std::string e = err("POINTS\n1 2 3\n1 2\n");
    EXPECT_HAS(e, "pts.txt:3:");
    EXPECT_HAS(e, "expected 3 numbers, found 2");
    e = err("POINTS\n\n1 2 abc\n");
    EXPECT_HAS(e, "pts.txt:3:");
    EXPECT_HAS(e, "'abc' is not a number");
    e = err("# header\n1 2 3\n");
    EXPECT_HAS(e, "pts.txt:2:");
    EXPECT_HAS(e, "POINTS or POINTSLIST");
    e = err("POINTSLIST\n0 0 0\n1 1 1\n2 0.5 1\n");
    EXPECT_HAS(e, "pts.txt:4:");
    EXPECT_HAS(e, "positive integers");
    e = err("POINTSLIST\n0 0 0\n1 1 1\n2 1 1\n3 3 3\n");
    EXPECT_HAS(e, "pts.txt:5:");
    e = err("POINTSLIST\n0 0 0\n");
    EXPECT_HAS(e, "needs 3 lines");
    e = err("POINTS\n# none\n");
    EXPECT_HAS(e, "pts.txt:1:");
    EXPECT_HAS(e, "no point");
    e = test::errorOf([] { post::readPointsFile("/nonexistent/pts.txt"); });
    EXPECT_HAS(e, "/nonexistent/pts.txt: cannot read");
    e = test::errorOf([] { post::parseMeasureVars("press,temp"); });
    EXPECT_HAS(e, "'temp'");
}

TEST(PostMeasure, CommandLine) {
    const std::string dir = test::scratch("post_measure_cli");
    const std::string kase = test::generateCase(dir, "tank", stillTankWith(kGauges, "2"));
    const auto r = test::runCpu(kase, dir + "/out", 2, [](solver::RunOptions& o) {
        o.save_h5 = true;
        o.tmax = 0.1;
    });
    std::ofstream(dir + "/good.txt") << "POINTS\n0.2 0 0.05\n";
    std::ofstream(dir + "/bad.txt") << "POINTS\n0.2 0 0.05\n0.2 0\n";
    const std::string bin = std::string("'") + SEASPRING_POST_BIN + "' measure -dirin '" + dir + "/out' ";
    auto run = [&](const std::string& args) {
        const int rc = std::system((bin + args + " >'" + dir + "/log.txt' 2>&1").c_str());
        return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
    };
    EXPECT_EQ(run("-points '" + dir + "/good.txt' -first 0 -last:1 -vars:press,vel,rhop -kclimit 0.5 -savecsv '" + dir +
                  "/m.csv'"), 0) << test::readFile(dir + "/log.txt");
    std::string h;
    const auto m = test::readCsv(dir + "/m.csv", h);
    EXPECT_EQ(h, "part;time;press_0;velx_0;vely_0;velz_0;rhop_0");
    EXPECT_EQ(m.size(), 2u);
    EXPECT_EQ(run("-points '" + dir + "/bad.txt' -savecsv '" + dir + "/m2.csv'"), 2);
    EXPECT_HAS(test::readFile(dir + "/log.txt"), dir + "/bad.txt:3:");
    EXPECT_FALSE(std::ifstream(dir + "/m2.csv").good());
    EXPECT_NE(run("-points '" + dir + "/good.txt'"), 0);  // -savecsv missing: a usage error
}
