// SeaSpring — MIT licence.
/// \file measure.cpp
/// \brief `seaspring-post measure` (see measure.h).
#include "post/measure.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <ostream>

#include "core/error.h"
#include "core/particle_set.h"
#include "physics/cell_grid.h"
#include "physics/eos_tait.h"
#include "physics/fluid_constants.h"
#include "physics/neighbour_rows.h"
#include "physics/sph_kernels.h"
#include "post/part_series.h"
#include "post/points_file.h"
#include "post/sorted_block.h"

namespace seaspring::post {

using physics::Float4;

namespace {

/// The kernel sums of every point inside the grid (physics::gaugeSampleAt, as the in-run gauges).
template <class Kernel, int kDim>
void sampleAll(const std::vector<Float4>& pts, const std::vector<bool>& outside, const std::vector<std::uint32_t>& cs,
               const std::vector<Float4>& poscell, const std::vector<Float4>& velrho, const physics::FluidConstants& c,
               const physics::CellGrid& g, std::vector<PointSums>& out) {
    // Points are independent: the same sums with any number of threads.
#pragma omp parallel for schedule(dynamic, 256)
    for (long long k = 0; k < static_cast<long long>(pts.size()); ++k) {
        if (outside[k]) continue;
        out[k].g = physics::gaugeSampleAt<Kernel, kDim>(pts[k], cs.data(), poscell.data(), velrho.data(), c, g);
        out[k].rhop = out[k].g.rho;
    }
}

}  // namespace

std::vector<MeasureVar> parseMeasureVars(const std::string& list) {
    std::vector<MeasureVar> v;
    auto add = [&](MeasureVar m) {
        if (std::find(v.begin(), v.end(), m) == v.end()) v.push_back(m);
    };
    std::size_t a = 0;
    while (a <= list.size()) {
        std::size_t b = list.find(',', a);
        if (b == std::string::npos) b = list.size();
        std::string w = list.substr(a, b - a);
        for (char& ch : w) ch = char(std::tolower(static_cast<unsigned char>(ch)));
        if (!w.empty() && w[0] == '+') w.erase(0, 1);  // DualSPHysics' "+press"
        if (w == "press") add(MeasureVar::Press);
        else if (w == "vel") add(MeasureVar::Vel);
        else if (w == "rhop" || w == "rho") add(MeasureVar::Rhop);
        else if (w == "wsum") add(MeasureVar::Wsum);
        else if (w == "all") {
            add(MeasureVar::Press), add(MeasureVar::Vel), add(MeasureVar::Rhop), add(MeasureVar::Wsum);
        } else
            throw Error("-vars: unknown variable '" + w + "' (known: press, vel, rhop, wsum, all)");
        a = b + 1;
    }
    return v;
}

std::vector<PointSums> measurePart(const io::PartData& d, const std::vector<Vec3d>& points, const MeasureGrid& grid,
                                   const std::string& what) {
    const int cell_div = grid.cell_div;
    const io::PartConstants& k = d.constants;
    if (d.mass.empty()) throw Error(what + ": no /mass (a version 1 part file): cannot measure");
    if (!(k.h > 0) || !(k.dp > 0) || !(k.rhop0 > 0) || (k.dimension != 2 && k.dimension != 3))
        throw Error(what + ": attributes h, dp, rhop0, dimension missing or invalid");
    const bool wendland = k.kernel == "Wendland C2";
    if (!wendland && k.kernel != "cubic spline") throw Error(what + ": unknown kernel '" + k.kernel + "'");
    if (cell_div < 1 || cell_div > 4) throw Error("cell_div must be 1..4");
    const int dim = k.dimension;
    std::vector<PointSums> out(points.size());

    // The active fluid.
    std::vector<std::uint32_t> fluid;
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for (std::size_t i = 0; i < d.np(); ++i) {
        if (d.type[i] != std::uint8_t(ParticleType::Fluid) || d.excluded[i] != 0) continue;
        fluid.push_back(std::uint32_t(i));
        for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], d.pos[3 * i + a]), hi[a] = std::max(hi[a], d.pos[3 * i + a]);
    }
    if (fluid.empty()) return out;
    const float massfluid = d.mass[fluid[0]];
    for (std::uint32_t i : fluid)
        if (d.mass[i] != massfluid) throw Error(what + ": fluid particles of different masses (" +
                                                std::to_string(massfluid) + ", " + std::to_string(d.mass[i]) + ")");

    physics::FluidInputs in;
    in.h = k.h, in.dp = k.dp, in.dim = dim, in.rhop0 = k.rhop0, in.massfluid = massfluid, in.b = 1.0, in.cs0 = 1.0;
    physics::FluidConstants c = physics::makeFluidConstants(in);
    if (!(k.b > 0)) throw Error(what + ": attribute b (Tait B) missing or invalid");
    c.cteb = float(k.b);  // as makeFluidConstants: the solver's own float B

    // The grid over the fluid's box grown by 4h (2D: one cell across y).
    const double m = 4.0 * k.h;
    double ymin = dim == 2 ? lo[1] : lo[1] - m, ymax = dim == 2 ? lo[1] : hi[1] + m;
    double xmin = lo[0] - m, zmin = lo[2] - m;
    if (grid.has_min) {
        if (!(grid.min.x <= lo[0] && grid.min.z <= lo[2] && (dim == 2 || grid.min.y <= lo[1])))
            throw Error(what + ": the grid minimum lies above a fluid particle");
        xmin = grid.min.x, zmin = grid.min.z;
        if (dim == 3) ymin = grid.min.y;
    }
    physics::CellGrid g;
    if (!physics::makeCellGrid(xmin, ymin, zmin, hi[0] + m, ymax, hi[2] + m, k.h, cell_div, g, 0.0))
        throw Error(what + ": the fluid's bounding box needs too many cells");
    const double gmax[3] = {hi[0] + m, ymax, hi[2] + m};

    // Sorted by (cell, id) as the solver's sort, PosCell and cell starts.
    SortedParticles sp;
    const std::vector<std::uint32_t> cs = appendSortedBlock(d, fluid, g, dim, sp, lo[1]);
    const std::vector<Float4>& poscell = sp.poscell;
    const std::vector<Float4>& velrho = sp.velrho;

    // The points' PosCell (2D: on the particles' plane); outside the grid: nothing.
    std::vector<Float4> pts(points.size());
    std::vector<bool> outside(points.size());
    for (std::size_t p = 0; p < points.size(); ++p) {
        const physics::Double3 q{points[p].x, dim == 2 ? lo[1] : points[p].y, points[p].z};
        outside[p] = !(q.x >= g.minx && q.x <= gmax[0] && q.z >= g.minz && q.z <= gmax[2] &&
                       (dim == 2 || (q.y >= g.miny && q.y <= gmax[1])));
        std::uint32_t cell;
        pts[p] = physics::makePosCell(g, q, cell);
    }
    if (wendland) {
        if (dim == 2) sampleAll<physics::WendlandKernel, 2>(pts, outside, cs, poscell, velrho, c, g, out);
        else sampleAll<physics::WendlandKernel, 3>(pts, outside, cs, poscell, velrho, c, g, out);
    } else {
        if (dim == 2) sampleAll<physics::CubicKernel, 2>(pts, outside, cs, poscell, velrho, c, g, out);
        else sampleAll<physics::CubicKernel, 3>(pts, outside, cs, poscell, velrho, c, g, out);
    }
    return out;
}

