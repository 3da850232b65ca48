// SeaSpring — MIT licence.
/// \file test_solver_case_errors.cpp
/// \brief loadSolverCase on edited copies of the resolved XML of cases generated in-process:
///        every error names the file, the line and the offending value.
#include "solver_case_test_util.h"

using namespace seaspring;
using namespace seaspring::test::solver_case;

namespace fs = std::filesystem;

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
