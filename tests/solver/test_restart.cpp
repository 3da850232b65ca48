// SeaSpring — MIT licence.
/// \file test_restart.cpp
/// \brief Restart files (-checkpoint, TERMINATE, -restart) through the seaspring program: a run
///        continued from a restart file ends with the same state hash as the run that was never
///        interrupted, and in the same OUTDIR its gauge files, ledger and part series are those
///        of the uninterrupted run, byte for byte; across thread counts, both time schemes, a
///        VCPM gate with its force and marker gauges, and (where a GPU is usable) between the
///        CPU and the GPU. Bad restarts stop with a message naming the file.
///        Broken on purpose, each failed here: PosCell left out of the restart file (the skin's
///        cell assignment is lost: hash differs), the symplectic scheme's next dt not saved, the
///        gauges' next measuring times not restored (gauge file differs).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "solver_test_util.h"
#include "test_files.h"

using namespace seaspring;

namespace {

namespace fs = std::filesystem;

using Program = test::ProgramRun;

Program runSeaspring(const std::string& args) {
    return test::runProgram("'" + std::string(SEASPRING_SOLVER_BIN) + "' " + args + " 2>&1");
}

std::string stateHash(const Program& p) {
    const std::string key = "State hash: ";
    const std::size_t k = p.out.find(key);
    return k == std::string::npos ? "" : p.out.substr(k + key.size(), 16);
}

/// The Antoci gate (2D, a VCPM gate clamped to a wall, force and marker gauges, ledger) at a
/// coarse resolution, generated once per test binary.
const std::string& antociCase() {
    static const std::string path = [] {
        const std::string dir = test::scratch("restart_case");
        return test::generateCaseFile(dir, "ag", test::caseDef("antoci_gate2d/AntociGate2D_Def.xml"), 0.004);
    }();
    return path;
}

const char* kRun = "-tmax:0.04 -tout:0.01 -progress:0 ";

/// Files of `a` and `b` (relative names) are byte for byte the same.
void expectSameFiles(const std::string& a, const std::string& b, const std::vector<std::string>& names) {
    for (const std::string& n : names) {
        const std::string fa = test::readFile(a + "/" + n), fb = test::readFile(b + "/" + n);
        EXPECT_FALSE(fa.empty()) << a << "/" << n;
        EXPECT_EQ(fa, fb) << n << " differs between " << a << " and " << b;
    }
}

/// The integer after "key": in a run.json (-1 when absent).
long long jsonInteger(const std::string& json, const std::string& key) {
    const std::string k = "\"" + key + "\": ";
    const std::size_t at = json.find(k);
    return at == std::string::npos ? -1 : std::stoll(json.substr(at + k.size()));
}

/// Runs the case uninterrupted, then interrupted by -nsteps after a checkpoint and continued
/// from OUTDIR/restart.h5 in the same OUTDIR (other options in `opts`, the continuation with
/// `restart_backend`); everything must match.
void checkContinuation(const std::string& tag, const std::string& opts, const std::string& restart_backend) {
    const std::string dir = test::scratch(tag);
    fs::remove_all(dir);
    const std::string whole = dir + "/whole", cut = dir + "/cut";
    const Program a = runSeaspring("-cpu -threads:1 " + std::string(kRun) + opts + " " + antociCase() + " " + whole);
    ASSERT_EQ(a.status, 0) << a.out;
    const Program b = runSeaspring("-cpu -threads:1 " + std::string(kRun) + opts + " -checkpoint:0.015 -nsteps:300 " +
                                   antociCase() + " " + cut);
    ASSERT_EQ(b.status, 0) << b.out;
    ASSERT_NE(b.out.find("checkpoint t="), std::string::npos) << b.out;
    ASSERT_NE(stateHash(b), stateHash(a));  // it did stop early
    const Program c = runSeaspring(restart_backend + " " + std::string(kRun) + opts + " -restart:" + cut +
                                   "/restart.h5 " + antociCase() + " " + cut);
    ASSERT_EQ(c.status, 0) << c.out;
    EXPECT_NE(c.out.find("continuing the outputs"), std::string::npos) << c.out;
    EXPECT_EQ(stateHash(c), stateHash(a)) << c.out;
    ASSERT_EQ(stateHash(a).size(), 16u) << a.out;
    expectSameFiles(whole, cut, {"ledger.csv", "gauges/GaugesForce_Gate.csv", "gauges/GaugesMarker_Tip.csv", "parts.xdmf"});
    // Run.out holds both runs' consoles.
    const std::string log = test::readFile(cut + "/Run.out");
    EXPECT_NE(log.find("checkpoint t="), std::string::npos);
    EXPECT_NE(log.find("restarted from"), std::string::npos);
    // The rates count this run's steps: the continuation made the steps the whole run made
    // after the checkpoint, and says so (its loop time is spent on those alone).
    const std::string ja = test::readFile(whole + "/run.json"), jc = test::readFile(cut + "/run.json");
    const long long steps = jsonInteger(ja, "steps");
    EXPECT_EQ(jsonInteger(ja, "steps_this_run"), steps);
    EXPECT_EQ(jsonInteger(jc, "steps"), steps);
    const long long cont = jsonInteger(jc, "steps_this_run");
    EXPECT_GT(cont, 0);
    EXPECT_LT(cont, steps - 100) << "the first run stopped at step 300, the checkpoint before it";
    EXPECT_NE(c.out.find("(" + std::to_string(cont) + " of them in this run, from t="), std::string::npos) << c.out;
}

bool gpuUsable() {
    static const bool usable = [] {
        const std::string dir = test::scratch("restart_gpu_probe");
        fs::remove_all(dir);
        return runSeaspring("-gpu -nsteps:1 -progress:0 -sv:none " + antociCase() + " " + dir).status == 0;
    }();
    return usable;
}

}  // namespace

