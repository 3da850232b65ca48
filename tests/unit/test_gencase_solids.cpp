// SeaSpring — MIT licence.
/// \file test_gencase_solids.cpp
/// \brief VCPM solids through the whole gencase builder: particle types, masses, bond and
///        clamp-bond counts (by hand), bond symmetry, the resolved case, DualSPHysics
///        <flexstrucs> bodies, and every input error with its file and line.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include <pugixml.hpp>

#include "core/error.h"
#include "gencase/resolved_case_writer.h"
#include "gencase/vcpm_bonds.h"
#include "gencase_test_util.h"

using namespace seaspring;
using namespace seaspring::gencase;

namespace {

struct CaseFile {
    std::string path;
    std::string text;
};

CaseFile writeCase(const std::string& tag, const std::string& mainlist, const std::string& special,
                   const std::string& casedef_extra = "", bool two_d = false) {
    const std::string dir = test::scratchDir("solids_" + tag);
    CaseFile c;
    c.text = test::caseXml(mainlist, 0.1, two_d, casedef_extra, special);
    c.path = test::writeFile(dir, "Case_Def.xml", c.text);
    return c;
}

/// "path:LINE:" of the first line of `c` holding `needle`.
std::string at(const CaseFile& c, const std::string& needle) {
    const int line = test::lineOf(c.text, needle);
    EXPECT_GT(line, 0) << needle;
    return c.path + ":" + std::to_string(line) + ":";
}

// Clamp block (mkbound 0): x in {-0.1, 0}, y and z in {-0.1, 0, 0.1, 0.2} -> 2*4*4 = 32.
// Beam (mkbound 1): x in {0.1 .. 0.5} (5 sites), y and z in {0, 0.1} -> 5*2*2 = 20 sites.
// Two fluid particles far away (x = 2, 2.1) so that the solid block sits between the
// boundaries and the fluid.
const char* kCantilever =
    "<setmkbound mk=\"0\"/><drawbox><boxfill>solid</boxfill><point x=\"-0.1\" y=\"-0.1\" z=\"-0.1\"/>"
    "<size x=\"0.1\" y=\"0.3\" z=\"0.3\"/></drawbox>\n"
    "<setmkbound mk=\"1\"/><drawbox><boxfill>solid</boxfill><point x=\"0.1\" y=\"0\" z=\"0\"/>"
    "<size x=\"0.4\" y=\"0.1\" z=\"0.1\"/></drawbox>\n"
    "<setmkfluid mk=\"0\"/><drawbox><boxfill>solid</boxfill><point x=\"2\" y=\"0\" z=\"0\"/>"
    "<size x=\"0.1\" y=\"0\" z=\"0\"/></drawbox>";

const char* kCantileverSolid =
    "<vcpmsolids>\n<solid mkbound=\"1\" mkclamp=\"0\" density=\"2500\" youngmod=\"3e6\" "
    "poissratio=\"0.3\" critstretch=\"0.01\" damping=\"1\"/>\n</vcpmsolids>";

/// Every solid-solid slot i->j has the mirror slot j->i (same kind and rest length); rest
/// lengths equal the actual distances; clamp slots point at fixed/moving particles.
void expectConsistentNetwork(const GeneratedCase& g) {
    const BondNetwork& b = g.bonds;
    const ParticleSet& p = g.particles;
    const double dp = g.constants.dp;
    auto row = [&](std::size_t id) { return id - b.first_solid; };
    for (std::size_t r = 0; r < b.solidCount(); ++r) {
        const std::size_t i = b.first_solid + r;
        ASSERT_EQ(p.type[i], ParticleType::Solid) << "row " << r;
        for (std::uint32_t s = b.offset[r]; s < b.offset[r + 1]; ++s) {
            const std::uint32_t j = b.neighbour[s];
            const Vec3d d = p.pos[j] - p.pos[i];
            EXPECT_NEAR(std::sqrt(dot(d, d)), b.rest_length[s], 1e-12);
            const bool second = (b.kind[s] & BondSecond) != 0;
            EXPECT_NEAR(b.rest_length[s], second ? std::sqrt(2.0) * dp : dp, 1e-15);
            if (b.kind[s] & BondClampFlag) {
                EXPECT_TRUE(p.type[j] == ParticleType::Fixed || p.type[j] == ParticleType::Moving);
                continue;
            }
            ASSERT_EQ(p.type[j], ParticleType::Solid);
            EXPECT_EQ(p.mk[j], p.mk[i]);
            int mirrors = 0;
            for (std::uint32_t t = b.offset[row(j)]; t < b.offset[row(j) + 1]; ++t)
                if (b.neighbour[t] == i) {
                    ++mirrors;
                    EXPECT_EQ(b.kind[t], b.kind[s]);
                    EXPECT_EQ(b.rest_length[t], b.rest_length[s]);
                }
            EXPECT_EQ(mirrors, 1) << "bond " << i << " -> " << j;
        }
    }
}

/// Slots counted by brute force over all particle pairs (independent of the site table).
std::size_t bruteForceSlots(const GeneratedCase& g, std::uint16_t clamp_mk) {
    const ParticleSet& p = g.particles;
    const double dp2 = g.constants.dp * g.constants.dp;
    std::size_t n = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (p.type[i] != ParticleType::Solid) continue;
        for (std::size_t j = 0; j < p.size(); ++j) {
            if (j == i || (p.mk[j] != p.mk[i] && p.mk[j] != clamp_mk)) continue;
            const Vec3d d = p.pos[j] - p.pos[i];
            const double r2 = dot(d, d);
            if (std::fabs(r2 - dp2) < 1e-9 || std::fabs(r2 - 2 * dp2) < 1e-9) ++n;
        }
    }
    return n;
}

}  // namespace

