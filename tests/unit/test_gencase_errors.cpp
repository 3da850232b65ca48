// SeaSpring — MIT licence.
/// \file test_gencase_errors.cpp
/// \brief The gencase command line end to end: the success path (NAME.xml, NAME.h5,
///        NAME.vtu, read back) and every input error: exit code 2, a message naming the file,
///        the line and the offending value, and no output file left behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include <pugixml.hpp>

#include "core/error.h"
#include "gencase_test_util.h"
#include "io/case_h5.h"

using namespace seaspring;

namespace fs = std::filesystem;

namespace {

using test::kPool;  // gencase_test_util.h

struct CliRun {
    std::string dir;   ///< scratch directory holding the case
    std::string text;  ///< the case definition
    std::string def;   ///< its path
    std::string out;   ///< OUTDIR/NAME passed to gencase
    test::CommandResult result;
};

CliRun runCase(const std::string& tag, const std::string& text, const std::string& extra_args = "",
            const std::string& def_name = "Case_Def.xml") {
    CliRun r;
    r.dir = test::scratchDir("cli_" + tag);
    r.text = text;
    r.def = test::writeFile(r.dir, def_name, text);
    r.out = r.dir + "/out/Case";
    r.result = test::runGencase(r.def + " " + r.out + " " + extra_args);
    return r;
}

/// "gencase error: FILE:LINE:" with LINE the first line of the case holding `needle`.
std::string locationOf(const CliRun& r, const std::string& needle) {
    const int line = test::lineOf(r.text, needle);
    EXPECT_GT(line, 0) << "'" << needle << "' is not in the case";
    return "gencase error: " + r.def + ":" + std::to_string(line) + ":";
}

/// Exit code 2 and nothing written: no NAME.xml/.h5/.vtu, no .part or .tmp, in fact no file.
void expectFailedCleanly(const CliRun& r) {
    EXPECT_EQ(r.result.exit_code, 2) << r.result.output;
    const std::vector<std::string> left = test::listFiles(r.dir + "/out");
    EXPECT_TRUE(left.empty()) << "left behind: " << (left.empty() ? "" : left.front());
    for (const char* ext : {".xml", ".h5", ".vtu", ".h5.part", ".xml.part", ".vtu.part", ".h5.part.tmp"})
        EXPECT_FALSE(fs::exists(r.out + ext)) << r.out + ext;
}

void expectContains(const std::string& text, const std::string& what) {
    EXPECT_NE(text.find(what), std::string::npos) << "expected '" << what << "' in:\n" << text;
}

std::size_t resolvedParticleCount(const std::string& xml_path) {
    pugi::xml_document doc;
    EXPECT_TRUE(doc.load_file(xml_path.c_str())) << xml_path;
    return doc.child("case").child("execution").child("particles").attribute("np").as_ullong();
}

}  // namespace

// ---- Success paths -------------------------------------------------------------------

TEST(GencaseCli, WritesResolvedCaseParticlesAndPreview) {
    const CliRun r = runCase("ok", test::caseXml(kPool), "-save:vtk");
    ASSERT_EQ(r.result.exit_code, 0) << r.result.output;
    EXPECT_EQ(test::listFiles(r.dir + "/out"),
              (std::vector<std::string>{"Case.h5", "Case.vtu", "Case.xml"}));
    EXPECT_EQ(resolvedParticleCount(r.out + ".xml"), 150u);
    const io::CaseFileContents h5 = io::readCaseH5(r.out + ".h5");
    EXPECT_EQ(h5.particles.size(), 150u);
    EXPECT_EQ(h5.header.np, 150u);
    EXPECT_EQ(h5.header.dimensions, 3);
    EXPECT_EQ(h5.header.dp, 0.1);
    EXPECT_EQ(h5.header.case_name, "Case");
    EXPECT_FALSE(h5.has_bonds);
    pugi::xml_document doc;
    ASSERT_TRUE(doc.load_file((r.out + ".xml").c_str()));
    const pugi::xml_node parts = doc.child("case").child("execution").child("particles");
    EXPECT_EQ(parts.attribute("nfixed").as_ullong(), 25u);
    EXPECT_EQ(parts.attribute("nfluid").as_ullong(), 125u);
    EXPECT_STREQ(doc.child("case").child("execution").child("files").attribute("particles").value(), "Case.h5");
    // The preview is a VTK UnstructuredGrid with the same number of points (its appended raw
    // block is not XML, so only the header is searched).
    std::ifstream vtu(r.out + ".vtu", std::ios::binary);
    const std::string vtu_text((std::istreambuf_iterator<char>(vtu)), std::istreambuf_iterator<char>());
    const std::string vtu_header = vtu_text.substr(0, vtu_text.find("<AppendedData"));
    expectContains(vtu_header, "<VTKFile type=\"UnstructuredGrid\"");
    expectContains(vtu_header, "<Piece NumberOfPoints=\"150\" NumberOfCells=\"150\">");
}