TEST(Restart, SymplecticContinuesWithTheSameBitsAndFiles) {
    checkContinuation("restart_sym", "-symplectic", "-cpu -threads:2");
}

TEST(Restart, VerletContinuesWithTheSameBitsAndFiles) {
    checkContinuation("restart_verlet", "-verlet:40", "-cpu -threads:1");
}

TEST(Restart, SpsContinuesWithTheSameBits) {
    checkContinuation("restart_sps", "-symplectic -viscolamsps:1e-6", "-cpu -threads:2");
}

TEST(Restart, ATerminateFileSavesAndStopsAndTheRestartRemovesIt) {
    const std::string dir = test::scratch("restart_terminate");
    fs::remove_all(dir);
    const std::string whole = dir + "/whole", cut = dir + "/cut";
    const Program a = runSeaspring("-cpu -threads:1 " + std::string(kRun) + antociCase() + " " + whole);
    ASSERT_EQ(a.status, 0) << a.out;
    fs::create_directories(cut);
    std::ofstream(cut + "/TERMINATE").put('\n');
    const Program b = runSeaspring("-cpu -threads:1 " + std::string(kRun) + antociCase() + " " + cut);
    ASSERT_EQ(b.status, 0) << b.out;
    EXPECT_NE(b.out.find("TERMINATE"), std::string::npos) << b.out;
    ASSERT_TRUE(fs::exists(cut + "/restart.h5"));
    const Program c = runSeaspring("-cpu -threads:1 " + std::string(kRun) + "-restart:" + cut + "/restart.h5 " +
                                   antociCase() + " " + cut);
    ASSERT_EQ(c.status, 0) << c.out;
    EXPECT_FALSE(fs::exists(cut + "/TERMINATE"));
    EXPECT_EQ(stateHash(c), stateHash(a)) << c.out;
}

TEST(Restart, IntoAnotherOutdirStartsItsFilesAfresh) {
    const std::string dir = test::scratch("restart_other");
    fs::remove_all(dir);
    const Program a = runSeaspring("-cpu -threads:1 " + std::string(kRun) + antociCase() + " " + dir + "/whole");
    ASSERT_EQ(a.status, 0) << a.out;
    const Program b = runSeaspring("-cpu -threads:1 " + std::string(kRun) + "-checkpoint:0.02 " + antociCase() + " " +
                                   dir + "/cut");
    ASSERT_EQ(b.status, 0) << b.out;
    EXPECT_EQ(stateHash(b), stateHash(a)) << "writing restart files changed the run";
    const Program c = runSeaspring("-cpu -threads:1 " + std::string(kRun) + "-restart:" + dir + "/cut/restart.h5 " +
                                   antociCase() + " " + dir + "/new");
    ASSERT_EQ(c.status, 0) << c.out;
    EXPECT_NE(c.out.find("outputs start afresh"), std::string::npos) << c.out;
    EXPECT_EQ(stateHash(c), stateHash(a)) << c.out;
    // The new OUTDIR's gauge file: its header, then only the rows after the restart time.
    const std::string g = test::readFile(dir + "/new/gauges/GaugesForce_Gate.csv");
    EXPECT_EQ(g.rfind("time;", 0), 0u) << g;
    EXPECT_EQ(g.find("\n0;"), std::string::npos) << g;
}

