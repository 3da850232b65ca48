// SeaSpring — MIT licence.
/// \file seaspring_main.cpp
/// \brief The solver: `seaspring [options] OUTDIR/NAME OUTDIR` (DualSPHysics habits).
///
/// Exit codes: 0 success, 2 bad input or command line, 1 run-time failure.
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "core/error.h"
#include "core/version.h"
#include "solver/backend.h"
#include "solver/run_options.h"
#include "solver/run_report.h"
#include "solver/simulation.h"
#include "solver/solver_case.h"

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
            backend = solver::makeCudaBackend(opt.gpu_id, why);
            if (!backend && opt.backend == solver::RunOptions::Backend::Gpu) {
                std::cerr << "seaspring: -gpu requested but " << why << "\n";
                return 2;
            }
            if (!backend && !opt.quiet) std::cout << "GPU not used: " << why << "; running on the CPU\n";
        }
        if (!backend) backend = solver::makeCpuBackend(opt.threads);

        if (!opt.quiet) {
            std::cout << "SeaSpring " << kVersion << " - case " << c.name << " (" << c.xml_path << ")\n";
            for (const std::string& l : solver::describeCase(c)) std::cout << "  " << l << "\n";
            std::cout << "  physics: "
                      << solver::describePhysics(c.params, c.constants.dimensions,
                                                       solver::resolveCellDiv(c, opt.cell_div), solver::resolveSkin(opt))
                      << "\n";
            std::cout << "  backend: " << backend->name() << " (" << backend->deviceName() << ")";
            if (backend->name() == "cpu") std::cout << ", " << backend->threads() << " threads";
            std::cout << "\n  TimeMax " << c.params.time_max << " s, TimeOut " << c.params.time_out
                      << " s, output in " << opt.outdir << "\n";
        }
        sim = std::make_unique<solver::Simulation>(c, opt, std::move(backend), std::cout);
    } catch (const std::exception& e) {
        std::cerr << "seaspring: " << e.what() << "\n";
        return 2;
    }
    try {
        const solver::RunSummary s = sim->run();
        const std::string json = (std::filesystem::path(opt.outdir) / "run.json").string();
        solver::writeRunJson(json, s);
        solver::printSummary(std::cout, s);
        if (!opt.quiet) std::cout << "Output: " << opt.outdir << "/parts.xdmf (ParaView), " << json << "\n";
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "seaspring: error: " << e.what() << "\n";
        return 1;
    }
}