TEST(GencaseCli, WithoutSaveVtkWritesNoPreview) {
    const CliRun r = runCase("novtk", test::caseXml(kPool));
    ASSERT_EQ(r.result.exit_code, 0) << r.result.output;
    EXPECT_EQ(test::listFiles(r.dir + "/out"), (std::vector<std::string>{"Case.h5", "Case.xml"}));
}

TEST(GencaseCli, DefinitionWithoutXmlExtensionAsDualSPHysics) {
    const std::string dir = test::scratchDir("cli_noext");
    test::writeFile(dir, "Case_Def.xml", test::caseXml(kPool));
    const test::CommandResult res = test::runGencase(dir + "/Case_Def " + dir + "/out/Case");
    ASSERT_EQ(res.exit_code, 0) << res.output;
    EXPECT_EQ(resolvedParticleCount(dir + "/out/Case.xml"), 150u);
    EXPECT_EQ(io::readCaseH5(dir + "/out/Case.h5").particles.size(), 150u);
}

TEST(GencaseCli, DpOverrideChangesTheLattice) {
    const CliRun r = runCase("dp02", test::caseXml(kPool), "-dp:0.2");
    ASSERT_EQ(r.result.exit_code, 0) << r.result.output;
    EXPECT_EQ(resolvedParticleCount(r.out + ".xml"), 36u);  // 3*3 floor + 3*3*3 water
    const io::CaseFileContents h5 = io::readCaseH5(r.out + ".h5");
    EXPECT_EQ(h5.particles.size(), 36u);
    EXPECT_EQ(h5.header.dp, 0.2);
}

TEST(GencaseCli, SolidCaseWritesBonds) {
    // Clamp (mkbound 0): the single site (0, 0, 0), id 0. Beam (mkbound 1): a line of 3 sites
    // x = 0.1, 0.2, 0.3 (ids 1..3): 2 solid-solid bonds (no diagonals on a line), and the
    // particle at x = 0.1 bonds to the clamp -> slots 2*2 + 1 = 5. Slot order is (dz, dy, dx)
    // lexicographic, so dx = -1 comes before dx = +1 in every row.
    const std::string mainlist =
        "<setmkbound mk=\"0\"/><drawbox><boxfill>solid</boxfill><point x=\"0\" y=\"0\" z=\"0\"/>"
        "<size x=\"0\" y=\"0\" z=\"0\"/></drawbox>"
        "<setmkbound mk=\"1\"/><drawbox><boxfill>solid</boxfill><point x=\"0.1\" y=\"0\" z=\"0\"/>"
        "<size x=\"0.2\" y=\"0\" z=\"0\"/></drawbox>";
    const CliRun r = runCase("solid", test::caseXml(mainlist, 0.1, false, "",
        "<vcpmsolids><solid mkbound=\"1\" mkclamp=\"0\" density=\"2500\" youngmod=\"3e6\" poissratio=\"0.3\"/></vcpmsolids>"));
    ASSERT_EQ(r.result.exit_code, 0) << r.result.output;
    const io::CaseFileContents h5 = io::readCaseH5(r.out + ".h5");
    ASSERT_TRUE(h5.has_bonds);
    EXPECT_EQ(h5.bonds.first_solid, 1u);
    EXPECT_EQ(h5.bonds.solidCount(), 3u);
    EXPECT_EQ(h5.bonds.bondSlots(), 5u);
    EXPECT_EQ(h5.bonds.offset, (std::vector<std::uint32_t>{0, 2, 4, 5}));
    EXPECT_EQ(h5.bonds.neighbour, (std::vector<std::uint32_t>{0, 2, 1, 3, 2}));
}