TEST(GencaseSolids, CantileverTypesMassesAndBondCounts) {
    const CaseFile c = writeCase("cantilever", kCantilever, kCantileverSolid);
    std::ostringstream log;
    const auto builder = test::buildCaseKeepBuilder(c.path, log);
    const GeneratedCase& g = builder->result();

    EXPECT_EQ(g.count(ParticleType::Fixed), 32u);
    EXPECT_EQ(g.count(ParticleType::Solid), 20u);
    EXPECT_EQ(g.count(ParticleType::Fluid), 2u);
    EXPECT_EQ(g.count(ParticleType::Moving), 0u);
    ASSERT_EQ(g.blocks.size(), 3u);
    // Order fixed, solid, fluid: the beam (mk 1 + 9 + 1 = 11) takes ids 32..51.
    EXPECT_EQ(g.blocks[1].type, ParticleType::Solid);
    EXPECT_EQ(g.blocks[1].mk, 11);
    EXPECT_EQ(g.blocks[1].mk_local, 1);
    EXPECT_EQ(g.blocks[1].begin, 32u);
    EXPECT_EQ(g.blocks[1].count, 20u);
    EXPECT_EQ(g.bonds.first_solid, 32u);
    for (std::size_t i = 0; i < g.particles.size(); ++i) {
        const bool solid = i >= 32 && i < 52;
        EXPECT_EQ(g.particles.type[i] == ParticleType::Solid, solid) << i;
        // Solid mass = density * dp^3 = 2500 * 0.001 = 2.5 kg.
        const float mass = solid ? 2.5f : float(i < 32 ? g.constants.massbound : g.constants.massfluid);
        EXPECT_FLOAT_EQ(g.particles.mass[i], mass) << i;
    }

    ASSERT_EQ(g.solids.size(), 1u);
    const SolidBody& s = g.solids[0];
    EXPECT_EQ(s.mkbound, 1);
    EXPECT_EQ(s.mk, 11);
    EXPECT_EQ(s.clamp_mkbound, std::vector<int>{0});
    EXPECT_EQ(s.clamp_mk, std::vector<std::uint16_t>{10});
    EXPECT_EQ(s.density, 2500);
    EXPECT_EQ(s.youngmod, 3e6);
    EXPECT_EQ(s.poissratio, 0.3);
    EXPECT_EQ(s.critstretch, 0.01);
    EXPECT_EQ(s.damping, 1);
    EXPECT_EQ(s.declared_in, "vcpmsolids");
    EXPECT_EQ(s.line, test::lineOf(c.text, "<solid "));

    // Solid-solid bonds of a 5x2x2 block. First neighbours: along x 4*2*2 = 16, along y
    // 5*1*2 = 10, along z 5*2*1 = 10 -> 36. Face diagonals: xy planes 2 layers * 4 squares * 2
    // = 16, xz planes 2 * 4 * 2 = 16, yz planes 5 * 1 * 2 = 10 -> 42. Total 78.
    // Clamp bonds: the 4 beam particles at x = 0.1 each see the clamp site at dx = -1 (first)
    // and the 4 sites (dx=-1, dy=+-1) and (dx=-1, dz=+-1) (second; the clamp is wider than the
    // beam) -> 4 * 5 = 20 (4 first, 16 second). No other beam particle is within sqrt(2) dp
    // of the clamp. Every particle has fewer than 18 bonds: 20 surface particles.
    EXPECT_EQ(g.bond_stats.solid_particles, 20u);
    EXPECT_EQ(g.bond_stats.bonds, 78u);
    EXPECT_EQ(g.bond_stats.clamp_bonds, 20u);
    EXPECT_EQ(g.bond_stats.surface_particles, 20u);
    EXPECT_EQ(g.bond_stats.isolated_particles, 0u);
    EXPECT_EQ(g.bonds.solidCount(), 20u);
    EXPECT_EQ(g.bonds.bondSlots(), 2u * 78u + 20u);
    EXPECT_EQ(g.bonds.bondSlots(), bruteForceSlots(g, 10));
    std::size_t first = 0, second = 0, clamp_first = 0, clamp_second = 0;
    for (std::uint8_t k : g.bonds.kind) {
        if (k == BondFirst) ++first;
        if (k == BondSecond) ++second;
        if (k == (BondFirst | BondClampFlag)) ++clamp_first;
        if (k == (BondSecond | BondClampFlag)) ++clamp_second;
    }
    EXPECT_EQ(first, 2u * 36u);
    EXPECT_EQ(second, 2u * 42u);
    EXPECT_EQ(clamp_first, 4u);
    EXPECT_EQ(clamp_second, 16u);
    expectConsistentNetwork(g);
    // The free-end corner (0.5, 0, 0): first -x, +y, +z (3); second (-1,+1,0), (-1,0,+1),
    // (0,+1,+1) (3) -> 6 slots.
    int corners = 0;
    for (std::size_t r = 0; r < g.bonds.solidCount(); ++r) {
        const Vec3d x = g.particles.pos[32 + r];
        if (std::fabs(x.x - 0.5) < 1e-9 && std::fabs(x.y) < 1e-9 && std::fabs(x.z) < 1e-9) {
            ++corners;
            EXPECT_EQ(g.bonds.offset[r + 1] - g.bonds.offset[r], 6u);
        }
    }
    EXPECT_EQ(corners, 1);
    EXPECT_NE(log.str().find("VCPM solids: 20 particles, 78 bonds, 20 clamp bonds"), std::string::npos)
        << log.str();
}