TEST(Restart, BadRestartsNameTheFile) {
    const std::string dir = test::scratch("restart_bad");
    fs::remove_all(dir);
    const Program b = runSeaspring("-cpu -threads:1 " + std::string(kRun) + "-checkpoint:0.02 -nsteps:500 " +
                                   antociCase() + " " + dir + "/cut");
    ASSERT_EQ(b.status, 0) << b.out;
    const std::string file = dir + "/cut/restart.h5";
    // Other physics options than the run that wrote it.
    Program p = runSeaspring("-cpu " + std::string(kRun) + "-viscoart:0.05 -restart:" + file + " " + antociCase() +
                             " " + dir + "/o1");
    EXPECT_NE(p.status, 0);
    EXPECT_NE(p.out.find(file), std::string::npos) << p.out;
    EXPECT_NE(p.out.find("same options"), std::string::npos) << p.out;
    EXPECT_EQ(p.out.find("cells differ"), std::string::npos) << p.out;  // the same cells
    // Other cells (as a file written before -cellmode:auto changed): the option that continues it.
    p = runSeaspring("-cpu " + std::string(kRun) + "-cellmode:third -restart:" + file + " " + antociCase() + " " + dir +
                     "/o5");
    EXPECT_NE(p.status, 0);
    EXPECT_NE(p.out.find("its cells differ: continue it with -cellmode:h)"), std::string::npos) << p.out;
    EXPECT_EQ(p.out.find("skin differs"), std::string::npos) << p.out;  // the same skin
    // Another skin (as a file written before the small runs' default skin changed), and none.
    p = runSeaspring("-cpu " + std::string(kRun) + "-skin:0.05 -restart:" + file + " " + antociCase() + " " + dir +
                     "/o6");
    EXPECT_NE(p.status, 0);
    EXPECT_NE(p.out.find("its skin differs: continue it with -skin:0.25)"), std::string::npos) << p.out;
    const Program z = runSeaspring("-cpu -threads:1 " + std::string(kRun) + "-skin:0 -checkpoint:0.02 -nsteps:500 " +
                                   antociCase() + " " + dir + "/cut0");
    ASSERT_EQ(z.status, 0) << z.out;
    p = runSeaspring("-cpu " + std::string(kRun) + "-restart:" + dir + "/cut0/restart.h5 " + antociCase() + " " + dir +
                     "/o7");
    EXPECT_NE(p.status, 0);
    EXPECT_NE(p.out.find("its skin differs: continue it with -skin:0)"), std::string::npos) << p.out;
    // Missing, and not a restart file.
    p = runSeaspring("-cpu " + std::string(kRun) + "-restart:" + dir + "/none.h5 " + antociCase() + " " + dir + "/o2");
    EXPECT_NE(p.status, 0);
    EXPECT_NE(p.out.find("none.h5: restart file not found"), std::string::npos) << p.out;
    p = runSeaspring("-cpu " + std::string(kRun) + "-restart:" + antociCase() + ".h5 " + antociCase() + " " + dir +
                     "/o3");
    EXPECT_NE(p.status, 0);
    EXPECT_NE(p.out.find("not a SeaSpring restart file"), std::string::npos) << p.out;
    // Another case (same physics line, other particles).
    const std::string other =
        test::generateCaseFile(dir + "/other", "ag", test::caseDef("antoci_gate2d/AntociGate2D_Def.xml"), 0.005);
    p = runSeaspring("-cpu " + std::string(kRun) + "-restart:" + file + " " + other + " " + dir + "/o4");
    EXPECT_NE(p.status, 0);
    EXPECT_NE(p.out.find(file), std::string::npos) << p.out;
    EXPECT_NE(p.out.find("another case"), std::string::npos) << p.out;
}

TEST(Restart, CpuAndGpuContinueEachOthersRuns) {
    if (!gpuUsable()) GTEST_SKIP() << "no usable GPU: the CPU->GPU and GPU->CPU restarts run on the GPU machine";
    checkContinuation("restart_cpu_gpu", "-symplectic", "-gpu");
    const std::string dir = test::scratch("restart_gpu_cpu");
    fs::remove_all(dir);
    const Program a = runSeaspring("-gpu " + std::string(kRun) + antociCase() + " " + dir + "/whole");
    ASSERT_EQ(a.status, 0) << a.out;
    const Program b = runSeaspring("-gpu " + std::string(kRun) + "-checkpoint:0.015 -nsteps:300 " + antociCase() + " " +
                                   dir + "/cut");
    ASSERT_EQ(b.status, 0) << b.out;
    const Program c = runSeaspring("-cpu -threads:2 " + std::string(kRun) + "-restart:" + dir + "/cut/restart.h5 " +
                                   antociCase() + " " + dir + "/cut");
    ASSERT_EQ(c.status, 0) << c.out;
    EXPECT_EQ(stateHash(c), stateHash(a)) << c.out;
}

