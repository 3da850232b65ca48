// SeaSpring — MIT licence.
/// \file gencase_main.cpp
/// \brief `gencase CASE_Def.xml OUTDIR/NAME [-dp:VALUE] [-save:vtk]`: DualSPHysics GenCase
///        syntax in, resolved case + particles (+ bonds) out.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "core/error.h"
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

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"SeaSpring gencase " + std::string(seaspring::kVersion) +
                 ": builds particles, bonds and the resolved case from a DualSPHysics-style case "
                 "definition.\nOptions may be written DualSPHysics-style (-dp:0.01 -save:vtk)."};
    seaspring::gencase::GencaseOptions opt;
    std::string save;
    app.add_option("definition", opt.definition, "case definition CASE_Def.xml (.xml optional)")->required();
    app.add_option("output", opt.output_base, "OUTDIR/NAME: writes NAME.xml, NAME.h5 (NAME.vtu)")->required();
    app.add_option("--dp", opt.dp_override, "override the particle spacing dp [m]");
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
    const auto t0 = std::chrono::steady_clock::now();
    try {
        std::cout << "SeaSpring gencase " << seaspring::kVersion << "\n";
        seaspring::gencase::CaseBuilder builder(opt, std::cout);
        builder.build();
        builder.write();
    } catch (const seaspring::Error& e) {
        std::cerr << "gencase error: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "gencase error: " << e.what() << "\n";
        return 3;
    }
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("Finished in %.2f s\n", s);
    return 0;
}
