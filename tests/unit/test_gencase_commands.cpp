// SeaSpring — MIT licence.
/// \file test_gencase_commands.cpp
/// \brief GenCase commands through the whole builder: exact counts, MK numbering, particle
///        order, variables and lists, initial density, masses, domain and parameters.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "gencase_test_util.h"
#include "physics/eos_tait.h"

using namespace seaspring;
using namespace seaspring::gencase;

namespace {

GeneratedCase build(const std::string& tag, const std::string& mainlist, bool two_d = false,
                    const std::string& casedef_extra = "", const std::string& parameters = "") {
    const std::string dir = test::scratchDir(tag);
    const std::string path =
        test::writeFile(dir, "Case_Def.xml", test::caseXml(mainlist, 0.1, two_d, casedef_extra, "", parameters));
    return test::buildCase(path);
}

std::string errorOf(const std::string& tag, const std::string& mainlist) {
    try {
        build(tag, mainlist);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

const char* kTank =
    "<setmkfluid mk=\"0\"/><drawbox><boxfill>solid</boxfill><point x=\"0\" y=\"0\" z=\"0\"/>"
    "<size x=\"0.4\" y=\"0.4\" z=\"0.3\"/></drawbox>"
    "<setmkbound mk=\"0\"/><drawbox><boxfill>bottom|left|right|front|back</boxfill>"
    "<point x=\"0\" y=\"0\" z=\"0\"/><size x=\"1\" y=\"0.4\" z=\"0.5\"/></drawbox>";

}  // namespace

TEST(GencaseCommands, TankWithWaterCountsAndMkNumbering) {
    const GeneratedCase g = build("tank", kTank);
    // Water 0..0.4 x 0..0.4 x 0..0.3 (5x5x4 sites) minus the sites the walls redraw (x=0,
    // y=0, y=0.4, z=0): 4 x 3 x 3 = 36. Tank 11x5x6 open top: bottom 55 + x-walls 2*5*5 +
    // y-walls 2*9*5 = 195.
    EXPECT_EQ(g.count(ParticleType::Fluid), 36u);
    EXPECT_EQ(g.count(ParticleType::Fixed), 195u);
    ASSERT_EQ(g.blocks.size(), 2u);
    EXPECT_EQ(g.blocks[0].mk, 10);  // mkbound 0 -> 0 + fluidcount(9) + 1
    EXPECT_EQ(g.blocks[0].mk_local, 0);
    EXPECT_EQ(g.blocks[1].mk, 1);   // mkfluid 0 -> 1
    EXPECT_EQ(g.blocks[1].begin, 195u);
    for (std::size_t i = 0; i < g.particles.size(); ++i) EXPECT_EQ(g.particles.id[i], i);
}

TEST(GencaseCommands, ParticlesAreOrderedByBlockMkAndLattice) {
    const GeneratedCase g = build("order", std::string(kTank) +
        "<setmkbound mk=\"3\"/><drawbox><boxfill>solid</boxfill><point x=\"0.8\" y=\"0.1\" z=\"0.1\"/>"
        "<size x=\"0\" y=\"0.1\" z=\"0\"/></drawbox>");
    const ParticleSet& p = g.particles;
    for (std::size_t i = 1; i < p.size(); ++i) {
        ASSERT_LE(p.type[i - 1], p.type[i]);
        if (p.type[i - 1] == p.type[i]) {
            ASSERT_LE(p.mk[i - 1], p.mk[i]);
        }
        if (p.mk[i - 1] == p.mk[i]) {  // x fastest, then y, then z
            const Vec3d a = p.pos[i - 1], b = p.pos[i];
            ASSERT_TRUE(a.z < b.z || (a.z == b.z && (a.y < b.y || (a.y == b.y && a.x < b.x))));
        }
    }
    EXPECT_EQ(g.blocks[1].mk, 13);
    EXPECT_EQ(g.blocks[1].count, 2u);
}

TEST(GencaseCommands, MkVoidCarvesAndLayersThickenWalls) {
    // A 1 m wide floor (11 x 5 sites) with a 0.2 m hole carved, then 2 layers downwards.
    const GeneratedCase g = build("layers",
        "<setmkbound mk=\"0\"/><drawbox><boxfill>bottom</boxfill><point x=\"0\" y=\"0\" z=\"0\"/>"
        "<size x=\"1\" y=\"0.4\" z=\"1\"/><layers vdp=\"0*,1\"/></drawbox>"
        "<setmkvoid/><drawbox><boxfill>solid</boxfill><point x=\"0.4\" y=\"0\" z=\"-0.1\"/>"
        "<size x=\"0.2\" y=\"0.4\" z=\"0.1\"/></drawbox>");
    // Two layers of 11 x 5 = 110, minus the hole 3 x 5 x 2 = 30.
    EXPECT_EQ(g.count(ParticleType::Fixed), 80u);
}

TEST(GencaseCommands, NamedListsRunWithTheCurrentState) {
    const std::string dir = test::scratchDir("lists");
    std::string xml = test::caseXml(
        "<newvarcte W=\"0.4\" Half=\"W/2\"/><newvar N=\"1\"/><setvar N=\"N+1\"/>"
        "<setactive drawpoints=\"0\"/>"
        "<setmkbound mk=\"1\"/><drawbox><boxfill>solid</boxfill><point x=\"0\" y=\"0\" z=\"0\"/>"
        "<size x=\"1\" y=\"1\" z=\"1\"/></drawbox><resetdraw/>"
        "<setmkbound mk=\"0\"/><runlist name=\"Row\"/>"
        "<move x=\"#Half\" y=\"0\" z=\"0.2\"/><runlist name=\"Row\" times=\"2\"/>");
    const std::string list =
        "<list name=\"Row\"><drawbox><boxfill>solid</boxfill><point x=\"0\" y=\"0\" z=\"0\"/>"
        "<size x=\"#W*N/2\" y=\"0\" z=\"0\"/></drawbox></list>\n    <mainlist>";
    xml.replace(xml.find("<mainlist>"), 10, list);
    const GeneratedCase g = test::buildCase(test::writeFile(dir, "Case_Def.xml", xml));
    // drawpoints=0 drew nothing; Row draws x 0..0.4 (5 sites) at z=0 and, moved, x 0.2..0.6
    // at z=0.2 (drawn twice onto the same sites): 10 particles, all mkbound 0.
    EXPECT_EQ(g.particles.size(), 10u);
    EXPECT_EQ(g.blocks.size(), 1u);
    EXPECT_DOUBLE_EQ(g.particles.pos[5].x, 0.2);
    EXPECT_DOUBLE_EQ(g.particles.pos[5].z, 0.2);
}

TEST(GencaseCommands, HydrostaticInitialDensity) {
    const GeneratedCase g = build("rho", kTank);
    const CaseConstants& c = g.constants;
    // hswl = top fluid z - bottom fluid z = 0.3 - 0.1; each column's top particle is at rho0.
    EXPECT_DOUBLE_EQ(c.hswl, 0.3 - 0.1);
    for (std::size_t i = 0; i < g.particles.size(); ++i) {
        const ParticleSet& p = g.particles;
        if (p.type[i] != ParticleType::Fluid) {
            EXPECT_FLOAT_EQ(p.rhop[i], 1000.f);
            EXPECT_FLOAT_EQ(p.mass[i], float(c.massbound));
            continue;
        }
        const double depth = 0.3 - p.pos[i].z;
        const double expect = 1000 * std::pow(1 + 1000 * 9.81 * depth / c.b, 1 / 7.0);
        EXPECT_NEAR(p.rhop[i], expect, 1e-3) << "z=" << p.pos[i].z;
        EXPECT_FLOAT_EQ(p.mass[i], float(1000 * 0.1 * 0.1 * 0.1));
    }
    // Sanity: rho at depth 0.2 m is about rho0 * (1 + rho0 g d / (7 B)).
    EXPECT_GT(c.b, 0);
}

TEST(GencaseCommands, TwoDimensionalCase) {
    const GeneratedCase g = build("twod",
        "<setmkfluid mk=\"0\"/><drawbox><boxfill>solid</boxfill><point x=\"0\" y=\"-1\" z=\"0\"/>"
        "<size x=\"0.5\" y=\"2\" z=\"0.5\"/></drawbox>"
        "<setmkbound mk=\"0\"/><drawbox><boxfill>bottom|left|right|front|back</boxfill>"
        "<point x=\"0\" y=\"-1\" z=\"0\"/><size x=\"1\" y=\"2\" z=\"1\"/></drawbox>", true);
    // Fluid 6 x 6 minus bottom row and left column: 25. Walls: bottom 11 + 2 sides x 10 = 31
    // (front/back faces do not cross the plane y = 0).
    EXPECT_EQ(g.constants.dimensions, 2);
    EXPECT_EQ(g.count(ParticleType::Fluid), 25u);
    EXPECT_EQ(g.count(ParticleType::Fixed), 31u);
    for (const Vec3d& x : g.particles.pos) EXPECT_EQ(x.y, 0.0);
}

TEST(GencaseCommands, SimulationDomainForms) {
    const GeneratedCase g = build("domain", kTank, false, "",
        "<simulationdomain><posmin x=\"default - 0.5\" y=\"-2\" z=\"default\"/>"
        "<posmax x=\"default + 10%\" y=\"default\" z=\"default + 50%\"/></simulationdomain>");
    EXPECT_DOUBLE_EQ(g.domain.min.x, -0.5);
    EXPECT_DOUBLE_EQ(g.domain.min.y, -2);
    EXPECT_DOUBLE_EQ(g.domain.min.z, 0);
    EXPECT_NEAR(g.domain.max.x, 1.0 + 0.1, 1e-12);
    EXPECT_NEAR(g.domain.max.y, 0.4, 1e-12);
    EXPECT_NEAR(g.domain.max.z, 0.5 + 0.25, 1e-12);
    EXPECT_THROW(build("domain2", kTank, false, "",
                       "<simulationdomain><posmax x=\"0.5\"/></simulationdomain>"),
                 Error);
}

TEST(GencaseCommands, ParametersGetDefaultsAndRejectUnknownKeys) {
    const GeneratedCase g = build("params", kTank, false, "",
                                  "<parameter key=\"#Shifting\" value=\"3\"/>"
                                  "<parameter key=\"DensityDT\" value=\"3\"/>");
    auto value = [&](const std::string& k) {
        for (const auto& [key, v] : g.parameters)
            if (key == k) return v;
        return std::string("<absent>");
    };
    EXPECT_EQ(value("DensityDT"), "3");
    EXPECT_EQ(value("Shifting"), "0");        // '#'-prefixed key skipped, default kept
    EXPECT_EQ(value("RhopOutMin"), "700");
    EXPECT_EQ(value("Visco"), "0.1");
    try {
        build("params2", kTank, false, "", "<parameter key=\"DensityDt\" value=\"3\"/>");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("DensityDt"), std::string::npos);
    }
}

TEST(GencaseCommands, CommandErrorsNameLineAndValue) {
    std::string e = errorOf("err1", "<setmkfluid mk=\"9\"/>");
    EXPECT_NE(e.find("mk=9"), std::string::npos) << e;
    EXPECT_NE(e.find("Case_Def.xml:"), std::string::npos) << e;
    e = errorOf("err2", "<setmkbound mk=\"0\"/><drawbox><boxfill>sides</boxfill>"
                        "<point x=\"0\" y=\"0\" z=\"0\"/><size x=\"1\" y=\"1\" z=\"1\"/></drawbox>");
    EXPECT_NE(e.find("\"sides\""), std::string::npos) << e;
    e = errorOf("err3", "<drawbox><point x=\"0\" y=\"0\" z=\"0\"/><size x=\"1\" y=\"1\" z=\"1\"/></drawbox>");
    EXPECT_NE(e.find("before any setmk"), std::string::npos) << e;
    e = errorOf("err4", "<setmkbound mk=\"0\"/><drawbeach/>");
    EXPECT_NE(e.find("<drawbeach>"), std::string::npos) << e;
    e = errorOf("err5", "<runlist name=\"Nope\"/>");
    EXPECT_NE(e.find("Nope"), std::string::npos) << e;
    e = errorOf("err6", "<setmkbound mk=\"0\"/><drawbox><point x=\"#Undefined*2\" y=\"0\" z=\"0\"/>"
                        "<size x=\"1\" y=\"1\" z=\"1\"/></drawbox>");
    EXPECT_NE(e.find("Undefined"), std::string::npos) << e;
    e = errorOf("err7", "<setmkfluid mk=\"0\"/><fillbox x=\"0\" y=\"0\" z=\"0\"><modefill>border|wall</modefill>"
                        "<point x=\"0\" y=\"0\" z=\"0\"/><size x=\"1\" y=\"1\" z=\"1\"/></fillbox>");
    EXPECT_NE(e.find("\"wall\""), std::string::npos) << e;
}