TEST(GencaseSolids, ResolvedCaseListsTheSolidsAndCounts) {
    const CaseFile c = writeCase("resolved", kCantilever, kCantileverSolid);
    std::ostringstream log;
    const auto builder = test::buildCaseKeepBuilder(c.path, log);
    pugi::xml_document doc;
    buildResolvedCase(doc, builder->source(), builder->result(), "Case.h5");
    const pugi::xml_node exec = doc.child("case").child("execution");
    const pugi::xml_node v = exec.child("vcpmsolids");
    ASSERT_TRUE(v);
    const std::pair<const char*, unsigned> counts[] = {
        {"particles", 20}, {"bonds", 78}, {"clampbonds", 20}, {"surface", 20}, {"bondslots", 176}};
    for (const auto& [name, value] : counts) EXPECT_EQ(v.attribute(name).as_uint(), value) << name;
    const pugi::xml_node s = v.child("solid");
    ASSERT_TRUE(s);
    EXPECT_FALSE(s.next_sibling("solid"));
    EXPECT_EQ(s.attribute("mkbound").as_int(), 1);
    EXPECT_EQ(s.attribute("mk").as_int(), 11);
    EXPECT_STREQ(s.attribute("mkclamp").value(), "0");
    const std::pair<const char*, double> material[] = {
        {"density", 2500}, {"youngmod", 3e6}, {"poissratio", 0.3}, {"critstretch", 0.01}, {"damping", 1}};
    for (const auto& [name, value] : material) EXPECT_EQ(s.attribute(name).as_double(), value) << name;
    EXPECT_STREQ(s.attribute("declaredin").value(), "vcpmsolids");
    EXPECT_EQ(s.attribute("particles").as_ullong(), 20u);
    const pugi::xml_node parts = exec.child("particles");
    EXPECT_EQ(parts.attribute("np").as_ullong(), 54u);
    EXPECT_EQ(parts.attribute("nsolid").as_ullong(), 20u);
    const pugi::xml_node block = parts.child("solid");
    ASSERT_TRUE(block);
    EXPECT_EQ(block.attribute("mkbound").as_int(), 1);
    EXPECT_EQ(block.attribute("begin").as_ullong(), 32u);
    EXPECT_EQ(block.attribute("count").as_ullong(), 20u);
}

