// SeaSpring — MIT licence.
/// \file seaspring_post_main.cpp
/// \brief `seaspring-post measure -dirin OUTDIR -points FILE [-first N] [-last N]
///        [-vars press,vel,rhop,wsum] [-kclimit 0.5] -savecsv OUT.csv`: post-processing of a
///        run's part files (DualSPHysics' MeasureTool spellings; docs/post.md).
#include <algorithm>
#include <cctype>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "core/error.h"
#include "core/version.h"
#include "post/measure.h"

namespace {

/// DualSPHysics writes options as -name value or -name:value; CLI11 wants --name value or
/// --name=value. Negative numbers ("-1") are left alone.
std::vector<std::string> translateArgs(int argc, char** argv) {
    std::vector<std::string> out;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        if (a == "-h") {
            a = "--help";
        } else if (a.size() > 2 && a[0] == '-' && std::isalpha(static_cast<unsigned char>(a[1]))) {
            const auto colon = a.find(':');
            a = colon == std::string::npos ? "--" + a.substr(1) : "--" + a.substr(1, colon - 1) + "=" + a.substr(colon + 1);
        }
        out.push_back(a);
    }
    std::reverse(out.begin(), out.end());  // CLI11's vector overload parses from the back
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"SeaSpring post-processing " + std::string(seaspring::kVersion) +
                 ": measurements from a run's part files.\nOptions may be written DualSPHysics-style "
                 "(-dirin OUT -first:2)."};
    app.require_subcommand(1);
    app.set_version_flag("--version", std::string(seaspring::kVersion));
    seaspring::post::MeasureOptions mo;
    std::string vars = "press";
    CLI::App* measure = app.add_subcommand(
        "measure",
        "the in-run gauges' kernel sums (Shepard-corrected) at the points of a points file, for every part "
        "file: one CSV row per part (MeasureTool)");
    measure->add_option("--dirin", mo.dirin, "the run's OUTDIR (reads OUTDIR/data/part_NNNN.h5)")->required();
    measure->add_option("--points", mo.points, "points file: POINTS then x y z lines, or POINTSLIST")->required();
    measure->add_option("--first", mo.first, "first part number (default: the first file)")->check(CLI::NonNegativeNumber);
    measure->add_option("--last", mo.last, "last part number (default: the last file)")->check(CLI::NonNegativeNumber);
    measure->add_option("--vars", vars, "press, vel, rhop, wsum or all, comma-separated (default press)");
    measure->add_option("--kclimit", mo.kclimit, "Shepard limit: wsum below it gives 0 (default 0.5)");
    std::vector<double> gridmin;
    measure->add_option("--celldiv", mo.grid.cell_div, "cells of 2h/N (1..4; default 1)")->check(CLI::Range(1, 4));
    measure->add_option("--gridmin", gridmin,
                        "x,y,z: the cell grid's origin (default: the fluid's box less 4h); the solver's domain "
                        "minimum and -celldiv of its cell size give its sums bit for bit")
        ->expected(3)
        ->delimiter(',');
    measure->add_option("--savecsv", mo.savecsv, "output CSV (';'-separated)")->required();
    try {
        std::vector<std::string> args = translateArgs(argc, argv);
        app.parse(args);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    try {
        if (measure->parsed()) {
            mo.vars = seaspring::post::parseMeasureVars(vars);
            if (!gridmin.empty()) {
                mo.grid.has_min = true;
                mo.grid.min = seaspring::Vec3d{gridmin[0], gridmin[1], gridmin[2]};
            }
            seaspring::post::runMeasure(mo, std::cout);
        }
    } catch (const seaspring::Error& e) {
        std::cerr << "seaspring-post error: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "seaspring-post error: " << e.what() << "\n";
        return 3;
    }
    return 0;
}