// The cells' switch (solver/cell_switch.h) across restarts: the 3D dam break (cells of dp) goes
// over to cells of h at step 188 of 250 with -cellswitch:0.05. A file written after the switch
// holds the cells of h (their cell ranges and near flags) and continues with the uninterrupted
// run's bits, on the CPU and (where usable) on the GPU; a file written before it switches
// later, as the uninterrupted run did. Without the switch the options differ: refused, naming
// the -cellswitch that continues it (both ways).
TEST(Restart, ContinuesAcrossTheCellSwitch) {
    const std::string dir = test::scratch("restart_switch");
    fs::remove_all(dir);
    const std::string kase =
        test::generateCaseFile(dir + "/case", "db", test::caseDef("dambreak3d/DamBreak3D_Def.xml"), 0.04);
    const std::string run = "-tmax:1 -tout:0.05 -progress:0 -sv:none -cellswitch:0.05 ";
    const Program a = runSeaspring("-cpu -threads:1 " + run + "-nsteps:250 " + kase + " " + dir + "/whole");
    ASSERT_EQ(a.status, 0) << a.out;
    ASSERT_NE(a.out.find("shared their cells with another"), std::string::npos) << a.out;
    const std::string after = dir + "/after", before = dir + "/before";
    ASSERT_EQ(runSeaspring("-cpu -threads:2 " + run + "-checkpoint:0.08 -nsteps:220 " + kase + " " + after).status, 0);
    ASSERT_EQ(runSeaspring("-cpu -threads:2 " + run + "-checkpoint:0.05 -nsteps:150 " + kase + " " + before).status, 0);
    const Program c = runSeaspring("-cpu -threads:2 " + run + "-nsteps:250 -restart:" + after + "/restart.h5 " + kase +
                                   " " + dir + "/c1");
    ASSERT_EQ(c.status, 0) << c.out;
    EXPECT_EQ(c.out.find("shared their cells with another"), std::string::npos) << "switched before the file: " << c.out;
    EXPECT_NE(c.out.find("; cells of h from divide"), std::string::npos) << c.out;
    EXPECT_EQ(stateHash(c), stateHash(a)) << c.out;
    EXPECT_NE(test::readFile(dir + "/c1/run.json").find("\"cell_switch_divide\": "), std::string::npos);
    const Program d = runSeaspring("-cpu -threads:1 " + run + "-nsteps:250 -restart:" + before + "/restart.h5 " + kase +
                                   " " + dir + "/c2");
    ASSERT_EQ(d.status, 0) << d.out;
    EXPECT_NE(d.out.find("shared their cells with another"), std::string::npos) << d.out;
    EXPECT_EQ(stateHash(d), stateHash(a)) << d.out;
    if (gpuUsable()) {
        const Program g = runSeaspring("-gpu " + run + "-nsteps:250 -restart:" + after + "/restart.h5 " + kase + " " +
                                       dir + "/c3");
        ASSERT_EQ(g.status, 0) << g.out;
        EXPECT_EQ(stateHash(g), stateHash(a)) << g.out;
    }
    const Program n = runSeaspring("-cpu " + std::string("-tmax:1 -progress:0 -sv:none -cellswitch:0 -nsteps:250 ") +
                                   "-restart:" + after + "/restart.h5 " + kase + " " + dir + "/c4");
    EXPECT_NE(n.status, 0);
    EXPECT_NE(n.out.find("same options"), std::string::npos) << n.out;
    EXPECT_NE(n.out.find("its cells' switch differs: continue it with -cellswitch:0.05)"), std::string::npos) << n.out;
    // A file of a run without the switch (as one written before it existed), continued with it.
    ASSERT_EQ(runSeaspring("-cpu " + std::string("-tmax:1 -progress:0 -sv:none -cellswitch:0 -checkpoint:0.05 ") +
                           "-nsteps:150 " + kase + " " + dir + "/plain")
                  .status,
              0);
    const Program m = runSeaspring("-cpu -tmax:1 -progress:0 -sv:none -nsteps:250 -restart:" + dir +
                                   "/plain/restart.h5 " + kase + " " + dir + "/c5");
    EXPECT_NE(m.status, 0);
    EXPECT_NE(m.out.find("its cells' switch differs: continue it with -cellswitch:0)"), std::string::npos) << m.out;
}