TEST(GencaseSolids, TwoDimensionalSolidHasFourPlusFourNeighbours) {
    const std::vector<Vec3i>& off = latticeOffsets(true);
    ASSERT_EQ(off.size(), 8u);
    EXPECT_EQ(firstNeighbourCount(true), 4u);
    for (std::size_t k = 0; k < off.size(); ++k) {
        EXPECT_EQ(off[k].y, 0);
        EXPECT_EQ(off[k].x * off[k].x + off[k].z * off[k].z, k < 4 ? 1 : 2);
    }
    // Clamp row (mkbound 0): z = -0.1, x = -0.1 .. 0.3 (5 sites). Solid (mkbound 1): 3 x 3
    // at x, z in {0, 0.1, 0.2}.
    const CaseFile c = writeCase("solid2d",
        "<setmkbound mk=\"0\"/><drawbox><boxfill>solid</boxfill><point x=\"-0.1\" y=\"0\" z=\"-0.1\"/>"
        "<size x=\"0.4\" y=\"0\" z=\"0\"/></drawbox>"
        "<setmkbound mk=\"1\"/><drawbox><boxfill>solid</boxfill><point x=\"0\" y=\"0\" z=\"0\"/>"
        "<size x=\"0.2\" y=\"0\" z=\"0.2\"/></drawbox>",
        "<vcpmsolids><solid mkbound=\"1\" mkclamp=\"0\" density=\"2500\" youngmod=\"3e6\" "
        "poissratio=\"0.3\"/></vcpmsolids>",
        "", true);
    const GeneratedCase g = test::buildCase(c.path);
    EXPECT_EQ(g.constants.dimensions, 2);
    EXPECT_EQ(g.count(ParticleType::Fixed), 5u);
    EXPECT_EQ(g.count(ParticleType::Solid), 9u);
    EXPECT_EQ(g.bonds.first_solid, 5u);
    // 2D mass = density * dp^2 = 2500 * 0.01 = 25 kg (per unit depth).
    for (std::size_t i = 5; i < 14; ++i) EXPECT_FLOAT_EQ(g.particles.mass[i], 25.0f);
    // 3x3 square lattice: first 2*3 (x) + 3*2 (z) = 12, diagonals 4 squares * 2 = 8 -> 20.
    // Clamp: the bottom row (3 particles) each bonds straight down (first) and to both lower
    // diagonals (second; the clamp row reaches x = -0.1 and 0.3) -> 3 * 3 = 9.
    // Complete (8 slots): the centre and the bottom middle -> surface 9 - 2 = 7.
    EXPECT_EQ(g.bond_stats.bonds, 20u);
    EXPECT_EQ(g.bond_stats.clamp_bonds, 9u);
    EXPECT_EQ(g.bond_stats.surface_particles, 7u);
    EXPECT_EQ(g.bonds.bondSlots(), 2u * 20u + 9u);
    EXPECT_EQ(g.bonds.bondSlots(), bruteForceSlots(g, 10));
    expectConsistentNetwork(g);
    for (std::size_t r = 0; r < 9; ++r) {
        const Vec3d x = g.particles.pos[5 + r];
        EXPECT_EQ(x.y, 0.0);
        const bool complete =
            std::fabs(x.x - 0.1) < 1e-9 && (std::fabs(x.z - 0.1) < 1e-9 || std::fabs(x.z) < 1e-9);
        const std::uint32_t slots = g.bonds.offset[r + 1] - g.bonds.offset[r];
        if (complete) EXPECT_EQ(slots, 8u) << r;
        else EXPECT_LT(slots, 8u) << r;
    }
}