int runMeasure(const MeasureOptions& o, std::ostream& log) {
    if (o.savecsv.empty()) throw Error("-savecsv: no output file given");
    if (o.vars.empty()) throw Error("-vars: no variable");
    if (!(o.kclimit >= 0)) throw Error("-kclimit must be >= 0");
    const std::vector<Vec3d> pts = readPointsFile(o.points);
    const auto parts = listPartFiles(o.dirin, o.first, o.last);
    log << "measure: " << pts.size() << " point(s), " << parts.size() << " part file(s) (" << parts.front().first
        << ".." << parts.back().first << ") in " << o.dirin << "\n";
    AtomicTextFile out(o.savecsv);
    std::FILE* f = out.file();
    int rows = 0;
    std::string h = "part;time";
    for (MeasureVar v : o.vars)
        for (std::size_t p = 0; p < pts.size(); ++p) {
            const std::string k = std::to_string(p);
            switch (v) {
                case MeasureVar::Press: h += ";press_" + k; break;
                case MeasureVar::Vel: h += ";velx_" + k + ";vely_" + k + ";velz_" + k; break;
                case MeasureVar::Rhop: h += ";rhop_" + k; break;
                case MeasureVar::Wsum: h += ";wsum_" + k; break;
            }
        }
    std::fprintf(f, "%s\n", h.c_str());
    for (const auto& [idx, path] : parts) {
        const io::PartData d = io::readPartH5(path);
        const std::vector<PointSums> s = measurePart(d, pts, o.grid, path);
        std::fprintf(f, "%d;%.10g", idx, d.time);
        const double kc = o.kclimit;
        for (MeasureVar v : o.vars)
            for (const PointSums& q : s) {
                const physics::GaugeSample& g = q.g;
                switch (v) {
                    case MeasureVar::Press: std::fprintf(f, ";%.9g", physics::shepard(g.press, g.wsum, kc)); break;
                    case MeasureVar::Vel:
                        std::fprintf(f, ";%.9g;%.9g;%.9g", physics::shepard(g.vx, g.wsum, kc),
                                     physics::shepard(g.vy, g.wsum, kc), physics::shepard(g.vz, g.wsum, kc));
                        break;
                    case MeasureVar::Rhop: std::fprintf(f, ";%.9g", physics::shepard(q.rhop, g.wsum, kc)); break;
                    case MeasureVar::Wsum: std::fprintf(f, ";%.9g", g.wsum); break;
                }
            }
        std::fprintf(f, "\n");
        ++rows;
    }
    out.commit();
    log << "measure: " << rows << " row(s) written to " << o.savecsv << "\n";
    return rows;
}

}  // namespace seaspring::post
