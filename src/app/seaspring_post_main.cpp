// SeaSpring — MIT licence.
/// \file seaspring_post_main.cpp
/// \brief `seaspring-post SUBCOMMAND -dirin OUTDIR ...`: post-processing of a run's part files,
///        with DualSPHysics' tools' spellings (docs/post.md): measure (MeasureTool), forces
///        (ComputeForces), flow (FlowTool), isosurface (IsoSurface).
#include <algorithm>
#include <cctype>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "core/error.h"
#include "core/version.h"
#include "post/flow.h"
#include "post/forces.h"
#include "post/isosurface.h"
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

/// "21", "21,22", "11-13" (DualSPHysics' -onlymk values) -> the numbers, in order.
std::vector<int> parseIntList(const std::string& text, const std::string& option) {
    std::vector<int> v;
    std::size_t a = 0;
    auto number = [&](const std::string& w) {
        std::size_t used = 0;
        int x = -1;
        try {
            x = std::stoi(w, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (w.empty() || used != w.size() || x < 0)
            throw seaspring::Error(option + ": '" + w + "' is not a non-negative integer (in '" + text + "')");
        return x;
    };
    while (a <= text.size()) {
        std::size_t b = text.find(',', a);
        if (b == std::string::npos) b = text.size();
        const std::string w = text.substr(a, b - a);
        const std::size_t dash = w.find('-', 1);
        if (dash == std::string::npos) {
            v.push_back(number(w));
        } else {
            const int lo = number(w.substr(0, dash)), hi = number(w.substr(dash + 1));
            if (hi < lo) throw seaspring::Error(option + ": empty range '" + w + "'");
            for (int x = lo; x <= hi; ++x) v.push_back(x);
        }
        a = b + 1;
    }
    return v;
}

/// The options every subcommand reads its part files with: --dirin (required), --first, --last.
void addPartRange(CLI::App* sub, std::string& dirin, int& first, int& last) {
    sub->add_option("--dirin", dirin, "the run's OUTDIR (reads OUTDIR/data/part_NNNN.h5)")->required();
    sub->add_option("--first", first, "first part number (default: the first file)")->check(CLI::NonNegativeNumber);
    sub->add_option("--last", last, "last part number (default: the last file)")->check(CLI::NonNegativeNumber);
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
    addPartRange(measure, mo.dirin, mo.first, mo.last);
    measure->add_option("--points", mo.points, "points file: POINTS then x y z lines, or POINTSLIST")->required();
    measure->add_option("--vars", vars, "press, vel, rhop, wsum, height or all, comma-separated (default press)");
    std::vector<double> height;
    CLI::Option* height_opt =
        measure->add_option("--height", height,
                            "[C] (DualSPHysics' -height[:C]): add the free-surface height above each point (the SWL "
                            "gauge's method, mass limit C times the fluid particle's mass; default 0.5 in 3D, 0.4 in 2D)")
            ->expected(0, 1);
    measure->add_option("--kclimit", mo.kclimit, "Shepard limit: wsum below it gives 0 (default 0.5)");
    std::vector<double> gridmin;
    measure->add_option("--celldiv", mo.grid.cell_div, "cells of 2h/N (1..4; 5: cells of dp; default 1)")->check(CLI::Range(1, 5));
    measure->add_option("--gridmin", gridmin,
                        "x,y,z: the cell grid's origin (default: the fluid's box less 4h); the solver's domain "
                        "minimum and -celldiv of its cell size give its sums bit for bit")
        ->expected(3)
        ->delimiter(',');
    measure->add_option("--savecsv", mo.savecsv, "output CSV (';'-separated)")->required();

    seaspring::post::ForcesOptions fo;
    std::string onlymk, mkbound;
    double viscoart = -1, viscolam = -1;
    CLI::App* forces = app.add_subcommand(
        "forces",
        "the fluid's force on boundary or solid MKs (the in-run force gauge's function), one CSV row per part "
        "file (ComputeForces)");
    addPartRange(forces, fo.dirin, fo.first, fo.last);
    forces->add_option("--filexml", fo.filexml, "the resolved case the run read (NAME.xml written by gencase)")->required();
    CLI::Option* omk = forces->add_option("--onlymk", onlymk, "absolute MKs (mkbound + mkboundfirst), e.g. 21 or 11,21-23");
    forces->add_option("--mkbound", mkbound, "or local mkbound numbers, e.g. 10")->excludes(omk);
    forces->add_option("--celldiv", fo.cell_div, "cells of 2h/N as the run's -cellmode (1..4, 5 for -cellmode:dp; default: as -cellmode:auto)")
        ->check(CLI::Range(1, 5));
    CLI::Option* art = forces->add_option("--viscoart", viscoart, "artificial viscosity alpha instead of the case's");
    forces->add_option("--viscolam", viscolam, "laminar viscosity nu [m^2/s] instead of the case's")->excludes(art);
    forces->add_option("--viscoboundfactor", fo.visco_bound_factor, "instead of the case's ViscoBoundFactor");
    forces->add_option("--savecsv", fo.savecsv, "output CSV (';'-separated)")->required();

    seaspring::post::FlowOptions wo;
    CLI::App* flow = app.add_subcommand(
        "flow", "fluid mass and volume crossing a plane section between consecutive part files, one CSV row per "
                "part file after the first (FlowTool)");
    addPartRange(flow, wo.dirin, wo.first, wo.last);
    flow->add_option("--plane", wo.plane, "x,y,z,nx,ny,nz: a point of the plane and its normal (the positive direction)")
        ->required()
        ->expected(1, 6)
        ->delimiter(',');
    flow->add_option("--limits", wo.limits, "xmin,ymin,zmin,xmax,ymax,zmax: only crossings inside this box (default: the "
                                            "whole plane)")
        ->expected(1, 6)
        ->delimiter(',');
    flow->add_option("--savecsv", wo.savecsv, "output CSV (';'-separated)")->required();

    seaspring::post::IsosurfaceOptions io;
    CLI::App* iso = app.add_subcommand(
        "isosurface", "the free surface of every part file: the gauges' kernel sums on a grid (PREFIX_NNNN.vti), "
                      "contoured by VTK under pvpython into VTK polydata (PREFIX_NNNN.vtp) (IsoSurface)");
    addPartRange(iso, io.dirin, io.first, io.last);
    iso->add_option("--var", io.var, "the field contoured: mass (sum V W m, default) or wsum (sum V W)");
    iso->add_option("--level", io.level, "contour value (default: 0.5 m_fluid in 3D, 0.4 m_fluid in 2D; 0.5 for wsum)")
        ->check(CLI::NonNegativeNumber);
    CLI::Option* dn = iso->add_option("--distnode", io.distnode, "grid node spacing [m] (default: dp)")
                          ->check(CLI::PositiveNumber);
    iso->add_option("--distnode_dp", io.distnode_dp, "grid node spacing in units of dp (default 1)")
        ->check(CLI::PositiveNumber)
        ->excludes(dn);
    iso->add_option("--limits", io.limits, "xmin,ymin,zmin,xmax,ymax,zmax: the grid's box (default: the fluid's box "
                                           "grown by 2h and a node)")
        ->expected(1, 6)
        ->delimiter(',');
    iso->add_option("--savevtk", io.savevtk, "output prefix: PREFIX_NNNN.vti (grid) and PREFIX_NNNN.vtp (surface)")
        ->required();
    iso->add_flag("--gridonly", io.gridonly, "write the grids only (no pvpython needed)");
    iso->add_option("--pvpython", io.pvpython, "ParaView's pvpython (default: $SEASPRING_PVPYTHON, else the PATH)");
    iso->add_option("--script", io.script, "the contouring script (default: the sources' tools/isosurface.py)");
    try {
        std::vector<std::string> args = translateArgs(argc, argv);
        app.parse(args);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    try {
        if (measure->parsed()) {
            mo.vars = seaspring::post::parseMeasureVars(height_opt->count() > 0 ? vars + ",height" : vars);
            if (!height.empty()) {
                if (!(height[0] > 0)) throw seaspring::Error("-height: the mass limit coefficient must be > 0");
                mo.height_coef = height[0];
            }
            if (!gridmin.empty()) {
                mo.grid.has_min = true;
                mo.grid.min = seaspring::Vec3d{gridmin[0], gridmin[1], gridmin[2]};
            }
            seaspring::post::runMeasure(mo, std::cout);
        } else if (forces->parsed()) {
            if (!onlymk.empty()) fo.onlymk = parseIntList(onlymk, "-onlymk");
            if (!mkbound.empty()) fo.mkbound = parseIntList(mkbound, "-mkbound");
            if (viscoart >= 0) fo.visco_treatment = 1, fo.visco = viscoart;
            if (viscolam >= 0) fo.visco_treatment = 3, fo.visco = viscolam;
            seaspring::post::runForces(fo, std::cout);
        } else if (flow->parsed()) {
            seaspring::post::runFlow(wo, std::cout);
        } else if (iso->parsed()) {
            seaspring::post::runIsosurface(io, std::cout);
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