// ---- Errors --------------------------------------------------------------------------

TEST(GencaseCliErrors, UnknownElementInMainlist) {
    const CliRun r = runCase("unknown_element", test::caseXml(std::string(kPool) + "\n<drawpyramid size=\"1\"/>"));
    expectFailedCleanly(r);
    expectContains(r.result.output, locationOf(r, "<drawpyramid"));
    expectContains(r.result.output, "<drawpyramid> is not a command SeaSpring's gencase supports");
}

TEST(GencaseCliErrors, UnknownAttribute) {
    const CliRun r = runCase("unknown_attr", test::caseXml("\n<setmkbound mk=\"0\" colour=\"red\"/>\n" + std::string(kPool)));
    expectFailedCleanly(r);
    expectContains(r.result.output, locationOf(r, "colour="));
    expectContains(r.result.output, "<setmkbound> unknown attribute 'colour=\"red\"'");
}

TEST(GencaseCliErrors, MissingRequiredAttribute) {
    const CliRun r = runCase("missing_attr", test::caseXml(std::string(kPool) + "\n<setmkbound/>"));
    expectFailedCleanly(r);
    expectContains(r.result.output, locationOf(r, "<setmkbound/>"));
    expectContains(r.result.output, "<setmkbound> requires attribute 'mk'");
}

TEST(GencaseCliErrors, NegativeDpInTheFile) {
    const CliRun r = runCase("negative_dp", test::caseXml(kPool, -0.1));
    expectFailedCleanly(r);
    expectContains(r.result.output, locationOf(r, "<definition"));
    expectContains(r.result.output, "<definition> dp=\"-0.1\": must be > 0");
}

TEST(GencaseCliErrors, NegativeDpOnTheCommandLine) {
    const CliRun r = runCase("negative_dp_cli", test::caseXml(kPool), "-dp:-0.1");
    expectFailedCleanly(r);
    expectContains(r.result.output, "gencase error: -dp:-0.1: must be a number > 0");
    expectContains(r.result.output, "(metres), written in full");
}

TEST(GencaseCliErrors, CaseWithoutParticles) {
    // Drawn entirely outside pointmin..pointmax (-1..5).
    const CliRun r = runCase("no_particles", test::caseXml(
        "<setmkfluid mk=\"0\"/><drawbox><boxfill>solid</boxfill><point x=\"10\" y=\"10\" z=\"10\"/>"
        "<size x=\"1\" y=\"1\" z=\"1\"/></drawbox>"));
    expectFailedCleanly(r);
    expectContains(r.result.output, locationOf(r, "<case>"));
    expectContains(r.result.output, "the case has no particles");
}

TEST(GencaseCliErrors, NanInAnExpression) {
    const CliRun r = runCase("nan", test::caseXml(std::string(kPool) +
        "\n<drawbox><boxfill>solid</boxfill><point x=\"#sqrt(-1)\" y=\"0\" z=\"0\"/><size x=\"0\" y=\"0\" z=\"0\"/></drawbox>"));
    expectFailedCleanly(r);
    expectContains(r.result.output, locationOf(r, "#sqrt(-1)"));
    expectContains(r.result.output, "<point> attribute x=\"#sqrt(-1)\"");
    expectContains(r.result.output, "non-finite");
    const CliRun z = runCase("zero_over_zero", test::caseXml("\n<newvar bad=\"#0/0\"/>\n" + std::string(kPool)));
    expectFailedCleanly(z);
    expectContains(z.result.output, locationOf(z, "<newvar"));
    expectContains(z.result.output, "variable bad=\"#0/0\"");
    expectContains(z.result.output, "non-finite");
}

