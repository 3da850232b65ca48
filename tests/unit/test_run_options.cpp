// SeaSpring — MIT licence.
/// \file test_run_options.cpp
/// \brief The solver's command line: every option, both spellings, the defaults, every
///        usage error (with the offending argument in the message), the help text and
///        applyOverrides.
#include <gtest/gtest.h>

#include <initializer_list>
#include <string>
#include <vector>

#include "core/error.h"
#include "solver/blowup_check.h"
#include "solver/run_options.h"

using namespace seaspring;
using solver::RunOptions;

namespace {

RunOptions parse(std::initializer_list<const char*> args) {
    std::vector<const char*> argv{"seaspring"};
    argv.insert(argv.end(), args.begin(), args.end());
    return solver::parseRunOptions(int(argv.size()), argv.data());
}

/// Options followed by the two positional arguments.
RunOptions parseWith(std::initializer_list<const char*> options) {
    std::vector<const char*> argv{"seaspring"};
    argv.insert(argv.end(), options.begin(), options.end());
    argv.push_back("out/Case");
    argv.push_back("out/run");
    return solver::parseRunOptions(int(argv.size()), argv.data());
}

/// The usage error for `args` (with the positional arguments added), "" when none.
std::string errorOf(std::initializer_list<const char*> options) {
    try {
        parseWith(options);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

void expectError(std::initializer_list<const char*> options, const std::string& message) {
    std::string args;
    for (const char* a : options) args += std::string(a) + " ";
    const std::string e = errorOf(options);
    EXPECT_EQ(e, message) << "arguments: " << args;
    EXPECT_EQ(e.find('\n'), std::string::npos) << "one line expected: " << e;
}

}  // namespace

TEST(RunOptions, Defaults) {
    const RunOptions o = parse({"out/Case", "out/run"});
    EXPECT_EQ(o.backend, RunOptions::Backend::Auto);
    EXPECT_EQ(o.gpu_id, 0);
    EXPECT_EQ(o.threads, 0);
    EXPECT_EQ(o.case_path, "out/Case");
    EXPECT_EQ(o.outdir, "out/run");
    EXPECT_TRUE(o.save_h5);
    EXPECT_FALSE(o.save_vtk);
    EXPECT_FALSE(o.tmax || o.tout || o.visco || o.visco_bound_factor || o.ddt_value || o.cfl ||
                 o.dt_fixed);
    EXPECT_FALSE(o.step_algorithm || o.verlet_steps || o.kernel || o.visco_treatment || o.ddt);
    EXPECT_FALSE(o.nsteps);
    EXPECT_EQ(o.cell_div, 0);  // auto
    EXPECT_EQ(o.progress_interval, 1.0);
    EXPECT_FALSE(o.quiet);
    EXPECT_FALSE(o.help);
    EXPECT_FALSE(o.version);
}

TEST(RunOptions, Backend) {
    EXPECT_EQ(parseWith({"-gpu"}).backend, RunOptions::Backend::Gpu);
    EXPECT_EQ(parseWith({"-gpu"}).gpu_id, 0);
    const RunOptions g = parseWith({"-gpu:3"});
    EXPECT_EQ(g.backend, RunOptions::Backend::Gpu);
    EXPECT_EQ(g.gpu_id, 3);
    EXPECT_EQ(parseWith({"--gpu=2"}).gpu_id, 2);
    EXPECT_EQ(parseWith({"-cpu"}).backend, RunOptions::Backend::Cpu);
    EXPECT_EQ(parseWith({"-cpu", "-threads:4"}).threads, 4);
    EXPECT_EQ(parseWith({"-threads:1"}).threads, 1);
}

TEST(RunOptions, RunControl) {
    EXPECT_EQ(*parseWith({"-tmax:2.5"}).tmax, 2.5);
    EXPECT_EQ(*parseWith({"-tout:1e-2"}).tout, 0.01);
    EXPECT_EQ(*parseWith({"-nsteps:100"}).nsteps, 100);
    EXPECT_EQ(*parseWith({"-nsteps:0"}).nsteps, 0);
    EXPECT_EQ(*parseWith({"-nsteps:9000000000"}).nsteps, 9000000000LL);
    EXPECT_EQ(parseWith({"-cellmode:full"}).cell_div, 1);
    EXPECT_EQ(parseWith({"-cellmode:h"}).cell_div, 2);
    EXPECT_EQ(parseWith({"-cellmode:third"}).cell_div, 3);
    EXPECT_EQ(parseWith({"-cellmode:quarter"}).cell_div, 4);
    EXPECT_EQ(parseWith({"-cellmode:dp"}).cell_div, 5);
    EXPECT_EQ(parseWith({"-cellmode:auto"}).cell_div, 0);
    EXPECT_FALSE(parseWith({}).skin.has_value());
    EXPECT_EQ(*parseWith({"-skin:0"}).skin, 0.0);
    EXPECT_EQ(*parseWith({"-skin:0.25"}).skin, 0.25);
    EXPECT_EQ(parseWith({}).cell_switch, solver::kCellSwitchFraction);
    EXPECT_EQ(parseWith({"-cellswitch:0"}).cell_switch, 0.0);
    EXPECT_EQ(parseWith({"-cellswitch:0.45"}).cell_switch, 0.45);
    EXPECT_EQ(parseWith({}).pair_lanes, 0);
    EXPECT_EQ(parseWith({"-pairlanes:1"}).pair_lanes, 1);
    EXPECT_EQ(parseWith({"-pairlanes:8"}).pair_lanes, 8);
    EXPECT_EQ(parseWith({"-progress:0"}).progress_interval, 0.0);
    EXPECT_EQ(parseWith({"-progress:2.5"}).progress_interval, 2.5);
    EXPECT_TRUE(parseWith({"-quiet"}).quiet);
}

TEST(RunOptions, Outputs) {
    RunOptions o = parseWith({"-sv:vtk"});
    EXPECT_FALSE(o.save_h5);
    EXPECT_TRUE(o.save_vtk);
    o = parseWith({"-sv:h5,vtk"});
    EXPECT_TRUE(o.save_h5);
    EXPECT_TRUE(o.save_vtk);
    o = parseWith({"-sv:h5"});
    EXPECT_TRUE(o.save_h5);
    EXPECT_FALSE(o.save_vtk);
    o = parseWith({"-sv:none"});
    EXPECT_FALSE(o.save_h5);
    EXPECT_FALSE(o.save_vtk);
    // DualSPHysics' -sv:binx (particle files) is h5 here, info is run.json; each with a note.
    o = parseWith({"-sv:binx,vtk"});
    EXPECT_TRUE(o.save_h5);
    EXPECT_TRUE(o.save_vtk);
    ASSERT_EQ(o.notes.size(), 1u);
    EXPECT_NE(o.notes[0].find("HDF5 part files"), std::string::npos) << o.notes[0];
    o = parseWith({"-sv:binx,info"});
    EXPECT_TRUE(o.save_h5);
    EXPECT_EQ(o.notes.size(), 2u);
    // -svpips and -dirdataout are accepted with a note (-dirdataout:data is the default: none).
    o = parseWith({"-svpips:1", "-dirdataout:data"});
    EXPECT_EQ(o.notes.size(), 1u);
    o = parseWith({"-svpips", "-dirdataout:parts"});
    ASSERT_EQ(o.notes.size(), 2u);
    EXPECT_NE((o.notes[0] + o.notes[1]).find("always written to OUTDIR/data"), std::string::npos);
    // -svres is accepted (DualSPHysics benchmark command lines) and changes nothing.
    for (const char* a : {"-svres", "-svres:0", "-svres:1"}) {
        o = parseWith({a});
        EXPECT_TRUE(o.save_h5) << a;
        EXPECT_FALSE(o.save_vtk) << a;
    }
}

TEST(RunOptions, PhysicsOverrides) {
    EXPECT_EQ(*parseWith({"-symplectic"}).step_algorithm, 2);
    RunOptions o = parseWith({"-verlet"});
    EXPECT_EQ(*o.step_algorithm, 1);
    EXPECT_FALSE(o.verlet_steps);
    o = parseWith({"-verlet:25"});
    EXPECT_EQ(*o.step_algorithm, 1);
    EXPECT_EQ(*o.verlet_steps, 25);
    EXPECT_EQ(*parseWith({"-wendland"}).kernel, 2);
    EXPECT_EQ(*parseWith({"-cubic"}).kernel, 1);
    o = parseWith({"-viscoart:0.05"});
    EXPECT_EQ(*o.visco_treatment, 1);
    EXPECT_EQ(*o.visco, 0.05);
    o = parseWith({"-viscolamsps:1e-6"});
    EXPECT_EQ(*o.visco_treatment, 2);
    EXPECT_EQ(*o.visco, 1e-6);
    o = parseWith({"-viscolam:0"});
    EXPECT_EQ(*o.visco_treatment, 3);
    EXPECT_EQ(*o.visco, 0.0);
    EXPECT_EQ(*parseWith({"-viscoboundfactor:0.5"}).visco_bound_factor, 0.5);
    for (int k = 0; k <= 3; ++k) {
        const std::string a = "-ddt:" + std::to_string(k);
        EXPECT_EQ(*parseWith({a.c_str()}).ddt, k);
    }
    EXPECT_EQ(*parseWith({"-ddtvalue:0.2"}).ddt_value, 0.2);
    EXPECT_EQ(*parseWith({"-cfl:0.3"}).cfl, 0.3);
    EXPECT_EQ(*parseWith({"-cfl:1"}).cfl, 1.0);
    EXPECT_EQ(*parseWith({"-dtfixed:1e-5"}).dt_fixed, 1e-5);
}

TEST(RunOptions, GnuSpellingAndOptionsAnywhere) {
    const RunOptions o =
        parse({"--cpu", "out/Case", "--cfl=0.25", "out/run", "--verlet=10", "--quiet"});
    EXPECT_EQ(o.backend, RunOptions::Backend::Cpu);
    EXPECT_EQ(*o.cfl, 0.25);
    EXPECT_EQ(*o.verlet_steps, 10);
    EXPECT_TRUE(o.quiet);
    EXPECT_EQ(o.case_path, "out/Case");
    EXPECT_EQ(o.outdir, "out/run");
    // After "--" everything is positional.
    const RunOptions p = parse({"-cpu", "--", "-odd/Case", "-run"});
    EXPECT_EQ(p.case_path, "-odd/Case");
    EXPECT_EQ(p.outdir, "-run");
}

TEST(RunOptions, HelpAndVersionWinOverEverythingElse) {
    for (const char* h : {"-h", "-help", "--help"}) {
        EXPECT_TRUE(parse({h}).help) << h;
        EXPECT_TRUE(parse({"-nonsense", h, "-cfl:7"}).help) << h;
    }
    for (const char* v : {"-version", "--version"}) {
        const RunOptions o = parse({v});
        EXPECT_TRUE(o.version) << v;
        EXPECT_FALSE(o.help) << v;
    }
}

TEST(RunOptions, PositionalErrors) {
    auto err = [](std::initializer_list<const char*> args) {
        try {
            parse(args);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    const std::string usage = " (usage: seaspring [options] OUTDIR/NAME OUTDIR)";
    EXPECT_EQ(err({}), "OUTDIR/NAME and OUTDIR are missing" + usage);
    EXPECT_EQ(err({"-cpu"}), "OUTDIR/NAME and OUTDIR are missing" + usage);
    EXPECT_EQ(err({"out/Case"}), "OUTDIR is missing" + usage);
    EXPECT_EQ(err({"a", "b", "c"}), "unexpected argument \"c\"" + usage);
}

TEST(RunOptions, UnknownAndMalformedOptions) {
    expectError({"-foo"}, "unknown option -foo");
    expectError({"-foo:3"}, "unknown option -foo:3");
    expectError({"--bar=1"}, "unknown option --bar=1");
    expectError({"-:3"}, "unknown option -:3");
    expectError({"-mdbc"}, "unknown option -mdbc");
    expectError({"-cpu:1"}, "-cpu:1: -cpu takes no value");
    expectError({"-skin:0.7"}, "-skin:0.7: 0.7 is larger than 0.5 (the skin is a fraction of the cell size)");
    expectError({"-skin:-1"}, "-skin:-1: -1 must be >= 0");
    expectError({"-cellswitch:1.5"}, "-cellswitch:1.5: 1.5 is larger than 1 (the share of the fluid in cells it shares; 0: never switch)");
    expectError({"-cellswitch:-0.1"}, "-cellswitch:-0.1: -0.1 must be >= 0");
    expectError({"-pairlanes:3"}, "-pairlanes:3: 3 is not a power of two (pair lanes: 1, 2, 4 or 8; 0: auto)");
    expectError({"-pairlanes:16"}, "-pairlanes:16: 16 must be 0..8 (pair lanes: 1, 2, 4 or 8; 0: auto)");
    expectError({"-symplectic:1"}, "-symplectic:1: -symplectic takes no value");
    expectError({"-quiet:yes"}, "-quiet:yes: -quiet takes no value");
    expectError({"-cfl"}, "-cfl: needs a value (-cfl:VALUE)");
    expectError({"-tmax"}, "-tmax: needs a value (-tmax:VALUE)");
    expectError({"-cfl:"}, "-cfl:: the value after ':' is missing");
    expectError({"--cfl="}, "--cfl=: the value after '=' is missing");
    expectError({"-gpu:"}, "-gpu:: the value after ':' is missing");
    expectError({"-cfl:0.3", "-cfl:0.4"}, "-cfl:0.4: -cfl is given twice (-cfl:0.3)");
    expectError({"-quiet", "--quiet"}, "--quiet: -quiet is given twice (-quiet)");
}

TEST(RunOptions, ConflictingOptions) {
    expectError({"-cpu", "-gpu"}, "-gpu cannot be combined with -cpu");
    expectError({"-gpu:1", "-cpu"}, "-gpu cannot be combined with -cpu");
    expectError({"-symplectic", "-verlet:30"}, "-verlet cannot be combined with -symplectic");
    expectError({"-cubic", "-wendland"}, "-wendland cannot be combined with -cubic");
    EXPECT_NE(errorOf({"-viscoart:0.1", "-viscolam:1e-6"}).find("cannot be combined"),
              std::string::npos);
    EXPECT_NE(errorOf({"-viscoart:0.1", "-viscolamsps:1e-6"}).find("cannot be combined"),
              std::string::npos);
    EXPECT_NE(errorOf({"-viscolam:1e-6", "-viscolamsps:1e-6"}).find("cannot be combined"),
              std::string::npos);
}

TEST(RunOptions, ValuesMustParseCompletely) {
    expectError({"-cfl:0.2x"}, "-cfl:0.2x: \"0.2x\" is not a number");
    expectError({"-cfl:nan"}, "-cfl:nan: \"nan\" is not a number");
    expectError({"-tmax:inf"}, "-tmax:inf: \"inf\" is not a number");
    expectError({"-tmax:0x10"}, "-tmax:0x10: \"0x10\" is not a number");
    expectError({"-tmax: 1"}, "-tmax: 1: \" 1\" is not a number");
    expectError({"-tmax:1e999"}, "-tmax:1e999: \"1e999\" is out of range");
    expectError({"-tout:1..2"}, "-tout:1..2: \"1..2\" is not a number");
    expectError({"-threads:4.0"}, "-threads:4.0: \"4.0\" is not an integer");
    expectError({"-threads:four"}, "-threads:four: \"four\" is not an integer");
    expectError({"-nsteps:1e3"}, "-nsteps:1e3: \"1e3\" is not an integer");
    expectError({"-nsteps:0x10"}, "-nsteps:0x10: \"0x10\" is not an integer");
    expectError({"-nsteps:99999999999999999999"},
                "-nsteps:99999999999999999999: 99999999999999999999 is too large");
    expectError({"-threads:99999999999"}, "-threads:99999999999: 99999999999 must be 1..1024");
    expectError({"-gpu:1x"}, "-gpu:1x: \"1x\" is not an integer");
    expectError({"-verlet:-"}, "-verlet:-: \"-\" is not an integer");
}

TEST(RunOptions, ValuesMustLieInRange) {
    expectError({"-cfl:0"}, "-cfl:0: 0 must be in (0, 1]");
    expectError({"-cfl:1.0001"}, "-cfl:1.0001: 1.0001 must be in (0, 1]");
    expectError({"-cfl:-0.1"}, "-cfl:-0.1: -0.1 must be in (0, 1]");
    expectError({"-threads:0"}, "-threads:0: 0 must be 1..1024");
    // 100000 threads crashed libgomp (SIGSEGV) before the run started.
    expectError({"-threads:100000"}, "-threads:100000: 100000 must be 1..1024");
    expectError({"-blowupcheck:-1"}, "-blowupcheck:-1: -1 must be >= 0");
    expectError({"-blowupkeep:-2"}, "-blowupkeep:-2: -2 must be >= 0");
    expectError({"-overwrite:1"}, "-overwrite:1: -overwrite takes no value");
    expectError({"-gpu:-1"}, "-gpu:-1: -1 must be >= 0");
    expectError({"-ddt:4"},
                "-ddt:4: 4 must be 0..3 (0 none, 1 Molteni, 2 Fourtakas, 3 Fourtakas full)");
    expectError({"-ddt:-1"},
                "-ddt:-1: -1 must be 0..3 (0 none, 1 Molteni, 2 Fourtakas, 3 Fourtakas full)");
    expectError({"-ddtvalue:-0.1"}, "-ddtvalue:-0.1: -0.1 must be >= 0");
    expectError({"-viscoart:-1"}, "-viscoart:-1: -1 must be >= 0");
    expectError({"-viscolam:-1e-6"}, "-viscolam:-1e-6: -1e-6 must be >= 0");
    expectError({"-viscolamsps:-1"}, "-viscolamsps:-1: -1 must be >= 0");
    expectError({"-viscoboundfactor:-2"}, "-viscoboundfactor:-2: -2 must be >= 0");
    expectError({"-tmax:0"}, "-tmax:0: 0 must be > 0");
    expectError({"-tout:-1"}, "-tout:-1: -1 must be > 0");
    expectError({"-dtfixed:0"}, "-dtfixed:0: 0 must be > 0");
    expectError({"-nsteps:-5"}, "-nsteps:-5: -5 must be >= 0");
    expectError({"-verlet:0"}, "-verlet:0: 0 must be >= 1");
    expectError({"-progress:-1"}, "-progress:-1: -1 must be >= 0");
    expectError({"-svres:2"}, "-svres:2: 2 must be 0..1");
    expectError({"-sv:h5,binx"}, "-sv:h5,binx: h5 and binx are the same output here");
    expectError({"-dirdataout:a/b"}, "-dirdataout:a/b: expected a folder name inside OUTDIR");
    expectError({"-svpips:3"}, "-svpips:3: 3 must be 0..2");
    expectError({"-cellmode:half"},
                "-cellmode:half: \"half\" is not a cell mode (supported: auto, full, h, third, quarter, dp)");
    expectError({"-sv:bi4"}, "-sv:bi4: unknown output \"bi4\" (supported: h5, vtk, none; DualSPHysics' binx and info are taken as h5 and as run.json)");
    expectError({"-sv:h5,"}, "-sv:h5,: unknown output \"\" (supported: h5, vtk, none; DualSPHysics' binx and info are taken as h5 and as run.json)");
    expectError({"-sv:vtk,vtk"}, "-sv:vtk,vtk: \"vtk\" is listed twice");
    expectError({"-sv:none,vtk"}, "-sv:none,vtk: \"none\" cannot be combined with outputs");
}

TEST(RunOptions, HelpListsEveryOption) {
    const std::string help = solver::runOptionsHelp();
    for (const char* o : {"-gpu[:ID]",
                          "-cpu",
                          "-threads:N",
                          "-tmax:T",
                          "-tout:T",
                          "-nsteps:N",
                          "-sv:LIST",
                          "-svres",
                          "-cellmode:auto|full|h",
                          "-progress:S",
                          "-quiet",
                          "-symplectic",
                          "-verlet[:N]",
                          "-wendland",
                          "-cubic",
                          "-viscoart:A",
                          "-viscolam:NU",
                          "-viscolamsps:NU",
                          "-viscoboundfactor:F",
                          "-ddt:K",
                          "-ddtvalue:D",
                          "-cfl:C",
                          "-dtfixed:DT",
                          "-overwrite",
                          "-blowupcheck:N",
                          "-blowupkeep:K",
                          "--help",
                          "-version",
                          "OUTDIR/NAME OUTDIR"})
        EXPECT_NE(help.find(o), std::string::npos) << o << " is not in the help";
    // Every option the help shows is accepted by the parser.
    for (const char* a : {"-gpu",
                          "-cpu",
                          "-threads:2",
                          "-tmax:1",
                          "-tout:1",
                          "-nsteps:1",
                          "-sv:vtk",
                          "-svres",
                          "-cellmode:h",
                          "-progress:1",
                          "-quiet",
                          "-symplectic",
                          "-verlet:2",
                          "-wendland",
                          "-cubic",
                          "-viscoart:1",
                          "-viscolam:1",
                          "-viscolamsps:1",
                          "-viscoboundfactor:1",
                          "-ddt:1",
                          "-ddtvalue:1",
                          "-cfl:1",
                          "-dtfixed:1",
                          "-overwrite",
                          "-blowupcheck:10",
                          "-blowupkeep:3",
                          "-threads:1024"})
        EXPECT_EQ(errorOf({a}), "") << a;
}

TEST(RunOptions, OverwriteAndBlowupCheck) {
    const RunOptions d = parseWith({});
    EXPECT_FALSE(d.overwrite);
    EXPECT_EQ(d.blowup_check_every, 100);
    EXPECT_EQ(d.blowup_keep_every, 0);
    const RunOptions o = parseWith({"-overwrite", "-blowupcheck:1", "-blowupkeep:7"});
    EXPECT_TRUE(o.overwrite);
    EXPECT_EQ(o.blowup_check_every, 1);
    EXPECT_EQ(o.blowup_keep_every, 7);
    // Auto: one kept scan per 2^18 particles of the case.
    EXPECT_EQ(solver::resolveKeepEvery(0, 17384), 1);
    EXPECT_EQ(solver::resolveKeepEvery(0, 262144), 1);
    EXPECT_EQ(solver::resolveKeepEvery(0, 262145), 2);
    EXPECT_EQ(solver::resolveKeepEvery(0, 2633654), 11);
    EXPECT_EQ(solver::resolveKeepEvery(5, 2633654), 5);
}

TEST(RunOptions, ApplyOverridesLeavesUnsetParametersAlone) {
    solver::SolverParameters p;
    p.step_algorithm = 2;
    p.verlet_steps = 33;
    p.kernel = 1;
    p.visco_treatment = 3;
    p.visco = 1e-6;
    p.visco_bound_factor = 0.5;
    p.density_dt = 2;
    p.density_dt_value = 0.3;
    p.cfl_number = 0.15;
    p.dt_fixed = 1e-4;
    p.time_max = 3;
    p.time_out = 0.5;
    const solver::SolverParameters before = p;
    solver::applyOverrides(parseWith({"-cpu", "-quiet", "-sv:none"}), p);
    EXPECT_EQ(p.step_algorithm, before.step_algorithm);
    EXPECT_EQ(p.verlet_steps, before.verlet_steps);
    EXPECT_EQ(p.kernel, before.kernel);
    EXPECT_EQ(p.visco_treatment, before.visco_treatment);
    EXPECT_EQ(p.visco, before.visco);
    EXPECT_EQ(p.visco_bound_factor, before.visco_bound_factor);
    EXPECT_EQ(p.density_dt, before.density_dt);
    EXPECT_EQ(p.density_dt_value, before.density_dt_value);
    EXPECT_EQ(p.cfl_number, before.cfl_number);
    EXPECT_EQ(p.dt_fixed, before.dt_fixed);
    EXPECT_EQ(p.time_max, before.time_max);
    EXPECT_EQ(p.time_out, before.time_out);
}

TEST(RunOptions, ApplyOverridesCommandLineWins) {
    solver::SolverParameters p;
    solver::applyOverrides(
        parseWith({"-verlet:12", "-cubic", "-viscolamsps:2e-6", "-viscoboundfactor:0.25", "-ddt:3",
                   "-ddtvalue:0.05", "-cfl:0.4", "-dtfixed:5e-5", "-tmax:7", "-tout:0.7"}),
        p);
    EXPECT_EQ(p.step_algorithm, 1);
    EXPECT_EQ(p.verlet_steps, 12);
    EXPECT_EQ(p.kernel, 1);
    EXPECT_EQ(p.visco_treatment, 2);
    EXPECT_EQ(p.visco, 2e-6);
    EXPECT_EQ(p.visco_bound_factor, 0.25);
    EXPECT_EQ(p.density_dt, 3);
    EXPECT_EQ(p.density_dt_value, 0.05);
    EXPECT_EQ(p.cfl_number, 0.4);
    EXPECT_EQ(p.dt_fixed, 5e-5);
    EXPECT_EQ(p.time_max, 7.0);
    EXPECT_EQ(p.time_out, 0.7);

    solver::SolverParameters q;
    q.step_algorithm = 1;
    q.kernel = 1;
    q.visco_treatment = 2;
    solver::applyOverrides(parseWith({"-symplectic", "-wendland", "-viscoart:0.02"}), q);
    EXPECT_EQ(q.step_algorithm, 2);
    EXPECT_EQ(q.kernel, 2);
    EXPECT_EQ(q.visco_treatment, 1);
    EXPECT_EQ(q.visco, 0.02);
}

TEST(RunOptions, VcpmOptions) {
    EXPECT_EQ(parseWith({}).solid_substeps, 0);
    EXPECT_FALSE(parseWith({}).vcpm_coupling.has_value());
    EXPECT_EQ(parseWith({"-vcpmsubsteps:4"}).solid_substeps, 4);
    EXPECT_EQ(*parseWith({"-vcpmcoupling:1"}).vcpm_coupling, 1);
    seaspring::solver::SolverParameters p;
    applyOverrides(parseWith({"-vcpmcoupling:1"}), p);
    EXPECT_EQ(p.vcpm_coupling, 1);
    expectError({"-vcpmcoupling:3"}, "-vcpmcoupling:3: 3 must be 1..2");
    EXPECT_FALSE(parseWith({}).vcpm_dt_coef.has_value());
    applyOverrides(parseWith({"-vcpmdtcoef:0.6"}), p);
    EXPECT_EQ(p.vcpm_dt_coef, 0.6);
    expectError({"-vcpmdtcoef:3"}, "-vcpmdtcoef:3: 3 is larger than 2 (as the VcpmDtCoef parameter)");
    expectError({"-vcpmdtcoef:0"}, "-vcpmdtcoef:0: 0 must be > 0");
    expectError({"-vcpmsubsteps:-1"}, "-vcpmsubsteps:-1: -1 must be 0..1000000");
}