TEST(GencaseSolids, FlexstrucBodyWithMvnullBecomesASolid) {
    // As in DualSPHysics' flexstruc examples: clamp mkbound 1, body mkbound 2 with mvnull.
    const std::string mainlist =
        "<setmkbound mk=\"1\"/><drawbox><boxfill>solid</boxfill><point x=\"-0.1\" y=\"-0.1\" z=\"-0.1\"/>"
        "<size x=\"0.1\" y=\"0.3\" z=\"0.3\"/></drawbox>"
        "<setmkbound mk=\"2\"/><drawbox><boxfill>solid</boxfill><point x=\"0.1\" y=\"0\" z=\"0\"/>"
        "<size x=\"0.4\" y=\"0.1\" z=\"0.1\"/></drawbox>";
    const std::string motion =
        "<motion><objreal ref=\"2\"><begin mov=\"1\" start=\"0\"/><mvnull id=\"1\"/></objreal></motion>";
    const std::string special =
        "<flexstrucs>\n<flexstrucbody mkbound=\"2\" mkclamp=\"1\"><density value=\"1000\"/>"
        "<youngmod value=\"1e6\"/><poissratio value=\"0.4\"/><constitmodel value=\"3\"/>"
        "<hgfactor value=\"0.1\"/></flexstrucbody>\n</flexstrucs>";
    const CaseFile c = writeCase("flexstruc", mainlist, special, motion);
    std::ostringstream log;
    const auto builder = test::buildCaseKeepBuilder(c.path, log);
    const GeneratedCase& g = builder->result();
    ASSERT_EQ(g.solids.size(), 1u);
    EXPECT_EQ(g.solids[0].declared_in, "flexstrucs");
    EXPECT_EQ(g.solids[0].mkbound, 2);
    EXPECT_EQ(g.solids[0].clamp_mkbound, std::vector<int>{1});
    EXPECT_EQ(g.solids[0].density, 1000);
    EXPECT_EQ(g.solids[0].youngmod, 1e6);
    EXPECT_EQ(g.solids[0].poissratio, 0.4);
    EXPECT_EQ(g.solids[0].line, test::lineOf(c.text, "<flexstrucbody"));
    ASSERT_EQ(g.motion.objects.size(), 1u);
    EXPECT_EQ(g.motion.objects[0].mkbound, 2);
    ASSERT_EQ(g.motion.objects[0].movements.size(), 1u);
    EXPECT_EQ(g.motion.objects[0].movements[0].kind, MovementKind::Null);
    // mvnull does not make it a moving boundary: same counts as the vcpmsolids cantilever.
    EXPECT_EQ(g.count(ParticleType::Moving), 0u);
    EXPECT_EQ(g.count(ParticleType::Fixed), 32u);
    EXPECT_EQ(g.count(ParticleType::Solid), 20u);
    EXPECT_EQ(g.bond_stats.bonds, 78u);
    EXPECT_EQ(g.bond_stats.clamp_bonds, 20u);
    for (std::size_t i = 32; i < 52; ++i) {
        EXPECT_EQ(g.particles.type[i], ParticleType::Solid);
        EXPECT_FLOAT_EQ(g.particles.mass[i], 1.0f);  // 1000 * 0.1^3
    }
    EXPECT_NE(log.str().find("<flexstrucbody mkbound=\"2\"> is modelled as a VCPM lattice solid"),
              std::string::npos);
    pugi::xml_document doc;
    buildResolvedCase(doc, builder->source(), g, "Case.h5");
    const pugi::xml_node s = doc.child("case").child("execution").child("vcpmsolids").child("solid");
    EXPECT_STREQ(s.attribute("declaredin").value(), "flexstrucs");
    EXPECT_STREQ(s.attribute("mkclamp").value(), "1");
}

