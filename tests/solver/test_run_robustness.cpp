// SeaSpring — MIT licence.
/// \file test_run_robustness.cpp
/// \brief Long runs that survive (issue 14): blow-ups are caught and diagnosed (which
///        particles, which quantity, the likely option) with the last good state kept; solids
///        that leave the domain are counted per body; absurd sub-steps and hostile options stop
///        with a clear error; SIGINT/SIGTERM end a run cleanly; an OUTDIR never mixes two runs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/wait.h>

#include "../unit/error_expect.h"
#include "core/device_memory.h"
#include "physics/particle_fields.h"
#include "solver/run_report.h"
#include "solver/output_dir.h"
#include "solver/run_limits.h"
#include "solver/stop_signal.h"
#include "solver_test_util.h"

using namespace seaspring;

namespace {

namespace fs = std::filesystem;

/// The 2D dam-break front at dp 0.025 (401 wall and 3200 fluid particles).
std::string damBreak(const std::string& dir, const std::string& extra_parameter = "") {
    std::string xml = test::readFile(test::caseDef("dambreak_front2d/DambreakFront2D_Def.xml"));
    if (!extra_parameter.empty()) xml = test::replaceOnce(xml, "<parameters>", "<parameters>" + extra_parameter);
    return test::generateCase(dir, "Front", xml, 0.025);
}

/// The hanging beam (750 solid particles, solid only) with `from` replaced by `to`.
std::string beam(const std::string& dir, const std::string& name, const std::string& from = "",
                 const std::string& to = "") {
    std::string xml = test::readFile(test::caseDef("hanging_beam/HangingBeam_Def.xml"));
    if (!from.empty()) xml = test::replaceOnce(xml, from, to);
    return test::generateCase(dir, name, xml);
}

/// Runs the seaspring program; returns its exit code (stdout and stderr to `log`).
int runProgram(const std::string& args, const std::string& log) {
    const std::string cmd = "OMP_WAIT_POLICY=passive '" + std::string(SEASPRING_SOLVER_BIN) + "' " + args + " >'" +
                            log + "' 2>&1";
    const int status = std::system(cmd.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

TEST(RunRobustness, FluidBlowupIsDiagnosedAndBlamesDtFixed) {
    const std::string dir = test::scratch("robust_fluid");
    const std::string kase = damBreak(dir);
    // A normal run: no diagnosis, exit code 0.
    const test::SolverRun good = test::runCpu(kase, dir + "/good", 2, [](solver::RunOptions& o) { o.nsteps = 30; });
    EXPECT_FALSE(good.summary.blowup.has_value());
    EXPECT_EQ(good.summary.exit_code, 0);
    // A fixed dt far above the CFL step loses the fluid within a few steps (it used to end with
    // exit 0 and "TimeMax reached" after losing 99.8% of it).
    const test::SolverRun bad = test::runCpu(kase, dir + "/bad", 2, [](solver::RunOptions& o) { o.dt_fixed = 0.002; });
    ASSERT_TRUE(bad.summary.blowup.has_value());
    const solver::BlowupDiagnosis& d = *bad.summary.blowup;
    EXPECT_EQ(d.quantity, "fluid loss");
    EXPECT_EQ(bad.summary.exit_code, 1);
    EXPECT_HAS(bad.summary.stop_reason, "blow-up");
    EXPECT_HAS(d.likely_option, "-dtfixed (0.002 s");
    EXPECT_LT(d.step, 30);
    EXPECT_FALSE(d.particles.empty());
    EXPECT_GE(d.particles[0].id, 401u);  // fluid particles
    EXPECT_LT(d.value, 0.1);
    EXPECT_EQ(d.bound, 0.1);  // MinFluidStop's default
}

TEST(RunRobustness, SolidBlowupBlamesVcpmSubsteps) {
    const std::string dir = test::scratch("robust_solid");
    const std::string kase =
        test::generateCaseFile(dir, "Plate", test::caseDef("hydrostatic_plate/HydrostaticPlate_Def.xml"), 0.025);
    // One solid sub-step per fluid step: 23 times the solid's stability limit. The message used
    // to blame VcpmDtCoef, and part files held displacements of 1e19 m. The default checks (no
    // scan of the state before the first output) stop the run at the end of the step in which
    // a sub-step first passed a bound.
    std::vector<double> output_times;
    const test::SolverRun r = test::runCpu(
        kase, dir + "/out", 2,
        [](solver::RunOptions& o) {
            o.solid_substeps = 1;
            o.tmax = 0.01;
        },
        [&](double t, long long, const solver::HostState&) { output_times.push_back(t); });
    ASSERT_TRUE(r.summary.blowup.has_value());
    const solver::BlowupDiagnosis& d = *r.summary.blowup;
    EXPECT_TRUE(d.quantity == "solid bond strain" || d.quantity == "solid speed") << d.quantity;
    EXPECT_EQ(d.likely_option.rfind("-vcpmsubsteps:1 ", 0), 0u) << d.likely_option;
    EXPECT_EQ(r.summary.exit_code, 1);
    ASSERT_FALSE(d.particles.empty());
    EXPECT_GE(d.particles[0].id, 744u);  // the solid block
    EXPECT_LT(d.particles[0].id, 744u + 78u);
    ASSERT_TRUE(std::isfinite(d.onset));
    EXPECT_LE(d.onset, d.time);
    EXPECT_GT(d.onset, d.time - r.summary.dt_last) << "caught " << d.time - d.onset << " s after it happened";
    EXPECT_LT(d.step, 50);
    // The last good state is kept: the t = 0 output, the only state scanned before (the
    // failing one is never written).
    ASSERT_EQ(output_times.size(), 1u);
    EXPECT_EQ(r.summary.last_good_time, 0.0);
    // With a scan after every step (-blowupcheck:1) the last good state is the step before.
    output_times.clear();
    const test::SolverRun every = test::runCpu(
        kase, dir + "/every", 2,
        [](solver::RunOptions& o) {
            o.solid_substeps = 1;
            o.blowup_check_every = 1;
            o.tmax = 0.01;
        },
        [&](double t, long long, const solver::HostState&) { output_times.push_back(t); });
    ASSERT_TRUE(every.summary.blowup.has_value());
    EXPECT_EQ(every.summary.blowup->step, d.step);
    ASSERT_EQ(output_times.size(), 2u);
    EXPECT_GT(output_times[1], 0.0);
    EXPECT_LT(output_times[1], d.time);
    EXPECT_EQ(every.summary.last_good_time, output_times[1]);
    // Kept at every K-th scan only (-blowupkeep:K; the others are quick scans, counted on the
    // backend): the same step stops the run, and the last good state is the last kept one, the
    // scan at the largest multiple of K before the failing step (none: the t = 0 output).
    for (const long long keep : {2LL, 3LL}) {
        std::vector<long long> steps;
        const test::SolverRun k = test::runCpu(
            kase, dir + "/keep" + std::to_string(keep), 2,
            [keep](solver::RunOptions& o) {
                o.solid_substeps = 1;
                o.blowup_check_every = 1;
                o.blowup_keep_every = keep;
                o.tmax = 0.01;
            },
            [&](double, long long s, const solver::HostState&) { steps.push_back(s); });
        ASSERT_TRUE(k.summary.blowup.has_value()) << keep;
        EXPECT_EQ(k.summary.blowup->step, d.step) << keep;
        EXPECT_EQ(k.summary.blowup->quantity, d.quantity) << keep;
        const long long kept = ((d.step - 1) / keep) * keep;
        ASSERT_EQ(steps.size(), kept > 0 ? 2u : 1u) << keep;
        EXPECT_EQ(steps.back(), kept) << keep;
    }
}

TEST(RunRobustness, SolidLeavingTheDomainIsFrozenAndCountedPerBody) {
    const std::string dir = test::scratch("robust_fall");
    // No clamp, no damping: the beam falls freely and leaves the domain (0.2 m below it) at 0.2 s;
    // by 0.5 s all of it lies more than 2h below (the margin: a plate at the edge of a case may
    // bend a little out of the default domain without being frozen or counted). Each particle
    // freezes where it crossed, at rest, with its bonds broken; free fall would have taken it
    // 1 m further down.
    const std::string kase = beam(dir, "Fall", "mkclamp=\"0\" density=\"2500\" youngmod=\"3e6\" poissratio=\"0.3\" damping=\"1\"",
                                  "density=\"2500\" youngmod=\"3e5\" poissratio=\"0.3\"");
    // Outputs only at 0 and 0.5 s: the periodic scans (every 100 steps, each a full scan of the
    // downloaded state at this size) find the particles outside.
    const test::SolverRun r = test::runCpu(kase, dir + "/out", 2, [](solver::RunOptions& o) {
        o.tmax = 0.5;
        o.tout = 0.5;
    });
    EXPECT_FALSE(r.summary.blowup.has_value());
    ASSERT_EQ(r.summary.solids_outside.size(), 1u);
    const solver::SolidOutside& o = r.summary.solids_outside[0];
    EXPECT_EQ(o.mkbound, 1);
    EXPECT_EQ(o.particles, 750u);
    EXPECT_EQ(o.outside, 750u);
    EXPECT_GT(o.first_time, 0.15);
    EXPECT_LT(o.first_time, 0.45);
    const solver::SolverCase& c = r.kase;
    const double floor = c.domain_min.z - 2.0 * c.constants.h;
    const double g = std::fabs(c.constants.gravity.z);
    double lowest = 1e300;
    for (std::uint32_t i = 0; i < 750; ++i) {
        const physics::Double3 v = r.state.solid_vel[i];
        EXPECT_EQ(v.x * v.x + v.y * v.y + v.z * v.z, 0.0) << i;
        lowest = std::min(lowest, r.state.pos[c.bonds->first_solid + i].z);
    }
    // One sub-step past the crossing at most: v dt with v = g t, t <= 0.5 s.
    EXPECT_LT(floor - lowest, g * 0.5 * r.summary.solid_dt) << "lowest " << lowest << ", box floor " << floor;
    EXPECT_GT(floor - lowest, 0.0);
    EXPECT_EQ(r.summary.broken_bonds, c.bonds->bondSlots() / 2);  // no clamp bonds
    // Quick scans (no state downloaded between outputs, -blowupkeep:1000) count the solids
    // outside the domain from their positions alone: the same counts, first seen at the same
    // scan.
    const test::SolverRun q = test::runCpu(kase, dir + "/quick", 2, [](solver::RunOptions& o) {
        o.tmax = 0.5;
        o.tout = 0.5;
        o.blowup_keep_every = 1000;
    });
    ASSERT_EQ(q.summary.solids_outside.size(), 1u);
    EXPECT_EQ(q.summary.solids_outside[0].outside, o.outside);
    EXPECT_EQ(q.summary.solids_outside[0].most, o.most);
    EXPECT_EQ(q.summary.solids_outside[0].first_time, o.first_time);
}

// The hydrostatic plate is the floor of its tank, so its lowest row is the edge of the default
// domain (the particles' bounding box) and bends below it at once: not a solid leaving the
// domain (without the 2h margin 39 of its 78 particles were counted, with a warning, in a valid
// validation case).
TEST(RunRobustness, APlateBendingAtTheEdgeOfTheDomainIsNotCounted) {
    const std::string dir = test::scratch("robust_edgeplate");
    const std::string kase =
        test::generateCaseFile(dir, "hp", test::caseDef("hydrostatic_plate/HydrostaticPlate_Def.xml"), 0.025);
    const test::SolverRun r = test::runCpu(kase, dir + "/out", 2, [](solver::RunOptions& o) {
        o.tmax = 0.01;
        o.tout = 0.005;
    });
    ASSERT_EQ(r.summary.solids_outside.size(), 1u);
    EXPECT_EQ(r.summary.solids_outside[0].most, 0u);
}

TEST(RunRobustness, SolidOnlyCasesNeedNoSpeedOfSound) {
    const std::string dir = test::scratch("robust_nohswl");
    const std::string with = beam(dir, "With");
    const std::string without = beam(dir, "Without", "<hswl value=\"0.1\" auto=\"false\" units_comment=\"m\" />", "");
    auto run = [&](const std::string& k, const std::string& out) {
        return test::runCpu(k, dir + out, 2, [](solver::RunOptions& o) { o.nsteps = 200; });
    };
    const test::SolverRun a = run(with, "/with"), b = run(without, "/without");
    EXPECT_EQ(b.kase.constants.speedsound, 0.0);
    EXPECT_EQ(a.summary.state_hash, b.summary.state_hash);  // c0 plays no part in a solid-only run
}

TEST(RunRobustness, AbsurdSolidSubstepsStopWithTheMaterial) {
    const std::string dir = test::scratch("robust_e");
    const std::string stiff = beam(dir, "Stiff", "youngmod=\"3e6\"", "youngmod=\"1e300\"");
    const std::string soft = beam(dir, "Soft", "youngmod=\"3e6\"", "youngmod=\"1e-300\"");
    std::string m = test::errorOf([&] { test::runCpu(stiff, dir + "/a", 1); });
    EXPECT_HAS(m, "Stiff.xml:");
    EXPECT_HAS(m, "youngmod=1e+300");
    EXPECT_HAS(m, "sub-steps (at most 1e+12)");
    m = test::errorOf([&] { test::runCpu(soft, dir + "/b", 1); });
    EXPECT_HAS(m, "youngmod=1e-300");
    EXPECT_HAS(m, "longer than TimeMax");
}

TEST(RunRobustness, AHugeFixedStepEnds) {
    // -dtfixed:1e30 made the output-time loop spin for ever (1e30 + TimeOut == 1e30).
    const std::string dir = test::scratch("robust_dt");
    const std::string kase = damBreak(dir, "<parameter key=\"MinFluidStop\" value=\"0\"/>");
    const test::SolverRun r = test::runCpu(kase, dir + "/out", 2, [](solver::RunOptions& o) { o.dt_fixed = 1e30; });
    EXPECT_EQ(r.summary.steps, 1);
    EXPECT_EQ(r.summary.physical_time, 1e30);
    EXPECT_EQ(r.summary.stop_reason, "TimeMax reached");
}

TEST(RunRobustness, StopSignalEndsTheRunCleanly) {
    const std::string dir = test::scratch("robust_signal");
    const std::string kase = beam(dir, "Beam");
    solver::setStopSignalForTest(SIGTERM);  // as if received before the first step
    const test::SolverRun r = test::runCpu(kase, dir + "/out", 1);
    solver::setStopSignalForTest(0);
    EXPECT_EQ(r.summary.stop_reason, "stopped by SIGTERM");
    EXPECT_EQ(r.summary.exit_code, 128 + SIGTERM);
    EXPECT_EQ(r.summary.steps, 0);
}

TEST(RunRobustness, OutdirWithAnEarlierRunIsRefusedOrCleared) {
    const std::string dir = test::scratch("robust_outdir");
    const std::string kase = beam(dir, "Beam");  // the case lives in dir: never touched
    const std::string args = "-cpu -threads:1 -nsteps:20 -progress:0 '" + kase + "' '" + dir + "'";
    ASSERT_EQ(runProgram(args, dir + "/../robust_outdir_1.log"), 0);
    std::ofstream(dir + "/data/part_0099.h5") << "stale";  // a part file of the earlier run
    EXPECT_EQ(runProgram(args, dir + "/../robust_outdir_2.log"), 2);
    EXPECT_HAS(test::readFile(dir + "/../robust_outdir_2.log"), "OUTDIR holds an earlier run (Run.out, run.json");
    EXPECT_TRUE(fs::exists(dir + "/data/part_0099.h5"));
    EXPECT_EQ(runProgram("-overwrite " + args, dir + "/../robust_outdir_3.log"), 0);
    EXPECT_FALSE(fs::exists(dir + "/data/part_0099.h5"));
    EXPECT_TRUE(fs::exists(kase + ".xml"));
    EXPECT_TRUE(fs::exists(kase + ".h5"));
    EXPECT_TRUE(solver::earlierRunFiles(dir + "/data").empty());
}

TEST(RunRobustness, TheProgramWritesRunJsonWithTheDiagnosisAndExitsWithOne) {
    const std::string dir = test::scratch("robust_program");
    const std::string kase = damBreak(dir);
    const int code = runProgram("-cpu -threads:1 -progress:0 -dtfixed:0.002 '" + kase + "' '" + dir + "/out'",
                                dir + "/log.txt");
    EXPECT_EQ(code, 1);
    const std::string json = test::readFile(dir + "/out/run.json");
    EXPECT_HAS(json, "\"exit_code\": 1");
    EXPECT_HAS(json, "\"blowup\": {");
    EXPECT_HAS(json, "\"quantity\": \"fluid loss\"");
    EXPECT_HAS(json, "\"likely_option\": \"DtFixed / -dtfixed");
    EXPECT_HAS(test::readFile(dir + "/out/Run.out"), "blow-up detected (fluid loss)");
    EXPECT_HAS(test::readFile(dir + "/log.txt"), "Stopped (blow-up: fluid loss)");
    EXPECT_HAS(json, "\"memory\": {");
    EXPECT_HAS(json, "\"host_peak_bytes\": ");  // the CPU: no GPU figures
    EXPECT_EQ(json.find("gpu_arrays_peak_bytes"), std::string::npos) << json;
    EXPECT_HAS(test::readFile(dir + "/log.txt"), "\nMemory: host peak ");
}

// The memory a run reports (summary, run.json, Run.out's "Memory:" line): the host's peak on
// every backend; on the GPU the most its arrays held (the device ledger, core/device_memory.h) —
// at least every particle's always-present fields of the field table, counted in bytes — and
// every byte of it given back when the run's backend goes.
TEST(RunRobustness, RunsReportTheirMemoryAndTheGpuGivesItBack) {
    const std::string dir = test::scratch("robust_memory");
    const std::string kase = damBreak(dir);
    std::uint64_t always = 0;  // bytes per particle of the fields every run allocates
#define SEASPRING_ADD_ALWAYS(name, type, need, flags) \
    if (physics::FieldNeed::need == physics::FieldNeed::Always) always += sizeof(type);
    SEASPRING_PARTICLE_FIELDS(SEASPRING_ADD_ALWAYS)
#undef SEASPRING_ADD_ALWAYS
    EXPECT_GE(always, 100u);
    const auto steps = [](solver::RunOptions& o) { o.nsteps = 5; };
    const test::SolverRun cpu = test::runCpu(kase, dir + "/cpu", 1, steps);
    EXPECT_GT(cpu.summary.host_bytes_peak, std::uint64_t(cpu.summary.np) * always);
    EXPECT_EQ(cpu.summary.gpu_bytes_peak, 0u);
    EXPECT_EQ(cpu.summary.gpu_bytes_total, 0u);
    EXPECT_EQ(solver::memoryLine(cpu.summary).rfind("Memory: host peak ", 0), 0u) << solver::memoryLine(cpu.summary);

    const std::uint64_t held = deviceBytesHeld();  // before the backend's own few bytes
    std::string why;
    std::unique_ptr<solver::Backend> gpu = solver::makeCudaBackend(0, why);
    if (!gpu) GTEST_SKIP() << "the GPU's figures: " << why << " (the CPU's were checked)";
    const test::SolverRun g = test::runOn(std::move(gpu), kase, dir + "/gpu", steps);
    EXPECT_EQ(deviceBytesHeld(), held) << "the run's device arrays were not all given back";
    EXPECT_GE(g.summary.gpu_bytes_peak, held + std::uint64_t(g.summary.np) * always);
    EXPECT_LT(g.summary.gpu_bytes_peak, g.summary.gpu_bytes_total);
    EXPECT_GT(g.summary.gpu_bytes_total, std::uint64_t(1) << 30);
    EXPECT_EQ(g.summary.state_hash, cpu.summary.state_hash);
    const std::string line = solver::memoryLine(g.summary);
    EXPECT_EQ(line.rfind("Memory: GPU arrays at most ", 0), 0u) << line;
    EXPECT_HAS(line, " bytes per particle) of the device's ");
}

// A case too large for the host's memory (capped by SEASPRING_MEMORY_LIMIT) is refused before
// the run, naming the case file and what it needs beyond the case already read: on the CPU
// 3601 particles x 480 B less the case's arrays (51-63 B each), about 1.50-1.54 MB, so 1.4 MB
// is refused and 1.6 MB runs (counting the case twice, 1.73 MB, would refuse it); on the GPU,
// whose arrays are on the device, 3601 x 320 B fits in 1.4 MB, and the run goes on.
TEST(RunRobustness, ACaseTooLargeForTheHostIsRefusedNamingIt) {
    const std::string dir = test::scratch("robust_host_memory");
    const std::string kase = damBreak(dir);
    const solver::SolverCase c = solver::loadSolverCase(kase);
    EXPECT_GE(solver::loadedCaseBytes(c), 3601.0 * 51);
    EXPECT_LE(solver::loadedCaseBytes(c), 3601.0 * 63);
    std::string why;
    const bool gpu = solver::makeCudaBackend(0, why) != nullptr;
    ::setenv("SEASPRING_MEMORY_LIMIT", "1400000", 1);
    const int code = runProgram("-cpu -threads:1 -progress:0 -nsteps:2 '" + kase + "' '" + dir + "/out'",
                                dir + "/log.txt");
    const int gpu_code = gpu ? runProgram("-gpu -progress:0 -nsteps:2 -sv:none '" + kase + "' '" + dir + "/out_gpu'",
                                          dir + "/log_gpu.txt")
                             : -1;
    ::setenv("SEASPRING_MEMORY_LIMIT", "1600000", 1);
    const int code_fits = runProgram("-cpu -threads:1 -progress:0 -nsteps:2 -sv:none '" + kase + "' '" + dir +
                                         "/out_fits'",
                                     dir + "/log_fits.txt");
    ::unsetenv("SEASPRING_MEMORY_LIMIT");
    EXPECT_EQ(code, 2);
    EXPECT_HAS(test::readFile(dir + "/log.txt"),
               "Front.h5: the run (3601 particles) beyond its case as read needs about 0.0015");
    EXPECT_HAS(test::readFile(dir + "/log.txt"),
               "GB of memory but only 0.0014 GB are available; generate the case with a larger dp");
    EXPECT_EQ(code_fits, 0) << test::readFile(dir + "/log_fits.txt");
    if (!gpu) GTEST_SKIP() << "the GPU's bound: " << why << " (the CPU's refusal was checked)";
    EXPECT_EQ(gpu_code, 0) << test::readFile(dir + "/log_gpu.txt");
}

// A case too large for the GPU (here: the device capped at 64 KiB by SEASPRING_DEVICE_MEMORY_LIMIT;
// the positions alone take 84 KiB) stops with exit 1 naming the case file, its particles, what
// was asked, held and free, and what to change; run.json says so. Without a GPU: skipped.
TEST(RunRobustness, ACaseTooLargeForTheGpuSaysWhichAndWhatToChange) {
    std::string why;
    if (!solver::makeCudaBackend(0, why)) GTEST_SKIP() << why;
    const std::string dir = test::scratch("robust_gpu_memory");
    const std::string kase = damBreak(dir);
    ::setenv("SEASPRING_DEVICE_MEMORY_LIMIT", "65536", 1);  // the program's environment
    const int code = runProgram("-gpu -progress:0 '" + kase + "' '" + dir + "/out'", dir + "/log.txt");
    ::unsetenv("SEASPRING_DEVICE_MEMORY_LIMIT");
    EXPECT_EQ(code, 1);
    const std::string log = test::readFile(dir + "/log.txt");
    EXPECT_HAS(log, "Front.h5: the run's 3601 particles do not fit the GPU: out of GPU memory: SeaSpring asked for ");
    EXPECT_HAS(log, "free of 0.1 MiB");
    EXPECT_HAS(log, "generate the case with a larger dp, free the GPU, or run on the CPU (-cpu)");
    EXPECT_HAS(log, "(SEASPRING_DEVICE_MEMORY_LIMIT=65536)");
    EXPECT_HAS(test::readFile(dir + "/out/run.json"), "\"exit_code\": 1");
}

// -sv:none on a fluid-only case: at an output nothing reads the state, so the backend's count of
// non-finite particles is the check there (as between outputs) and the state stays on the
// backend. The outputs are still counted and the run is the same; a blow-up is still caught.
TEST(RunRobustness, OutputsWithoutFilesAreCountedAndTheRunIsTheSame) {
    const std::string dir = test::scratch("robust_nofiles");
    const std::string kase = damBreak(dir);
    auto opts = [](bool files) {
        return [files](solver::RunOptions& o) {
            o.nsteps = 40;
            o.tout = 1e-4;  // about one output per step
            o.save_h5 = files;
        };
    };
    const test::SolverRun h5 = test::runCpu(kase, dir + "/h5", 2, opts(true));
    const test::SolverRun none = test::runCpu(kase, dir + "/none", 2, opts(false));
    EXPECT_GT(h5.summary.outputs, 10);
    EXPECT_EQ(none.summary.outputs, h5.summary.outputs);
    EXPECT_EQ(none.summary.state_hash, h5.summary.state_hash);
    EXPECT_FALSE(none.summary.blowup.has_value());
    const test::SolverRun bad = test::runCpu(kase, dir + "/bad", 2, [](solver::RunOptions& o) {
        o.dt_fixed = 0.002;
        o.save_h5 = false;
    });
    ASSERT_TRUE(bad.summary.blowup.has_value());
    EXPECT_FALSE(bad.summary.blowup->particles.empty());
}
