// SeaSpring — MIT licence.
/// \file test_constants.cpp
/// \brief Derived constants against hand-computed GenCase values.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "gencase/constants.h"
#include "gencase_test_util.h"

using namespace seaspring;
using namespace seaspring::gencase;

TEST(Constants, DamBreakValuesAsGenCase) {
    ConstantsInput in;
    in.coefh = 1.0;
    const CaseConstants c = computeConstants(in, 0.0085, false, 0.289);
    const double cs = 20 * std::sqrt(9.81 * 0.289);
    EXPECT_DOUBLE_EQ(c.h, std::sqrt(3 * 0.0085 * 0.0085));
    EXPECT_DOUBLE_EQ(c.speedsystem, std::sqrt(9.81 * 0.289));
    EXPECT_DOUBLE_EQ(c.speedsound, cs);
    EXPECT_DOUBLE_EQ(c.b, cs * cs * 1000 / 7);
    EXPECT_DOUBLE_EQ(c.massfluid, 1000 * 0.0085 * 0.0085 * 0.0085);
    EXPECT_DOUBLE_EQ(c.massbound, c.massfluid);
    // The GenCase figures in shared/dualsphysics-cases/README.md, to 4 significant figures.
    EXPECT_NEAR(c.h, 0.014722, 0.5e-6);
    EXPECT_NEAR(c.speedsound, 33.68, 0.005);
    EXPECT_NEAR(c.b, 162005, 50);
}

TEST(Constants, TwoDimensionalUsesSqrt2AndAreaMass) {
    ConstantsInput in;
    in.coefh = 1.0;
    const CaseConstants c = computeConstants(in, 0.01, true, 1.99);
    EXPECT_EQ(c.dimensions, 2);
    EXPECT_DOUBLE_EQ(c.h, std::sqrt(2 * 0.01 * 0.01));
    EXPECT_DOUBLE_EQ(c.massfluid, 1000 * 0.01 * 0.01);
}

TEST(Constants, HdpAndUserValues) {
    ConstantsInput in;
    in.hdp = 2;
    in.speedsystem = {10, false};
    in.coefsound = 10;
    in.rhop0 = 997;
    const CaseConstants c = computeConstants(in, 0.002, true, 0.4);
    EXPECT_DOUBLE_EQ(c.h, 0.004);
    EXPECT_DOUBLE_EQ(c.speedsound, 100);
    EXPECT_DOUBLE_EQ(c.b, 100.0 * 100.0 * 997 / 7);
    ConstantsInput fixed;
    fixed.speedsound = {50, false};
    fixed.massbound = {0.5, false};
    const CaseConstants d = computeConstants(fixed, 0.1, false, 1.0);
    EXPECT_DOUBLE_EQ(d.speedsound, 50);
    EXPECT_DOUBLE_EQ(d.massbound, 0.5);
    EXPECT_DOUBLE_EQ(d.massfluid, 1000 * 0.1 * 0.1 * 0.1);
}

TEST(Constants, SoundSpeedHasTheShallowWaterFloor) {
    // coefsound 5 would give 5*sqrt(g h); the floor 10*sqrt(g h) wins.
    ConstantsInput in;
    in.coefsound = 5;
    const CaseConstants c = computeConstants(in, 0.01, false, 0.5);
    EXPECT_DOUBLE_EQ(c.speedsound, 10 * std::sqrt(9.81 * 0.5));
}

TEST(Constants, ParseErrorsNameTheLine) {
    const std::string dir = test::scratchDir("constants");
    const std::string path = test::writeFile(dir, "c.xml",
        "<constantsdef>\n  <coefh value=\"1\"/>\n  <hdp value=\"2\"/>\n</constantsdef>\n");
    XmlSource src(path);
    ExpressionEvaluator ev;
    try {
        parseConstantsDef(src, src.root(), ev);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("c.xml:1"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("both <coefh> and <hdp>"), std::string::npos);
    }
    const std::string p2 = test::writeFile(dir, "d.xml",
        "<constantsdef>\n  <rhop0 value=\"-5\"/>\n</constantsdef>\n");
    XmlSource s2(p2);
    try {
        parseConstantsDef(s2, s2.root(), ev);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("d.xml:2"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("-5"), std::string::npos);
    }
    const std::string p3 = test::writeFile(dir, "e.xml",
        "<constantsdef>\n  <lattice bound=\"2\" fluid=\"1\"/>\n  <gamma valeu=\"7\"/>\n</constantsdef>\n");
    XmlSource s3(p3);
    EXPECT_THROW(parseConstantsDef(s3, s3.root(), ev), Error);
}