// DualSPHysics' constitmodel: 2 (plane stress) in a 2D case is kept and written to the resolved
// case (the solver then uses physics::planeStressEquivalent); a model that does not fit the
// case's dimension stops gencase with the element's line.
TEST(GencaseSolids, ConstitModelIsKeptAndMustFitTheDimension) {
    const std::string mainlist2d =
        "<setmkbound mk=\"0\"/><drawbox><boxfill>solid</boxfill><point x=\"-0.1\" y=\"0\" z=\"-0.1\"/>"
        "<size x=\"0.4\" y=\"0\" z=\"0\"/></drawbox>"
        "<setmkbound mk=\"1\"/><drawbox><boxfill>solid</boxfill><point x=\"0\" y=\"0\" z=\"0\"/>"
        "<size x=\"0.2\" y=\"0\" z=\"0.2\"/></drawbox>";
    const CaseFile c = writeCase("constit2d", mainlist2d,
        "<vcpmsolids><solid mkbound=\"1\" mkclamp=\"0\" density=\"2500\" youngmod=\"3e6\" "
        "poissratio=\"0.3\" constitmodel=\"2\"/></vcpmsolids>", "", true);
    std::ostringstream log;
    const auto builder = test::buildCaseKeepBuilder(c.path, log);
    const GeneratedCase& g = builder->result();
    ASSERT_EQ(g.solids.size(), 1u);
    EXPECT_EQ(g.solids[0].constitmodel, 2);
    pugi::xml_document doc;
    buildResolvedCase(doc, builder->source(), g, "Case.h5");
    EXPECT_STREQ(doc.child("case").child("execution").child("vcpmsolids").child("solid").attribute("constitmodel").value(),
                 "2");
    // flexstrucbody's child element, 2D.
    const CaseFile f = writeCase("constit2d_flex", mainlist2d,
        "<flexstrucs>\n<flexstrucbody mkbound=\"1\" mkclamp=\"0\"><density value=\"1000\"/>"
        "<youngmod value=\"1e6\"/><poissratio value=\"0.4\"/><constitmodel value=\"2\"/></flexstrucbody>\n"
        "</flexstrucs>", "", true);
    EXPECT_EQ(test::buildCase(f.path).solids.at(0).constitmodel, 2);
    // 3 (St Venant-Kirchhoff, 3D) in 2D, 2 (plane stress) in 3D, and an unknown model.
    const CaseFile e2 = writeCase("constit_err2d", mainlist2d,
        "<vcpmsolids>\n<solid mkbound=\"1\" mkclamp=\"0\" density=\"2500\" youngmod=\"3e6\" "
        "poissratio=\"0.3\" constitmodel=\"3\"/>\n</vcpmsolids>", "", true);
    std::string m = test::buildError(e2.path);
    EXPECT_NE(m.find(at(e2, "<solid ")), std::string::npos) << m;
    EXPECT_NE(m.find("constitmodel=3 (St Venant-Kirchhoff, 3D) in a 2D case"), std::string::npos) << m;
    const CaseFile e3 = writeCase("constit_err3d", kCantilever,
        "<vcpmsolids>\n<solid mkbound=\"1\" mkclamp=\"0\" density=\"2500\" youngmod=\"3e6\" "
        "poissratio=\"0.3\" constitmodel=\"2\"/>\n</vcpmsolids>");
    m = test::buildError(e3.path);
    EXPECT_NE(m.find("constitmodel=2 (plane stress, 2D) in a 3D case"), std::string::npos) << m;
    const CaseFile e4 = writeCase("constit_err7", kCantilever,
        "<vcpmsolids>\n<solid mkbound=\"1\" mkclamp=\"0\" density=\"2500\" youngmod=\"3e6\" "
        "poissratio=\"0.3\" constitmodel=\"7\"/>\n</vcpmsolids>");
    m = test::buildError(e4.path);
    EXPECT_NE(m.find("constitmodel=7: expected 1 (plane strain, 2D), 2 (plane stress, 2D) or 3 (3D)"),
              std::string::npos) << m;
}

// ---- Errors: the message names the file, the line of the offending element and the value.

