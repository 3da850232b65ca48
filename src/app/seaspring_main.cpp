// SeaSpring — MIT licence.
/// \file seaspring_main.cpp
/// \brief The solver: `seaspring [options] OUTDIR/NAME OUTDIR` (DualSPHysics habits).
///
/// Exit codes: 0 success, 2 bad input or command line (an OUTDIR holding an earlier run without
/// -overwrite included), 1 run-time failure (a blow-up or another error; run.json says which),
/// 128 + N stopped by signal N (130 SIGINT, 143 SIGTERM). Everything printed once OUTDIR is known
/// (the banner, the run's lines, the summary, errors) also goes to OUTDIR/Run.out
/// (solver/run_log.h).
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/version.h"
#include "solver/backend.h"
#include "solver/output_dir.h"
#include "solver/run_options.h"
#include "solver/run_log.h"
#include "solver/run_report.h"
#include "solver/simulation.h"
#include "solver/solver_case.h"
#include "solver/stop_signal.h"

using namespace seaspring;

int main(int argc, char** argv) {
    solver::RunOptions opt;
    try {
        opt = solver::parseRunOptions(argc, argv);
    } catch (const Error& e) {
        std::cerr << "seaspring: " << e.what() << "\n(seaspring --help lists the options)\n";
        return 2;
    }
    if (opt.help) {
        std::cout << solver::runOptionsHelp();
        return 0;
    }
    if (opt.version) {
        std::cout << "seaspring " << kVersion << "\n";
        return 0;
    }
    std::unique_ptr<solver::RunLog> run_log;
    std::vector<std::string> cleared;
    try {
        // -restart from OUTDIR/restart.h5 continues that run's files in OUTDIR; a restart into
        // another folder starts its outputs there like a new run.
        const bool continuing =
            !opt.restart_file.empty() && solver::restartContinuesIn(opt.restart_file, opt.outdir);
        if (!continuing) cleared = solver::prepareOutputDir(opt.outdir, opt.overwrite);
        run_log = std::make_unique<solver::RunLog>(opt.outdir, std::cout, continuing);
    } catch (const std::exception& e) {
        std::cerr << "seaspring: " << e.what() << "\n";
        return 2;
    }
    std::ostream& log = run_log->out();
    solver::installStopSignals();
    for (const std::string& n : opt.notes) log << "note: " << n << "\n";  // DualSPHysics options taken as aliases
    if (!cleared.empty() && !opt.quiet) {
        log << "-overwrite: removed the earlier run's";
        for (const std::string& f : cleared) log << " " << f;
        log << " from " << opt.outdir << "\n";
    }
    std::unique_ptr<solver::Simulation> sim;
    solver::SolverCase c;
    try {
        c = solver::loadSolverCase(opt.case_path);
        solver::applyOverrides(opt, c.params);
        if (opt.tmax) c.params.time_max = *opt.tmax;
        if (opt.tout) c.params.time_out = *opt.tout;

        std::unique_ptr<solver::Backend> backend;
        std::string why;
        if (opt.backend != solver::RunOptions::Backend::Cpu) {
            backend = solver::makeCudaBackend(opt.gpu_id, why, opt.threads);
            if (!backend && opt.backend == solver::RunOptions::Backend::Gpu) {
                run_log->error(std::cerr, "seaspring: -gpu requested but " + why + "\n");
                return 2;
            }
            if (!backend && !opt.quiet) log << "GPU not used: " << why << "; running on the CPU\n";
        }
        if (!backend) backend = solver::makeCpuBackend(opt.threads);

        if (!opt.quiet) {
            log << "SeaSpring " << kVersion << " - case " << c.name << " (" << c.xml_path << ")\n";
            for (const std::string& l : solver::describeCase(c)) log << "  " << l << "\n";
            log << "  physics: "
                << solver::describePhysics(c.params, c.constants.dimensions, solver::resolveCellDiv(c, opt.cell_div),
                                           solver::resolveSkin(c, opt), solver::resolvePairLanes(c, opt.pair_lanes),
                                           solver::resolveCellSwitch(c, opt.cell_div, opt.cell_switch))
                << "\n";
            log << "  backend: " << backend->name() << " (" << backend->deviceName() << ")";
            if (backend->name() == "cpu") log << ", " << backend->threads() << " threads";
            log << "\n  TimeMax " << c.params.time_max << " s, TimeOut " << c.params.time_out << " s, output in "
                << opt.outdir << "\n";
        }
        sim = std::make_unique<solver::Simulation>(c, opt, std::move(backend), log);
    } catch (const std::exception& e) {
        run_log->error(std::cerr, std::string("seaspring: ") + e.what() + "\n");
        return 2;
    }
    const std::string json = (std::filesystem::path(opt.outdir) / "run.json").string();
    try {
        const solver::RunSummary s = sim->run();
        solver::writeRunJson(json, s);
        solver::printSummary(log, s);
        if (!opt.quiet)
            log << "Output: " << opt.outdir << "/parts.xdmf (ParaView), " << json << ", " << run_log->path() << "\n";
        if (s.blowup) run_log->error(std::cerr, "seaspring: error: " + solver::describeBlowup(*s.blowup) + "\n");
        log.flush();
        return s.exit_code;
    } catch (const std::exception& e) {
        run_log->error(std::cerr, std::string("seaspring: error: ") + e.what() + "\n");
        solver::RunSummary s = sim->summary();  // what the run had reached
        s.stop_reason = std::string("error: ") + e.what();
        s.exit_code = 1;
        try {
            solver::writeRunJson(json, s);
        } catch (const std::exception& e2) {
            run_log->error(std::cerr, std::string("seaspring: ") + e2.what() + "\n");
        }
        return 1;
    }
}
