// SeaSpring — MIT licence.
/// \file gencase_main.cpp
/// \brief `gencase CASE_Def.xml OUTDIR/NAME [-dp:VALUE] [-save:vtk]`: DualSPHysics GenCase
///        syntax in, resolved case + particles (+ bonds) out.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "core/error.h"
#include "core/memory_budget.h"
#include "core/version.h"
#include "gencase/case_builder.h"

namespace {

/// DualSPHysics writes options as -name:value; CLI11 wants --name=value.
std::vector<std::string> translateArgs(int argc, char** argv) {
    std::vector<std::string> out;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        if (a.size() > 1 && a[0] == '-' && a[1] != '-' && a.find(':') != std::string::npos) {
            const auto colon = a.find(':');
            a = "--" + a.substr(1, colon - 1) + "=" + a.substr(colon + 1);
        } else if (a == "-h") {
            a = "--help";
        }
        out.push_back(a);
    }
    std::reverse(out.begin(), out.end());  // CLI11's vector overload parses from the back
    return out;
}

/// A -dp value: a finite, normal number > 0 written completely ("0", "1e-400", "abc" are not).
bool parseDp(const std::string& text, double& dp) {
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(v) || !(v > 0)) return false;
    dp = v;
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"SeaSpring gencase " + std::string(seaspring::kVersion) +
                 ": builds particles, bonds and the resolved case from a DualSPHysics-style case "
                 "definition.\nOptions may be written DualSPHysics-style (-dp:0.01 -save:vtk)."};
    seaspring::gencase::GencaseOptions opt;
    std::string save;
    app.add_option("definition", opt.definition, "case definition CASE_Def.xml (.xml optional)")->required();
    app.add_option("output", opt.output_base, "OUTDIR/NAME: writes NAME.xml, NAME.h5 (NAME.vtu)")->required();
    std::string dp_text;
    app.add_option("--dp", dp_text, "override the particle spacing dp [m] (a number > 0)");
    app.add_option("--save", save, "extra outputs: vtk (ParaView preview NAME.vtu)")
        ->check(CLI::IsMember({"vtk", "all", "none"}));
    app.add_flag("--verbose,-v", opt.verbose, "print every drawing command with its point count");
    app.set_version_flag("--version", std::string(seaspring::kVersion));
    try {
        std::vector<std::string> args = translateArgs(argc, argv);
        app.parse(args);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    opt.save_vtk = save == "vtk" || save == "all";
    if (!dp_text.empty() && !parseDp(dp_text, opt.dp_override)) {
        std::cerr << "gencase error: -dp:" << dp_text << ": must be a number > 0 (metres), written in full\n";
        return 2;
    }
    const auto t0 = std::chrono::steady_clock::now();
    std::cout << "SeaSpring gencase " << seaspring::kVersion << "\n";
    seaspring::gencase::CaseBuilder builder(opt, std::cout);
    try {
        builder.build();
        builder.checkForSolver();
    } catch (const seaspring::Error& e) {  // the input
        std::cerr << "gencase error: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "gencase error: " << e.what() << "\n";
        return 3;
    }
    try {
        builder.write();
    } catch (const std::exception& e) {  // the outputs: a file or folder that cannot be written
        std::cerr << "gencase error: " << e.what() << "\n";
        return 3;
    }
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("Finished in %.2f s (host memory peak %.1f MiB)\n", s,
                double(seaspring::peakHostMemory()) / (1024.0 * 1024.0));
    return 0;
}