namespace {

/// `<vcpmsolids>` with one `<solid ATTRS/>` per entry, each on its own line.
std::string solids(std::initializer_list<const char*> attrs) {
    std::string out = "<vcpmsolids>\n";
    for (const char* a : attrs) out += std::string("<solid ") + a + "/>\n";
    return out + "</vcpmsolids>";
}

/// Building `c` throws seaspring::Error; its message holds "path:LINE:" (LINE: first line of
/// the case holding `needle`) and each of `parts`.
void expectBuildError(const CaseFile& c, const std::string& needle,
                      std::initializer_list<std::string> parts) {
    EXPECT_THROW(test::buildCase(c.path), Error);
    const std::string m = test::buildError(c.path);
    EXPECT_NE(m.find(at(c, needle)), std::string::npos) << m;
    for (const std::string& p : parts) EXPECT_NE(m.find(p), std::string::npos) << "'" << p << "' in " << m;
}

}  // namespace

TEST(GencaseSolidsErrors, SolidMkWithoutParticles) {
    const CaseFile c = writeCase("err_noparticles", kCantilever,
        solids({"mkbound=\"5\" density=\"2500\" youngmod=\"3e6\" poissratio=\"0.3\""}));
    expectBuildError(c, "<solid ", {"solid mkbound=5 has no particles"});
}

TEST(GencaseSolidsErrors, ClampMkWithoutParticles) {
    const CaseFile c = writeCase("err_noclamp", kCantilever,
        solids({"mkbound=\"1\" mkclamp=\"7\" density=\"2500\" youngmod=\"3e6\" poissratio=\"0.3\""}));
    expectBuildError(c, "<solid ", {"mkclamp 7 does not exist"});
}

TEST(GencaseSolidsErrors, PoissonRatioHalfIsRejected) {
    const CaseFile c = writeCase("err_poisson", kCantilever,
        solids({"mkbound=\"1\" mkclamp=\"0\" density=\"2500\" youngmod=\"3e6\" poissratio=\"0.5\""}));
    expectBuildError(c, "<solid ", {"<solid> poissratio=0.5", "must lie in (-1, 0.5)"});
}

TEST(GencaseSolidsErrors, ZeroYoungModulusIsRejected) {
    const CaseFile c = writeCase("err_young", kCantilever,
        solids({"mkbound=\"1\" mkclamp=\"0\" density=\"2500\" youngmod=\"0\" poissratio=\"0.3\""}));
    expectBuildError(c, "<solid ", {"<solid> youngmod=0", "must be > 0"});
    const CaseFile f = writeCase("err_flexyoung", kCantilever,
        "<flexstrucs>\n<flexstrucbody mkbound=\"1\" mkclamp=\"0\"><density value=\"1000\"/>"
        "<youngmod value=\"0\"/><poissratio value=\"0.3\"/></flexstrucbody>\n</flexstrucs>");
    expectBuildError(f, "<flexstrucbody", {"<flexstrucbody> youngmod=0", "must be > 0"});
}

TEST(GencaseSolidsErrors, SolidWithPrescribedMotionIsRejected) {
    const std::string motion =
        "<motion>\n<objreal ref=\"1\"><begin mov=\"1\" start=\"0\"/><mvrect id=\"1\" duration=\"1\">"
        "<vel x=\"1\" y=\"0\" z=\"0\"/></mvrect></objreal>\n</motion>";
    const CaseFile c = writeCase("err_motion", kCantilever, kCantileverSolid, motion);
    expectBuildError(c, "<solid ", {"solid mkbound=1 has a prescribed motion (line " +
                                        std::to_string(test::lineOf(c.text, "<objreal")) + ")",
                                    "only mvnull is allowed"});
}

TEST(GencaseSolidsErrors, ClampNamingAnotherSolid) {
    const std::string mainlist = std::string(kCantilever) +
        "<setmkbound mk=\"2\"/><drawbox><boxfill>solid</boxfill><point x=\"0.6\" y=\"0\" z=\"0\"/>"
        "<size x=\"0.2\" y=\"0.1\" z=\"0.1\"/></drawbox>";
    const CaseFile c = writeCase("err_clampsolid", mainlist,
        solids({"mkbound=\"1\" mkclamp=\"0\" density=\"2500\" youngmod=\"3e6\" poissratio=\"0.3\"",
                "mkbound=\"2\" mkclamp=\"1\" density=\"2500\" youngmod=\"3e6\" poissratio=\"0.3\""}));
    expectBuildError(c, "<solid mkbound=\"2\"", {"mkclamp 1 is itself a solid"});
}