TEST(GencaseCliErrors, UnknownVariable) {
    const CliRun r = runCase("unknown_var", test::caseXml(std::string(kPool) +
        "\n<drawbox><boxfill>solid</boxfill><point x=\"#TankLength/2\" y=\"0\" z=\"0\"/><size x=\"0\" y=\"0\" z=\"0\"/></drawbox>"));
    expectFailedCleanly(r);
    expectContains(r.result.output, locationOf(r, "#TankLength"));
    expectContains(r.result.output, "unknown variable 'TankLength'");
}

TEST(GencaseCliErrors, MalformedXml) {
    // An unquoted attribute value: pugixml stops there.
    const CliRun r = runCase("malformed", test::caseXml(std::string(kPool) + "\n<setmkbound mk=0/>"));
    expectFailedCleanly(r);
    expectContains(r.result.output, locationOf(r, "mk=0/>"));
    expectContains(r.result.output, "XML parse error");
}

TEST(GencaseCliErrors, MotionFileMissing) {
    const std::string motion =
        "<motion><objreal ref=\"0\"><begin mov=\"1\" start=\"0\"/><mvfile id=\"1\" duration=\"1\">\n"
        "<file name=\"NoSuchSeries.csv\" fields=\"2\" fieldtime=\"0\" fieldz=\"1\"/>\n"
        "</mvfile></objreal></motion>";
    const CliRun r = runCase("motion_missing", test::caseXml(kPool, 0.1, false, motion));
    expectFailedCleanly(r);
    expectContains(r.result.output, locationOf(r, "<file name"));
    expectContains(r.result.output, "<file> cannot open motion file '" + r.dir + "/NoSuchSeries.csv'");
}

TEST(GencaseCliErrors, MotionFileMalformed) {
    const std::string motion =
        "<motion><objreal ref=\"0\"><begin mov=\"1\" start=\"0\"/><mvfile id=\"1\" duration=\"1\">\n"
        "<file name=\"Series.csv\" fields=\"2\" fieldtime=\"0\" fieldz=\"1\"/>\n"
        "</mvfile></objreal></motion>";
    const std::string dir = test::scratchDir("cli_motion_bad");
    // Line 1 header, lines 2-3 data, line 4 a typo in the second column.
    const std::string csv = test::writeFile(dir, "Series.csv", "time;z\n0;0\n0.1;0.01\n0.2;0.0x2\n");
    const std::string text = test::caseXml(kPool, 0.1, false, motion);
    const std::string def = test::writeFile(dir, "Case_Def.xml", text);
    CliRun r;
    r.dir = dir;
    r.text = text;
    r.def = def;
    r.out = dir + "/out/Case";
    r.result = test::runGencase(def + " " + r.out);
    expectFailedCleanly(r);
    expectContains(r.result.output, "gencase error: " + csv + ":4: value '0.0x2' is not a finite number in column 2");
    // ... and names the case element that uses the data.
    expectContains(r.result.output, "<mvfile> at " + def + ":" + std::to_string(test::lineOf(text, "<mvfile")));
}

TEST(GencaseCliErrors, UnknownParameterKey) {
    const CliRun r = runCase("unknown_param", test::caseXml(kPool, 0.1, false, "", "",
        "<parameter key=\"SpeedOfLight\" value=\"3e8\"/>"));
    expectFailedCleanly(r);
    expectContains(r.result.output, locationOf(r, "SpeedOfLight"));
    expectContains(r.result.output, "key=\"SpeedOfLight\" is not a known parameter");
}

TEST(GencaseCliErrors, RequiredParameterMissingOrGivenTwice) {
    std::string text = test::caseXml(kPool);
    const std::string timemax = "<parameter key=\"TimeMax\" value=\"1\" />";
    ASSERT_NE(text.find(timemax), std::string::npos);
    text.erase(text.find(timemax), timemax.size());
    const CliRun r = runCase("missing_param", text);
    expectFailedCleanly(r);
    expectContains(r.result.output, locationOf(r, "<parameters>"));
    expectContains(r.result.output, "<parameters> misses the required parameter TimeMax");
    const CliRun twice = runCase("twice_param", test::caseXml(kPool, 0.1, false, "", "",
        "<parameter key=\"TimeOut\" value=\"0.2\"/>"));
    expectFailedCleanly(twice);
    expectContains(twice.result.output, locationOf(twice, "key=\"TimeOut\" value=\"0.2\""));
    expectContains(twice.result.output, "key=\"TimeOut\" is given twice");
}

