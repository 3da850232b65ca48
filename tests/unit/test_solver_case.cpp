// SeaSpring — MIT licence.
/// \file test_solver_case.cpp
/// \brief loadSolverCase on cases generated in-process by gencase (a pool, a case with a
///        moving boundary, a VCPM solid and gauges, a 2D case), and on edited copies of the
///        resolved XML: every error names the file, the line and the offending value.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "gencase_test_util.h"
#include "io/case_h5.h"
#include "solver/solver_case.h"

using namespace seaspring;
using solver::loadSolverCase;

namespace fs = std::filesystem;

namespace {

using test::kPool;  // gencase_test_util.h

// The pool plus a moving wall (mkbound 1, x = -0.1: 25), a VCPM beam (mkbound 2: 3*2*2 = 12)
// clamped to a block (mkbound 3: 2*2*2 = 8).
const char* kMovingAndSolid =
    "<setmkbound mk=\"1\"/><drawbox><boxfill>solid</boxfill><point x=\"-0.1\" y=\"0\" z=\"0\"/>"
    "<size x=\"0\" y=\"0.4\" z=\"0.4\"/></drawbox>\n"
    "<setmkbound mk=\"2\"/><drawbox><boxfill>solid</boxfill><point x=\"0.6\" y=\"0\" z=\"0\"/>"
    "<size x=\"0.2\" y=\"0.1\" z=\"0.1\"/></drawbox>\n"
    "<setmkbound mk=\"3\"/><drawbox><boxfill>solid</boxfill><point x=\"0.9\" y=\"0\" z=\"0\"/>"
    "<size x=\"0.1\" y=\"0.1\" z=\"0.1\"/></drawbox>";
const char* kMotion =
    "<motion><objreal ref=\"1\"><begin mov=\"1\" start=\"0\"/><mvrect id=\"1\" duration=\"1\">"
    "<vel x=\"0.1\" y=\"0\" z=\"0\"/></mvrect></objreal></motion>";
const char* kSolid =
    "<vcpmsolids><solid mkbound=\"2\" mkclamp=\"3\" density=\"2500\" youngmod=\"3e6\" "
    "poissratio=\"0.3\"/></vcpmsolids>\n<gauges><default><output value=\"true\"/></default>"
    "<velocity name=\"V\"><point x=\"#1/4\" y=\"0\" z=\"0\"/></velocity></gauges>";

std::string readText(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

/// A case generated in-process: OUT/Case.xml and OUT/Case.h5.
struct Generated {
    std::string dir, base, xml;  ///< scratch dir, OUTDIR/NAME, text of NAME.xml
    gencase::GeneratedCase g;    ///< what gencase generated
};

Generated generate(const std::string& tag, const std::string& mainlist,
                   const std::string& casedef_extra = "", const std::string& special = "",
                   const std::string& parameters = "", bool two_d = false) {
    Generated r;
    r.dir = test::scratchDir("solver_case_" + tag);
    const std::string def =
        test::writeFile(r.dir, "Case_Def.xml",
                        test::caseXml(mainlist, 0.1, two_d, casedef_extra, special, parameters));
    std::ostringstream log;
    auto b = test::buildCaseKeepBuilder(def, log);
    b->write();
    r.g = b->result();
    r.base = r.dir + "/out/Case";
    r.xml = readText(r.base + ".xml");
    return r;
}

const Generated& pool() {
    static const Generated p = generate("pool", kPool);
    return p;
}

/// The resolved XML with the first `from` after `after` replaced by `to`, written next to the
/// original as NAME.xml (so that it names the same Case.h5), and the message of loading it
/// ("" when it loads). `after` = "<execution>" skips the copy of the definition in <casedef>.
struct Edited {
    std::string path, text, error, after;
    /// "PATH:LINE" of the first line after `after` holding `needle`.
    std::string where(const std::string& needle) const {
        const std::size_t from = text.find(after);
        const std::size_t at = text.find(needle, from == std::string::npos ? 0 : from);
        EXPECT_NE(at, std::string::npos) << "'" << needle << "' is not in the edited case";
        if (at == std::string::npos) return path + ":?";
        return path + ":" +
               std::to_string(1 +
                              std::count(text.begin(), text.begin() + std::ptrdiff_t(at), '\n'));
    }
    /// "PATH:LINE:" as in errors thrown for the XML.
    std::string at(const std::string& needle) const { return where(needle) + ":"; }
};

Edited edit(const Generated& c, const std::string& from, const std::string& to,
            const std::string& after = "<execution>") {
    Edited e;
    e.text = c.xml;
    e.after = after;
    const std::size_t start = e.text.find(after);
    EXPECT_NE(start, std::string::npos) << "'" << after << "' is not in the resolved case";
    const std::size_t at = e.text.find(from, start == std::string::npos ? 0 : start);
    EXPECT_NE(at, std::string::npos) << "'" << from << "' is not in the resolved case";
    if (at != std::string::npos) e.text.replace(at, from.size(), to);
    e.path = test::writeFile(c.dir + "/out", "Edited.xml", e.text);
    try {
        loadSolverCase(e.path);
    } catch (const Error& err) {
        e.error = err.what();
    }
    return e;
}

void expectContains(const std::string& text, const std::string& what) {
    EXPECT_NE(text.find(what), std::string::npos) << "expected '" << what << "' in:\n" << text;
}

/// Replaces the value of parameter `key` and expects "PATH:LINE: <parameter> key=".." value="..":
/// ... with each of `parts` in the message.
void expectParameterError(const std::string& key, const std::string& old_value,
                          const std::string& value, std::initializer_list<const char*> parts) {
    SCOPED_TRACE(key + "=" + value);
    const std::string from = "key=\"" + key + "\" value=\"" + old_value + "\"";
    const Edited e = edit(pool(), from, "key=\"" + key + "\" value=\"" + value + "\"");
    ASSERT_FALSE(e.error.empty()) << "loaded despite " << key << "=" << value;
    expectContains(e.error, e.at("key=\"" + key + "\"") + " <parameter> key=\"" + key +
                                "\" value=\"" + value + "\"");
    for (const char* p : parts) expectContains(e.error, p);
}

}  // namespace

// ---- Loading generated cases ---------------------------------------------------------------

TEST(SolverCase, LoadsThePoolAsGencaseWroteIt) {
    const Generated& p = pool();
    const solver::SolverCase c = loadSolverCase(p.base);
    EXPECT_EQ(c.name, "Case");
    EXPECT_EQ(c.xml_path, p.base + ".xml");
    EXPECT_EQ(fs::canonical(c.h5_path), fs::canonical(p.base + ".h5"));
    EXPECT_EQ(c.nfixed, 25u);
    EXPECT_EQ(c.nmoving, 0u);
    EXPECT_EQ(c.nsolid, 0u);
    EXPECT_EQ(c.nfluid, 125u);
    ASSERT_EQ(c.blocks.size(), 2u);
    EXPECT_EQ(c.blocks[0].type, ParticleType::Fixed);
    EXPECT_EQ(c.blocks[0].mk, 10);
    EXPECT_EQ(c.blocks[0].mk_local, 0);
    EXPECT_EQ(c.blocks[0].begin, 0u);
    EXPECT_EQ(c.blocks[0].count, 25u);
    EXPECT_EQ(c.blocks[1].type, ParticleType::Fluid);
    EXPECT_EQ(c.blocks[1].mk, 1);
    EXPECT_EQ(c.blocks[1].mk_local, 0);
    EXPECT_EQ(c.blocks[1].begin, 25u);
    EXPECT_EQ(c.blocks[1].count, 125u);
    // Constants and domain round-trip exactly (written with 17 digits).
    EXPECT_EQ(c.constants.dimensions, 3);
    EXPECT_EQ(c.constants.dp, p.g.constants.dp);
    EXPECT_EQ(c.constants.h, p.g.constants.h);
    EXPECT_EQ(c.constants.speedsound, p.g.constants.speedsound);
    EXPECT_EQ(c.constants.b, p.g.constants.b);
    EXPECT_EQ(c.constants.massfluid, p.g.constants.massfluid);
    EXPECT_EQ(c.constants.massbound, p.g.constants.massbound);
    EXPECT_EQ(c.params.cfl_number, p.g.constants.cflnumber);
    EXPECT_EQ(c.domain_min.x, p.g.domain.min.x);
    EXPECT_EQ(c.domain_min.z, p.g.domain.min.z);
    EXPECT_EQ(c.domain_max.y, p.g.domain.max.y);
    EXPECT_EQ(c.domain_max.z, p.g.domain.max.z);
    // Particles are those gencase generated.
    ASSERT_EQ(c.particles.size(), p.g.particles.size());
    for (std::size_t i = 0; i < c.particles.size(); ++i) {
        ASSERT_EQ(c.particles.id[i], p.g.particles.id[i]) << i;
        ASSERT_EQ(c.particles.pos[i].z, p.g.particles.pos[i].z) << i;
        ASSERT_EQ(c.particles.rhop[i], p.g.particles.rhop[i]) << i;
    }
    EXPECT_FALSE(c.bonds.has_value());
    EXPECT_TRUE(c.motion.empty());
    EXPECT_EQ(c.solid_bodies, 0u);
    EXPECT_TRUE(c.notes.empty());
}

TEST(SolverCase, DefaultsAndGivenParameters) {
    const solver::SolverCase d = loadSolverCase(pool().base);
    const solver::SolverParameters def;
    EXPECT_EQ(d.params.step_algorithm, def.step_algorithm);
    EXPECT_EQ(d.params.verlet_steps, 40);
    EXPECT_EQ(d.params.kernel, 2);
    EXPECT_EQ(d.params.visco_treatment, 1);
    EXPECT_EQ(d.params.visco, 0.1);
    EXPECT_EQ(d.params.time_max, 1.0);
    EXPECT_EQ(d.params.time_out, 0.1);
    EXPECT_EQ(d.params.rhop_out_min, 700);
    EXPECT_EQ(d.params.rhop_out_max, 1300);
    EXPECT_EQ(d.params.coef_dt_min, 0.05);
    EXPECT_EQ(d.params.density_dt, 0);
    EXPECT_EQ(d.params.density_dt_value, 0.1);
    EXPECT_FALSE(d.params.dt_all_particles);

    const Generated g = generate(
        "params", kPool, "", "",
        "<parameter key=\"StepAlgorithm\" value=\"2\"/><parameter key=\"VerletSteps\" "
        "value=\"30\"/>"
        "<parameter key=\"Kernel\" value=\"1\"/><parameter key=\"ViscoTreatment\" value=\"2\"/>"
        "<parameter key=\"ViscoBoundFactor\" value=\"2\"/><parameter key=\"DensityDT\" "
        "value=\"3\"/>"
        "<parameter key=\"DensityDTvalue\" value=\"0.2\"/><parameter key=\"CoefDtMin\" "
        "value=\"0.1\"/>"
        "<parameter key=\"DtIni\" value=\"1e-4\"/><parameter key=\"DtMin\" value=\"1e-5\"/>"
        "<parameter key=\"DtFixed\" value=\"2e-4\"/><parameter key=\"RhopOutMin\" value=\"800\"/>"
        "<parameter key=\"RhopOutMax\" value=\"1200\"/><parameter key=\"MinFluidStop\" "
        "value=\"0.5\"/>"
        "<parameter key=\"WrnPartsOut\" value=\"5\"/><parameter key=\"SlipMode\" value=\"2\"/>"
        "<parameter key=\"ShiftTFS\" value=\"1.5\"/>");
    const solver::SolverParameters p = loadSolverCase(g.base).params;
    EXPECT_EQ(p.step_algorithm, 2);
    EXPECT_EQ(p.verlet_steps, 30);
    EXPECT_EQ(p.kernel, 1);
    EXPECT_EQ(p.visco_treatment, 2);
    EXPECT_EQ(p.visco_bound_factor, 2.0);
    EXPECT_EQ(p.density_dt, 3);
    EXPECT_EQ(p.density_dt_value, 0.2);
    EXPECT_EQ(p.coef_dt_min, 0.1);
    EXPECT_EQ(p.dt_ini, 1e-4);
    EXPECT_EQ(p.dt_min, 1e-5);
    EXPECT_EQ(p.dt_fixed, 2e-4);
    EXPECT_EQ(p.rhop_out_min, 800);
    EXPECT_EQ(p.rhop_out_max, 1200);
    EXPECT_EQ(p.min_fluid_stop, 0.5);
    EXPECT_EQ(p.wrn_parts_out, 5);
}

TEST(SolverCase, PathMayNameTheXmlOrTheH5) {
    const Generated& p = pool();
    EXPECT_EQ(loadSolverCase(p.base + ".xml").xml_path, p.base + ".xml");
    EXPECT_EQ(loadSolverCase(p.base + ".h5").xml_path, p.base + ".xml");
}

TEST(SolverCase, AbsentKeyTakesTheTableDefault) {
    const Edited e = edit(pool(), "<parameter key=\"Kernel\" value=\"2\" />", "");
    EXPECT_EQ(e.error, "");
    EXPECT_EQ(loadSolverCase(e.path).params.kernel, 2);
}

TEST(SolverCase, MovingBoundarySolidAndGauges) {
    const Generated g =
        generate("moving_solid", std::string(kPool) + "\n" + kMovingAndSolid, kMotion, kSolid);
    const solver::SolverCase c = loadSolverCase(g.base);
    EXPECT_EQ(c.nfixed, 33u);  // floor 25 + clamp 8
    EXPECT_EQ(c.nmoving, 25u);
    EXPECT_EQ(c.nsolid, 12u);
    EXPECT_EQ(c.nfluid, 125u);
    ASSERT_EQ(c.blocks.size(), 5u);
    EXPECT_EQ(c.blocks[2].type, ParticleType::Moving);
    EXPECT_EQ(c.blocks[2].mk_local, 1);
    EXPECT_EQ(c.blocks[2].begin, 33u);
    EXPECT_EQ(c.blocks[3].type, ParticleType::Solid);
    EXPECT_EQ(c.blocks[3].mk_local, 2);
    ASSERT_EQ(c.motion.objects.size(), 1u);
    EXPECT_EQ(c.motion.objects[0].mkbound, 1);
    ASSERT_TRUE(c.bonds.has_value());
    EXPECT_EQ(c.bonds->first_solid, 58u);
    EXPECT_EQ(c.bonds->solidCount(), 12u);
    EXPECT_EQ(c.bonds->bondSlots(), g.g.bonds.bondSlots());
    EXPECT_EQ(c.solid_bodies, 1u);
    // The same SolidBody gencase wrote (the case model's), read back.
    ASSERT_EQ(c.solids.size(), 1u);
    ASSERT_EQ(g.g.solids.size(), 1u);
    EXPECT_EQ(c.solids[0].mkbound, 2);
    EXPECT_EQ(c.solids[0].mk, g.g.solids[0].mk);
    EXPECT_EQ(c.solids[0].clamp_mkbound, std::vector<int>{3});
    EXPECT_EQ(c.solids[0].clamp_mk, g.g.solids[0].clamp_mk);
    EXPECT_EQ(c.solids[0].youngmod, 3e6);
    EXPECT_EQ(c.solids[0].declared_in, "vcpmsolids");
    EXPECT_EQ(c.solids[0].particles, 12u);
    EXPECT_EQ(g.g.solids[0].particles, 12u);
    // The gauges as gencase resolved them (expression evaluated) are read back.
    EXPECT_TRUE(c.notes.empty());
    ASSERT_EQ(c.gauges.gauges.size(), 1u);
    EXPECT_EQ(c.gauges.gauges[0].kind, model::GaugeKind::Velocity);
    EXPECT_EQ(c.gauges.gauges[0].name, "V");
    EXPECT_EQ(c.gauges.gauges[0].point.x, 0.25);
    EXPECT_EQ(c.gauges.defaults.output, std::optional<bool>(true));
    const std::vector<std::string> lines = solver::describeCase(c);
    std::string all;
    for (const std::string& l : lines) all += l + "\n";
    expectContains(all, "particles: 195 (fixed 33, moving 25, solid 12, fluid 125), 3D");
    expectContains(all, "motion: 1 object(s)");
    expectContains(all,
                   "VCPM solids: 1 body, " + std::to_string(g.g.bonds.bondSlots()) + " bond slots");
}

TEST(SolverCase, TwoDimensionalCaseHasAFlatDomain) {
    const Generated g = generate(
        "2d",
        "<setmkbound mk=\"0\"/><drawbox><boxfill>solid</boxfill><point x=\"0\" y=\"0\" z=\"-0.2\"/>"
        "<size x=\"0.4\" y=\"0\" z=\"0\"/></drawbox>\n<setmkfluid "
        "mk=\"0\"/><drawbox><boxfill>solid</boxfill>"
        "<point x=\"0\" y=\"0\" z=\"0\"/><size x=\"0.4\" y=\"0\" z=\"0.4\"/></drawbox>",
        "", "", "", true);
    const solver::SolverCase c = loadSolverCase(g.base);
    EXPECT_EQ(c.constants.dimensions, 2);
    EXPECT_EQ(c.nfixed, 5u);
    EXPECT_EQ(c.nfluid, 25u);
    EXPECT_EQ(c.domain_min.y, c.domain_max.y);
}

TEST(SolverCase, DescribeCaseLines) {
    const solver::SolverCase c = loadSolverCase(pool().base);
    const std::vector<std::string> lines = solver::describeCase(c);
    ASSERT_GE(lines.size(), 4u);
    EXPECT_EQ(lines[0], "particles: 150 (fixed 25, moving 0, solid 0, fluid 125), 3D");
    expectContains(lines[1], "dp=0.1 m, h=");
    expectContains(lines[1], "c0=");
    expectContains(lines[1], "B=");
    expectContains(lines[2], "mass: fluid 1 kg, boundary 1 kg");
    EXPECT_EQ(lines[3], "domain: (0, 0, -0.2) - (0.4, 0.4, 0.4) m");
}

// ---- Files -------------------------------------------------------------------------------

TEST(SolverCaseErrors, MissingXml) {
    const std::string missing = pool().dir + "/out/Nothing";
    try {
        loadSolverCase(missing);
        FAIL() << "no error";
    } catch (const Error& e) {
        expectContains(e.what(), missing + ".xml: no such case file");
    }
}

TEST(SolverCaseErrors, MissingH5NamesTheFilesLine) {
    const Edited e = edit(pool(), "particles=\"Case.h5\"", "particles=\"Gone.h5\"");
    expectContains(e.error, e.at("<files") + " <files> particles=\"Gone.h5\": ");
    expectContains(e.error, "Gone.h5 does not exist");
}

TEST(SolverCaseErrors, H5RemovedNextToItsXml) {
    const Generated g = generate("noh5", kPool);
    fs::remove(g.base + ".h5");
    try {
        loadSolverCase(g.base);
        FAIL() << "no error";
    } catch (const Error& e) {
        expectContains(e.what(),
                       g.base + ".xml:" + std::to_string(test::lineOf(g.xml, "<files")) + ":");
        expectContains(e.what(), g.base + ".h5 does not exist");
    }
}

// ---- <particles> against itself and the .h5 ------------------------------------------------

TEST(SolverCaseErrors, NpDiffersFromTheTypeCounts) {
    const Edited e = edit(pool(), "np=\"150\"", "np=\"151\"");
    expectContains(
        e.error,
        e.at("<particles") + " <particles> np=151 differs from nfixed+nmoving+nsolid+nfluid=150");
}

TEST(SolverCaseErrors, NpDiffersFromTheH5) {
    std::string from = "np=\"150\" nfixed=\"25\" nmoving=\"0\" nsolid=\"0\" nfluid=\"125\"";
    Edited e =
        edit(pool(), from, "np=\"149\" nfixed=\"25\" nmoving=\"0\" nsolid=\"0\" nfluid=\"124\"");
    // The fluid block still says 125: the blocks are checked first.
    expectContains(e.error,
                   e.at("<particles") + " <particles> np=149 but its blocks hold 150 particles");

    Generated shrunk = pool();
    shrunk.xml = e.text;
    e = edit(shrunk, "begin=\"25\" count=\"125\"", "begin=\"25\" count=\"124\"");
    expectContains(e.error, e.at("<particles") + " <particles> np=149 but ");
    expectContains(e.error, "Case.h5 holds 150 particles");
}

TEST(SolverCaseErrors, BlockCountsDifferFromTheTypeCounts) {
    Generated p = pool();
    p.xml = edit(p, "<fixed mk=\"10\" mkbound=\"0\" begin=\"0\" count=\"25\"",
                 "<fixed mk=\"10\" mkbound=\"0\" begin=\"0\" count=\"24\"")
                .text;
    const Edited e = edit(p, "begin=\"25\" count=\"125\"", "begin=\"24\" count=\"126\"");
    expectContains(e.error, e.at("<particles") +
                                " <particles> nfixed=25 but its fixed blocks hold 24 particles");
}

TEST(SolverCaseErrors, BlockTypeOrMkDiffersFromTheH5) {
    Edited e = edit(pool(), "<fixed mk=\"10\"", "<fixed mk=\"12\"");
    expectContains(e.error, "Case.h5: particle 0 is fixed mk 10 but " + e.where("<fixed") +
                                " <fixed mk=12> covers ids 0..24");
    // Same counts, but the fluid block claims to be a fixed one (type order and counts kept).
    Generated p = pool();
    p.xml = edit(p, "nfixed=\"25\" nmoving=\"0\" nsolid=\"0\" nfluid=\"125\"",
                 "nfixed=\"150\" nmoving=\"0\" nsolid=\"0\" nfluid=\"0\"")
                .text;
    e = edit(p, "<fluid mk=\"1\" mkfluid=\"0\"", "<fixed mk=\"1\" mkbound=\"0\"");
    expectContains(e.error, "Case.h5: particle 25 is fluid mk 1 but " + e.where("<fixed mk=\"1\"") +
                                " <fixed mk=1> covers ids 25..149");
}

TEST(SolverCaseErrors, BlocksMustBeContiguousAndKnown) {
    Edited e = edit(pool(), "begin=\"25\" count=\"125\"", "begin=\"26\" count=\"125\"");
    expectContains(
        e.error, e.at("<fluid") + " <fluid> begin=26: blocks must follow each other (expected 25)");
    e = edit(pool(), "<fixed mk=\"10\" mkbound=\"0\" begin=\"0\" count=\"25\" />",
             "<fixed mk=\"10\" mkbound=\"0\" begin=\"0\" count=\"25\" /><floating mk=\"11\" />");
    expectContains(e.error, e.at("<floating") + " <floating> is not a particle block");
    e = edit(pool(), "count=\"125\"", "count=\"12x\"");
    expectContains(e.error,
                   e.at("count=\"12x\"") + " <fluid> attribute count=\"12x\": expected an integer");
}

// ---- Unsupported features ------------------------------------------------------------------

TEST(SolverCaseErrors, UnsupportedParameterValuesNameTheLine) {
    expectParameterError("Boundary", "1", "3", {"is not supported by seaspring (supported: 1 DBC, 2 mDBC)"});
    expectParameterError("Shifting", "0", "1", {"not supported by seaspring (supported: 0 none)"});
    expectParameterError("XPeriodicIncY", "0", "0.5",
                         {"periodic boundaries is not supported by seaspring"});
    expectParameterError("XYPeriodic", "0", "1",
                         {"periodic boundaries is not supported by seaspring"});
    expectParameterError("ZPeriodicIncX", "0", "1",
                         {"periodic boundaries is not supported by seaspring"});
    expectParameterError("Symmetry", "0", "1", {"a symmetry plane is not supported by seaspring"});
    expectParameterError("Kernel", "2", "3",
                         {"not supported by seaspring (supported: 1 cubic spline, 2 Wendland)"});
    expectParameterError(
        "ViscoTreatment", "1", "4",
        {"not supported by seaspring (supported: 1 artificial, 2 laminar+SPS, 3 laminar)"});
    expectParameterError("DensityDT", "0", "4",
                         {"(supported: 0 none, 1 Molteni, 2 Fourtakas, 3 Fourtakas full)"});
    expectParameterError("StepAlgorithm", "1", "3", {"(supported: 1 Verlet, 2 symplectic)"});
    expectParameterError("ViscoTime", "NONE", "visco.csv",
                         {"a viscosity-time file is not supported", "NONE"});
    expectParameterError("DtFixedFile", "NONE", "dt.csv",
                         {"a dt file is not supported by seaspring"});
    expectParameterError("RigidAlgorithm", "1", "2", {"not supported by seaspring (supported: 1"});
    expectParameterError("FtPause", "0", "0.5", {"a floating-body pause is not supported"});
    expectParameterError("FtIgnoreRadius", "0", "1", {"not supported by seaspring"});
    expectParameterError("DtAllParticles", "0", "2", {"not supported by seaspring (supported: 0 fluid, 1 all particles"});
    expectParameterError("TimeOutExtra", "-1", "0.1", {"extra motion output is not supported"});
    expectParameterError("DivCleanKp", "0", "1", {"divergence cleaning is not supported"});
}

TEST(SolverCaseErrors, ParameterRangesAndSyntax) {
    expectParameterError("TimeMax", "1", "0", {"must be > 0"});
    expectParameterError("TimeOut", "0.1", "-1", {"must be > 0"});
    expectParameterError("Visco", "0.1", "-0.1", {"must be >= 0"});
    expectParameterError("ViscoBoundFactor", "1", "-1", {"must be >= 0"});
    expectParameterError("DensityDTvalue", "0.1", "-0.1", {"must be >= 0"});
    expectParameterError("VerletSteps", "40", "0", {"must be >= 1"});
    expectParameterError("CoefDtMin", "0.05", "0", {"must be > 0"});
    expectParameterError("DtFixed", "0", "-1e-4", {"must be >= 0"});
    expectParameterError("RhopOutMax", "1300", "600", {"must exceed RhopOutMin=700"});
    expectParameterError("MinFluidStop", "0.1", "2", {"must be <= 1"});
    expectParameterError("Kernel", "2", "1.5", {"expected an integer"});
    expectParameterError("TimeMax", "1", "abc", {"'abc' is not a number"});
}

TEST(SolverCaseErrors, UnknownDeprecatedRepeatedAndMissingKeys) {
    const std::string anchor = "<parameter key=\"Kernel\" value=\"2\" />";
    Edited e = edit(pool(), anchor, anchor + "<parameter key=\"Foo\" value=\"1\" />");
    expectContains(e.error,
                   e.at("key=\"Foo\"") + " <parameter> key=\"Foo\" is not a known parameter");
    e = edit(pool(), anchor, anchor + "<parameter key=\"PosDouble\" value=\"1\" />");
    expectContains(e.error,
                   e.at("key=\"PosDouble\"") + " <parameter> key=\"PosDouble\" is deprecated");
    e = edit(pool(), anchor, anchor + "\n<parameter key=\"Kernel\" value=\"1\" />");
    expectContains(e.error, std::to_string(test::lineOf(e.text, anchor) + 1) +
                                ": <parameter> key=\"Kernel\" is given twice");
    e = edit(pool(), "<parameter key=\"TimeMax\" value=\"1\" />", "");
    expectContains(e.error,
                   e.at("<parameters>") + " <parameters> misses the required parameter TimeMax");
    e = edit(pool(), anchor, "<parameter key=\"Kernel\" value=\"2\" extra=\"1\" />");
    expectContains(e.error, e.at("extra=") + " <parameter> unknown attribute 'extra=\"1\"'");
}

TEST(SolverCaseErrors, UnknownOrUnsupportedSections) {
    Edited e = edit(pool(), "<files ", "<foo />\n<files ");
    expectContains(e.error, e.at("<foo") + " unknown element <foo> inside <execution>");
    e = edit(pool(), "<special />", "<special>\n<inout />\n</special>");
    expectContains(e.error, e.at("<inout") + " <inout> is not supported by seaspring");
    e = edit(pool(), "<files ", "<constants />\n<files ");
    expectContains(e.error,
                   e.at("<constants />") + " <constants> appears twice inside <execution>");
}

TEST(SolverCaseErrors, Constants) {
    Edited e = edit(pool(), "<gamma value=\"7\" />", "<gamma value=\"6\" />");
    expectContains(
        e.error, e.at("<gamma") + " <gamma> value=6: is not supported by seaspring (supported: 7)");
    e = edit(pool(), "<cflnumber value=\"0.20000000000000001\" />", "<cflnumber value=\"1.5\" />");
    expectContains(e.error, e.at("<cflnumber") + " <cflnumber> value=1.5: must lie in (0, 1]");
    e = edit(pool(), "<dimensions value=\"3\" />", "<dimensions value=\"4\" />");
    expectContains(e.error, e.at("<dimensions") + " <dimensions> value=4: must be 2 or 3");
    e = edit(pool(), "<dimensions value=\"3\" />", "<dimensions value=\"2\" />");
    expectContains(e.error,
                   "Case.h5: dimensions=3 but " + e.where("<dimensions") + " <dimensions> says 2");
    e = edit(pool(), "<dp value=\"0.10000000000000001\" />", "<dp value=\"0.1000001\" />");
    expectContains(e.error, "Case.h5: dp=0.1 but " + e.where("<dp ") + " <dp> says 0.1000001");
    e = edit(pool(), "<cflnumber value=\"0.20000000000000001\" />", "");
    expectContains(e.error,
                   e.at("<constants>") + " <constants> requires a child element <cflnumber>");
}

TEST(SolverCaseErrors, Domain) {
    const std::string posmax = "<posmax x=\"0.40000000000000002\"";
    Edited e = edit(pool(), posmax, "<posmax x=\"0.3\"");
    expectContains(e.error, "Case.h5: particle ");
    expectContains(e.error, "lies outside " + e.where("<simulationdomain") +
                                " <simulationdomain> (0, 0, -0.2) - (0.3, 0.4, 0.4)");
    e = edit(pool(), posmax, "<posmax x=\"-1\"");
    expectContains(e.error, e.at("<simulationdomain") +
                                " <simulationdomain> posmin (0, 0, -0.2) must lie below posmax");
    e = edit(pool(), posmax, "<posmax x=\"default\"");
    expectContains(e.error, e.at("<posmax") + " <posmax> attribute x=\"default\"");
    // The resolved case holds plain numbers: an expression is an error, not evaluated.
    e = edit(pool(), posmax, "<posmax x=\"#0.2*2\"");
    expectContains(e.error, e.at("<posmax") + " <posmax> attribute x=\"#0.2*2\": '#0.2*2': the resolved case "
                                              "holds plain numbers");
}

TEST(SolverCaseErrors, MovingBlockWithoutMotionAndSolidSummary) {
    const Generated g =
        generate("moving_solid_err", std::string(kPool) + "\n" + kMovingAndSolid, kMotion, kSolid);
    const std::size_t exec = g.xml.find("<execution>");
    const std::size_t m0 = g.xml.find("<motion>", exec), m1 = g.xml.find("</motion>", exec);
    ASSERT_NE(m0, std::string::npos);
    Edited e = edit(g, g.xml.substr(m0, m1 + 9 - m0), "");
    expectContains(
        e.error,
        e.at("<moving") + " <moving> mkbound=1 is a moving boundary without <objreal ref=\"1\">");
    const std::string slots = "bondslots=\"" + std::to_string(g.g.bonds.bondSlots()) + "\"";
    e = edit(g, slots, "bondslots=\"7\"");
    expectContains(e.error, e.at("bondslots=") + " <vcpmsolids> bondslots=7 but ");
    const std::size_t v0 = g.xml.find("<vcpmsolids particles"),
                      v1 = g.xml.find("</vcpmsolids>", v0);
    ASSERT_NE(v0, std::string::npos);
    e = edit(g, g.xml.substr(v0, v1 + 13 - v0), "");
    expectContains(e.error,
                   e.at("<particles") +
                       " <particles> has solid particles but <execution> has no <vcpmsolids>");
}
