// SeaSpring — MIT licence.
/// \file test_gencase_limits.cpp
/// \brief Hostile inputs gencase must answer with a clear error (issue 14): bounded expression
///        depth, element nesting and list expansion, the memory estimate before large
///        allocations, the solver's own checks of parameters and constants (one function for
///        both programs), output names that name no file or the input itself, strict -dp, and
///        exit code 3 for outputs that cannot be written.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>

#include "error_expect.h"
#include "gencase_test_util.h"

using namespace seaspring;

namespace fs = std::filesystem;

namespace {

using test::kPool;  // gencase_test_util.h

/// The message of what gencase stops with before writing (build(), then checkForSolver(),
/// as gencase_main does); "" when the case passes.
std::string buildAndCheckError(const std::string& def) {
    std::ostringstream log;
    try {
        test::buildCaseKeepBuilder(def, log)->checkForSolver();
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

/// buildAndCheckError of the pool case with `from` replaced by `to` in its XML (`from` must occur).
std::string errorWith(const std::string& tag, const std::string& from, const std::string& to,
                      const std::string& mainlist = kPool) {
    std::string xml = test::caseXml(mainlist);
    const std::size_t at = xml.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) xml.replace(at, from.size(), to);
    return buildAndCheckError(test::writeFile(test::scratchDir("lim_" + tag), "Case_Def.xml", xml));
}

}  // namespace

TEST(GencaseLimits, ExpressionDepthIsBounded) {
    // 30,000 nested parentheses and 2 M unary minuses overflowed the parser's stack.
    const std::string deep = "#" + std::string(30000, '(') + "0" + std::string(30000, ')');
    std::string m = errorWith("paren", "y=\"0\" z=\"0\"/>", "y=\"0\" z=\"" + deep + "\"/>");
    EXPECT_HAS(m, "nested deeper than 256 levels");
    EXPECT_HAS(m, "(60001 characters)");  // the message quotes a cut value, not 60 kB
    EXPECT_LT(m.size(), 600u);
    m = errorWith("unary", "y=\"0\" z=\"0\"/>", "y=\"0\" z=\"#" + std::string(2000000, '-') + "0\"/>");
    EXPECT_HAS(m, "nested deeper than 256 levels");
    // 200 levels are fine.
    EXPECT_EQ(errorWith("paren_ok", "y=\"0\" z=\"0\"/>",
                        "y=\"0\" z=\"#" + std::string(200, '(') + "0" + std::string(200, ')') + "\"/>"),
              "");
}

TEST(GencaseLimits, ElementNestingIsBoundedEvenInDisabledElements) {
    // A skipped `_` subtree 20 k levels deep made an 800 MB resolved case.
    std::string deep;
    for (int i = 0; i < 20000; ++i) deep += "<a>";
    for (int i = 0; i < 20000; ++i) deep += "</a>";
    const std::string m = errorWith("deep", "<mkconfig", "<_skipped>" + deep + "</_skipped><mkconfig");
    EXPECT_HAS(m, "Case_Def.xml:");
    EXPECT_HAS(m, "elements are nested deeper than 64 levels");
}

TEST(GencaseLimits, ListExpansionIsBounded) {
    // Lists calling lists 1000 times each, 7 deep: 1e21 commands.
    std::string lists;
    for (int k = 1; k <= 7; ++k)
        lists += "<list name=\"L" + std::to_string(k) + "\">" +
                 (k < 7 ? "<runlist name=\"L" + std::to_string(k + 1) + "\" times=\"1000\"/>"
                        : std::string("<newvar x=\"1\"/>")) +
                 "</list>\n";
    const std::string m = errorWith("bomb", "<mainlist>", lists + "<mainlist><runlist name=\"L1\" times=\"1000\"/>");
    EXPECT_HAS(m, "more than 1000000 commands run");
}

TEST(GencaseLimits, MemoryEstimateBeforeTheLatticeAndTheParticles) {
    // Water over the whole domain -1..5 at dp 0.2: 31^3 = 29791 sites (60 kB of lattice) and as
    // many particles (about 4.8 MB).
    const std::string water =
        "<setmkfluid mk=\"0\"/><drawbox><boxfill>solid</boxfill><point x=\"-1\" y=\"-1\" z=\"-1\"/>"
        "<size x=\"6\" y=\"6\" z=\"6\"/></drawbox>";
    const std::string def =
        test::writeFile(test::scratchDir("lim_mem"), "Case_Def.xml", test::caseXml(water, 0.2));
    ::setenv("SEASPRING_MEMORY_LIMIT", "10000", 1);  // the lattice does not fit
    std::string m = test::buildError(def);
    EXPECT_HAS(m, "Case_Def.xml:");
    EXPECT_HAS(m, "<definition> the lattice (29791 sites with dp=0.2, 2 bytes each) needs about");
    EXPECT_HAS(m, "GB of memory but only 1e-05 GB are available; reduce the domain or increase dp");
    ::setenv("SEASPRING_MEMORY_LIMIT", "1000000", 1);  // the lattice fits, the particles do not
    m = test::buildError(def);
    EXPECT_HAS(m, "<definition> 29791 particles needs about 0.00477 GB of memory");
    EXPECT_HAS(m, "increase dp or reduce the drawn volume");
    ::unsetenv("SEASPRING_MEMORY_LIMIT");
    EXPECT_EQ(test::buildError(def), "");
}

TEST(GencaseLimits, RejectsWhatTheSolverWouldReject) {
    // One reader (model::checkSolverParameters / checkCaseConstants) for both programs.
    EXPECT_HAS(errorWith("tmax", "key=\"TimeMax\" value=\"1\"", "key=\"TimeMax\" value=\"-1\""),
               "<parameter> key=\"TimeMax\" value=\"-1\": must be > 0");
    EXPECT_HAS(errorWith("tout", "key=\"TimeOut\" value=\"0.1\"", "key=\"TimeOut\" value=\"#0*1\""),
               "<parameter> key=\"TimeOut\" value=\"0\": must be > 0");
    EXPECT_HAS(errorWith("step", "<parameter key=\"Visco\"", "<parameter key=\"StepAlgorithm\" value=\"7\"/><parameter key=\"Visco\""),
               "key=\"StepAlgorithm\" value=\"7\": is not supported by seaspring");
    EXPECT_HAS(errorWith("bound", "<parameter key=\"Visco\"",
                         "<parameter key=\"VcpmSubStepBound\" value=\"2\"/><parameter key=\"Visco\""),
               "key=\"VcpmSubStepBound\" value=\"2\": is not supported by seaspring (supported: -1 auto");
    EXPECT_HAS(errorWith("rows", "<parameter key=\"Visco\"",
                         "<parameter key=\"VcpmSurfaceCorrection\" value=\"0\"/><parameter key=\"VcpmRowBending\" "
                         "value=\"1\"/><parameter key=\"Visco\""),
               "key=\"VcpmRowBending\" value=\"1\": needs VcpmSurfaceCorrection 1");
    EXPECT_HAS(errorWith("rows2", "<parameter key=\"Visco\"",
                         "<parameter key=\"VcpmRowBending\" value=\"2\"/><parameter key=\"Visco\""),
               "key=\"VcpmRowBending\" value=\"2\": is not supported by seaspring (supported: -1 auto");
    EXPECT_HAS(errorWith("cfl", "<cflnumber value=\"0.2\" />", "<cflnumber value=\"5\" />"),
               "<cflnumber> value=5: must lie in (0, 1]");
    // gravity -1e300 gave infinite constants and exit 0.
    const std::string g = errorWith("grav", "z=\"-9.81\"", "z=\"-1e300\"");
    EXPECT_HAS(g, "is not finite");
    // Neither fluid nor solid: nothing to simulate.
    const std::string floor_only =
        "<setmkbound mk=\"0\"/><drawbox><boxfill>solid</boxfill><point x=\"0\" y=\"0\" z=\"-0.2\"/>"
        "<size x=\"0.4\" y=\"0.4\" z=\"0\"/></drawbox>";
    EXPECT_HAS(errorWith("empty", "<mkconfig", "<mkconfig", floor_only), "neither fluid nor VCPM solid particles");
}

TEST(GencaseLimits, OutputNamesAndTheInputItself) {
    const std::string dir = test::scratchDir("lim_names");
    const std::string def = test::writeFile(dir, "same.xml", test::caseXml(kPool));
    const std::string before = test::buildError(def);  // builds
    ASSERT_EQ(before, "");
    for (const std::string& out : {std::string("''"), std::string("/"), dir + "/sub/"}) {
        const test::CommandResult r = test::runGencase(def + " " + out);
        EXPECT_EQ(r.exit_code, 2) << out;
        EXPECT_HAS(r.output, "the output must be OUTDIR/NAME, ending in a file name");
    }
    // `gencase same.xml same` overwrote its input.
    const std::uintmax_t size = fs::file_size(def);
    const test::CommandResult r = test::runGencase(def + " " + dir + "/same");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_HAS(r.output, "is the case definition");
    EXPECT_EQ(fs::file_size(def), size);
    EXPECT_FALSE(fs::exists(dir + "/same.h5"));
}

TEST(GencaseLimits, DpMustBeAPositiveNumber) {
    const std::string dir = test::scratchDir("lim_dp");
    const std::string def = test::writeFile(dir, "Case_Def.xml", test::caseXml(kPool));
    for (const char* v : {"0", "1e-400", "-0.1", "abc", "0.1x", "nan", "inf"}) {
        const test::CommandResult r = test::runGencase(def + " " + dir + "/out/Case -dp:" + v);
        EXPECT_EQ(r.exit_code, 2) << v;
        EXPECT_HAS(r.output, std::string("-dp:") + v + ": must be a number > 0");
        EXPECT_FALSE(fs::exists(dir + "/out/Case.xml")) << v;
    }
    EXPECT_EQ(test::runGencase(def + " " + dir + "/out/Case -dp:0.2").exit_code, 0);
}

TEST(GencaseLimits, WriteFailuresExitWithThree) {
    const std::string dir = test::scratchDir("lim_write");
    const std::string def = test::writeFile(dir, "Case_Def.xml", test::caseXml(kPool));
    // OUTDIR below a regular file cannot be created; NAME.xml taken by a folder cannot be renamed.
    test::CommandResult r = test::runGencase(def + " " + def + "/sub/Case");
    EXPECT_EQ(r.exit_code, 3) << r.output;
    fs::create_directories(dir + "/out/Case.xml");
    r = test::runGencase(def + " " + dir + "/out/Case");
    EXPECT_EQ(r.exit_code, 3) << r.output;
    EXPECT_HAS(r.output, "exists and is not a regular file");
}
