// SeaSpring — MIT licence.
/// \file solver_test_util.cpp
#include "solver_test_util.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "solver/backend.h"
#include "solver/solver_case.h"

namespace seaspring::test {

namespace fs = std::filesystem;

std::string scratch(const std::string& tag) {
    // The pid alone repeats across runs (old directories stay in TempDir(), and a program run
    // into one that holds an earlier run's output exits with 2): the process's start time, taken
    // once, makes the name unique per run and the same for every call in this process.
    static const std::string run = std::to_string(::getpid()) + "_" +
                                   std::to_string(std::chrono::system_clock::now().time_since_epoch().count());
    return ::testing::TempDir() + "seaspring_" + tag + "_" + run;
}

std::string caseDef(const std::string& rel) { return std::string(SEASPRING_SOURCE_DIR) + "/cases/" + rel; }

std::string readFile(const std::string& path) {
    std::ifstream f(path);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

std::string replaceOnce(std::string text, const std::string& from, const std::string& to) {
    const std::size_t k = text.find(from);
    EXPECT_NE(k, std::string::npos) << "'" << from << "' not found";
    EXPECT_EQ(text.find(from, k + 1), std::string::npos) << "'" << from << "' found twice";
    if (k != std::string::npos) text.replace(k, from.size(), to);
    return text;
}

double dist(const physics::Double3& a, const physics::Double3& b) {
    return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
}

bool finite(const physics::Double3& a) { return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z); }

std::size_t brokenSlots(const solver::HostState& st) {
    return std::size_t(std::count_if(st.bond_broken.begin(), st.bond_broken.end(), [](std::uint8_t b) { return b != 0; }));
}

std::string generateCaseFile(const std::string& dir, const std::string& name, const std::string& def_path,
                             double dp) {
    fs::create_directories(dir);
    std::ostringstream cmd;
    cmd << "'" << SEASPRING_GENCASE_BIN << "' '" << def_path << "' '" << dir << "/" << name << "'";
    if (dp > 0) cmd << " -dp:" << dp;
    cmd << " > '" << dir << "/" << name << ".gencase.log' 2>&1";
    if (std::system(cmd.str().c_str()) != 0) {
        std::ifstream log(dir + "/" + name + ".gencase.log");
        std::stringstream s;
        s << log.rdbuf();
        throw Error("gencase failed for " + def_path + ":\n" + s.str());
    }
    return dir + "/" + name;
}

std::string generateCase(const std::string& dir, const std::string& name, const std::string& def_xml,
                         double dp) {
    fs::create_directories(dir);
    const std::string def = dir + "/" + name + "_Def.xml";
    std::ofstream(def) << def_xml;
    return generateCaseFile(dir, name, def, dp);
}

std::string pistonCase(const std::string& dir, const char* file, const std::string& params) {
    const std::string xml = readFile(std::string(SEASPRING_TEST_DATA_DIR) + "/phases/" + file);
    return generateCase(dir, "piston", replaceOnce(xml, "<!--PARAMETERS-->", params));
}

SolverRun runOn(std::unique_ptr<solver::Backend> backend, const std::string& case_path, const std::string& outdir,
                const std::function<void(solver::RunOptions&)>& tweak,
                const solver::Simulation::OutputObserver& observe) {
    SolverRun r;
    r.kase = solver::loadSolverCase(case_path);
    solver::RunOptions o;
    o.case_path = case_path;
    o.outdir = outdir;
    o.quiet = true;
    o.save_h5 = false;
    if (tweak) tweak(o);
    solver::applyOverrides(o, r.kase.params);
    if (o.tmax) r.kase.params.time_max = *o.tmax;
    if (o.tout) r.kase.params.time_out = *o.tout;
    std::ostringstream log;
    solver::Simulation sim(r.kase, o, std::move(backend), log);
    if (observe) sim.onOutput(observe);
    r.summary = sim.run();
    r.state = sim.finalState();
    return r;
}

SolverRun runCpu(const std::string& case_path, const std::string& outdir, int threads,
                 const std::function<void(solver::RunOptions&)>& tweak,
                 const solver::Simulation::OutputObserver& observe) {
    return runOn(
        solver::makeCpuBackend(threads), case_path, outdir,
        [&](solver::RunOptions& o) {
            o.backend = solver::RunOptions::Backend::Cpu;
            o.threads = threads;
            if (tweak) tweak(o);
        },
        observe);
}

}  // namespace seaspring::test