TEST(GencaseSolidsErrors, ClampNamingItself) {
    const CaseFile c = writeCase("err_clampself", kCantilever,
        solids({"mkbound=\"1\" mkclamp=\"0,1\" density=\"2500\" youngmod=\"3e6\" poissratio=\"0.3\""}));
    expectBuildError(c, "<solid ", {"mkclamp names the solid's own mkbound 1"});
}

TEST(GencaseSolidsErrors, DuplicateSolidMkbound) {
    const CaseFile c = writeCase("err_duplicate", kCantilever,
        solids({"mkbound=\"1\" mkclamp=\"0\" density=\"2500\" youngmod=\"3e6\" poissratio=\"0.3\"",
                "mkbound=\"1\" density=\"1000\" youngmod=\"1e6\" poissratio=\"0.2\""}));
    expectBuildError(c, "<solid mkbound=\"1\" density",
                     {"solid mkbound=1 is declared twice (first at line " +
                      std::to_string(test::lineOf(c.text, "<solid mkbound=\"1\" mkclamp")) + ")"});
    const CaseFile f = writeCase("err_duplicate2", kCantilever,
        std::string(kCantileverSolid) + "<flexstrucs>\n<flexstrucbody mkbound=\"1\"><density value=\"1000\"/>"
        "<youngmod value=\"1e6\"/><poissratio value=\"0.3\"/></flexstrucbody>\n</flexstrucs>");
    expectBuildError(f, "<flexstrucbody", {"solid mkbound=1 is declared twice"});
}

TEST(GencaseSolidsErrors, IsolatedSolidParticle) {
    // drawbox of size 0: one solid particle (mkbound 3 -> mk 3 + 9 + 1 = 13) at (2, 2, 2) with
    // no lattice neighbour. Reported at <special>: the bond builder does not know the <solid>.
    const std::string mainlist = std::string(kCantilever) +
        "<setmkbound mk=\"3\"/><drawbox><boxfill>solid</boxfill><point x=\"2\" y=\"2\" z=\"2\"/>"
        "<size x=\"0\" y=\"0\" z=\"0\"/></drawbox>";
    const CaseFile c = writeCase("err_isolated", mainlist,
        solids({"mkbound=\"1\" mkclamp=\"0\" density=\"2500\" youngmod=\"3e6\" poissratio=\"0.3\"",
                "mkbound=\"3\" density=\"2500\" youngmod=\"3e6\" poissratio=\"0.3\""}));
    expectBuildError(c, "<special>", {"1 solid particle(s) have no bond at all", "mk 13", "at (2, 2, 2)"});
}

TEST(GencaseSolidsErrors, UnknownAttributeAndChild) {
    const CaseFile a = writeCase("err_attr", kCantilever,
        solids({"mkbound=\"1\" density=\"2500\" youngmod=\"3e6\" poissratio=\"0.3\" stiffness=\"2\""}));
    expectBuildError(a, "<solid ", {"unknown attribute 'stiffness=\"2\"'"});
    const CaseFile b = writeCase("err_child", kCantilever,
        "<flexstrucs><flexstrucbody mkbound=\"1\"><density value=\"1000\"/><youngmod value=\"1e6\"/>"
        "<poissratio value=\"0.3\"/>\n<thickness value=\"1\"/></flexstrucbody></flexstrucs>");
    expectBuildError(b, "<thickness", {"unknown element <thickness> inside <flexstrucbody>"});
}

// Regression: a second <vcpmsolids> block is an error, not ignored.
TEST(GencaseSolidsErrors, SecondVcpmsolidsBlockIsNotIgnored) {
    const CaseFile c = writeCase("err_second_block", kCantilever,
        std::string(kCantileverSolid) +
        "\n<vcpmsolids><solid mkbound=\"3\" density=\"2500\" youngmod=\"3e6\" poissratio=\"0.7\"/></vcpmsolids>");
    const std::string m = test::buildError(c.path);
    EXPECT_NE(m, "") << "a second <vcpmsolids> was silently ignored";
    EXPECT_NE(m.find(c.path + ":" + std::to_string(test::lineOf(c.text, "<solid mkbound=\"3\""))),
              std::string::npos) << m;
}
