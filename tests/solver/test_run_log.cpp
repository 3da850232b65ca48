// SeaSpring — MIT licence.
/// \file test_run_log.cpp
/// \brief What a run leaves in OUTDIR besides the particles: Run.out (the console, line by
///        line, errors included) through the seaspring program itself, the part files' masses
///        and case constants as the program writes them, and ledger.csv's ';' separator.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/error.h"
#include "io/part_output.h"
#include "solver/run_log.h"
#include "solver/solver_case.h"
#include "solver_test_util.h"
#include "test_files.h"

using namespace seaspring;

namespace {

namespace fs = std::filesystem;

using Program = test::ProgramRun;

/// Runs the seaspring program with `args`, stdout captured, stderr to `err_file`.
Program runSeaspring(const std::string& args, const std::string& err_file) {
    return test::runProgram("'" + std::string(SEASPRING_SOLVER_BIN) + "' " + args + " 2>'" + err_file + "'");
}

/// The line of `text` that starts with `prefix` ("" when none).
std::string lineStarting(const std::string& text, const std::string& prefix) {
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (line.rfind(prefix, 0) == 0) return line;
    return "";
}

}  // namespace

TEST(RunLog, TeesEveryLineToTheFileAsItGoes) {
    const std::string dir = test::scratch("runlog_tee") + "/out";
    fs::remove_all(dir);
    std::ostringstream console, errors;
    {
        solver::RunLog log(dir, console);  // creates the folder
        EXPECT_EQ(log.path(), dir + "/Run.out");
        log.out() << "banner " << 42 << "\n";
        log.out() << "half a line";
        // A finished line is in the file at once, with no flush and the log still open.
        EXPECT_EQ(test::readFile(log.path()), "banner 42\n");
        log.out() << std::flush;
        EXPECT_EQ(test::readFile(log.path()), "banner 42\nhalf a line");
        log.out() << '\n';
        log.error(errors, "seaspring: error: broken\n");
        EXPECT_EQ(test::readFile(log.path()), "banner 42\nhalf a line\nseaspring: error: broken\n");
    }
    EXPECT_EQ(console.str(), "banner 42\nhalf a line\n");
    EXPECT_EQ(errors.str(), "seaspring: error: broken\n");

    // A second run into the same folder starts a new file.
    {
        solver::RunLog log(dir, console);
        log.out() << "second\n";
    }
    EXPECT_EQ(test::readFile(dir + "/Run.out"), "second\n");

    // An output folder that cannot be made is an error naming it.
    const std::string blocked = test::scratch("runlog_tee") + "/file";
    std::ofstream(blocked) << "x";
    try {
        solver::RunLog log(blocked + "/out", console);
        ADD_FAILURE() << "no error for a folder below a plain file";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(blocked + "/out: cannot create the output folder"), std::string::npos)
            << e.what();
    }
}

TEST(RunLog, TheProgramWritesRunOutPartMassesAndLedger) {
    // The hydrostatic plate, coarse: fluid, walls and a VCPM solid (three particle masses).
    const std::string dir = test::scratch("runlog_program");
    const std::string kase =
        test::generateCaseFile(dir, "plate", test::caseDef("hydrostatic_plate/HydrostaticPlate_Def.xml"), 0.05);
    const std::string out = dir + "/out";
    const Program p = runSeaspring("-cpu -threads:1 -tmax:0.01 -tout:0.005 -progress:1e-9 '" + kase + "' '" + out +
                                       "'",
                                   dir + "/stderr.txt");
    ASSERT_EQ(p.status, 0) << p.out << test::readFile(dir + "/stderr.txt");

    // Run.out is the console, byte for byte: banner, physics line, progress (a line per step
    // here), summary, state hash.
    const std::string run_out = test::readFile(out + "/Run.out");
    EXPECT_EQ(run_out, p.out);
    const std::string hash = lineStarting(run_out, "State hash: ");
    EXPECT_EQ(hash.size(), std::string("State hash: ").size() + 16) << run_out;
    EXPECT_NE(lineStarting(run_out, "SeaSpring "), "");
    EXPECT_NE(lineStarting(run_out, "  physics: "), "");
    EXPECT_NE(lineStarting(run_out, "t="), "");
    EXPECT_NE(lineStarting(run_out, "Finished "), "");
    EXPECT_NE(run_out.find(out + "/Run.out"), std::string::npos);

    // The part files: each particle's mass from the case, and the case constants.
    const solver::SolverCase c = solver::loadSolverCase(kase);
    const io::PartData d = io::readPartH5(out + "/data/part_0001.h5");
    EXPECT_EQ(d.mass, c.particles.mass);
    ASSERT_GT(c.nsolid, 0u);
    EXPECT_NE(d.mass[c.nfixed + c.nmoving], d.mass[c.particles.size() - 1]);  // solid and fluid
    EXPECT_EQ(d.constants.h, c.constants.h);
    EXPECT_EQ(d.constants.dp, c.constants.dp);
    EXPECT_EQ(d.constants.kernel, c.params.kernel == 1 ? "cubic spline" : "Wendland C2");
    EXPECT_EQ(d.constants.rhop0, c.constants.rhop0);
    EXPECT_EQ(d.constants.dimension, 2);
    EXPECT_NE(test::readFile(out + "/parts.xdmf").find("<Attribute Name=\"mass\" AttributeType=\"Scalar\" "
                                                      "Center=\"Node\">"),
              std::string::npos);

    // ledger.csv: ';'-separated like the gauge files, 21 columns, no ','.
    const std::string ledger = test::readFile(out + "/ledger.csv");
    EXPECT_EQ(ledger.rfind("time;fluid_px;", 0), 0u) << ledger.substr(0, 80);
    EXPECT_EQ(ledger.find(','), std::string::npos);
    const std::string first_row = lineStarting(ledger, "0;");
    EXPECT_EQ(std::count(first_row.begin(), first_row.end(), ';'), 20) << first_row;

    // A failing run leaves its error in Run.out too (stderr and Run.out hold the same line).
    const Program bad = runSeaspring("-cpu '" + dir + "/missing' '" + dir + "/out_bad'", dir + "/stderr_bad.txt");
    EXPECT_EQ(bad.status, 2);
    const std::string err = test::readFile(dir + "/stderr_bad.txt");
    EXPECT_NE(err.find("missing.xml"), std::string::npos) << err;
    EXPECT_EQ(test::readFile(dir + "/out_bad/Run.out"), err);
}