TEST(GencaseCliErrors, FloatingsAreNotSupported) {
    const CliRun r = runCase("floatings", test::caseXml(kPool, 0.1, false,
        "<floatings>\n<floating mkbound=\"0\"><massbody value=\"1\"/></floating>\n</floatings>"));
    expectFailedCleanly(r);
    expectContains(r.result.output, locationOf(r, "<floatings>"));
    expectContains(r.result.output, "<floatings> is not supported by SeaSpring yet");
}

TEST(GencaseCliErrors, MissingDefinitionFile) {
    const std::string dir = test::scratchDir("cli_nofile");
    const test::CommandResult res = test::runGencase(dir + "/Nothing_Def " + dir + "/out/Case");
    EXPECT_EQ(res.exit_code, 2) << res.output;
    expectContains(res.output, dir + "/Nothing_Def: case definition not found (also tried " + dir +
                                   "/Nothing_Def.xml)");
    EXPECT_TRUE(test::listFiles(dir).empty());
}

TEST(GencaseCliErrors, FailureLeavesAnEarlierOutputUntouched) {
    // A first run succeeds; a second run into the same OUTDIR/NAME fails at input checking and
    // must leave the first run's files exactly as they were (and add nothing).
    const std::string dir = test::scratchDir("cli_keep");
    const std::string good = test::writeFile(dir, "Good_Def.xml", test::caseXml(kPool));
    const std::string bad = test::writeFile(dir, "Bad_Def.xml", test::caseXml(std::string(kPool) + "<setmkbound/>"));
    ASSERT_EQ(test::runGencase(good + " " + dir + "/out/Case").exit_code, 0);
    const auto before = fs::last_write_time(dir + "/out/Case.h5");
    const test::CommandResult res = test::runGencase(bad + " " + dir + "/out/Case -save:vtk");
    EXPECT_EQ(res.exit_code, 2) << res.output;
    EXPECT_EQ(test::listFiles(dir + "/out"), (std::vector<std::string>{"Case.h5", "Case.xml"}));
    EXPECT_EQ(fs::last_write_time(dir + "/out/Case.h5"), before);
    EXPECT_EQ(resolvedParticleCount(dir + "/out/Case.xml"), 150u);
}

// Regression: a failing rename must not leave NAME.h5/NAME.vtu behind; a non-file where
// NAME.xml goes is refused before anything is renamed.
TEST(GencaseCliErrors, WriteFailureLeavesNoPartialOutput) {
    const std::string dir = test::scratchDir("cli_write_failure");
    const std::string def = test::writeFile(dir, "Case_Def.xml", test::caseXml(kPool));
    fs::create_directories(dir + "/out/Case.xml");
    test::writeFile(dir + "/out/Case.xml", "keep", "blocks the rename of Case.xml.part");
    const test::CommandResult res = test::runGencase(def + " " + dir + "/out/Case -save:vtk");
    EXPECT_NE(res.exit_code, 0) << res.output;
    expectContains(res.output, "gencase error:");
    EXPECT_EQ(test::listFiles(dir + "/out"), (std::vector<std::string>{"Case.xml/keep"}));
}

// Regression: a repeated single section (a second <motion>) is an error, not ignored.
TEST(GencaseCliErrors, SecondMotionSectionIsNotIgnored) {
    const CliRun r = runCase("second_motion", test::caseXml(kPool, 0.1, false,
        "<motion></motion>\n<motion><objreal ref=\"77\"><begin mov=\"1\" start=\"0\"/><mvnull id=\"1\"/></objreal></motion>"));
    expectFailedCleanly(r);
    expectContains(r.result.output, "gencase error: " + r.def + ":" +
                                        std::to_string(test::lineOf(r.text, "<motion><objreal")));
}
