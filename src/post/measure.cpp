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
        else if (w == "height") add(MeasureVar::Height);
        else if (w == "all") {
            add(MeasureVar::Press), add(MeasureVar::Vel), add(MeasureVar::Rhop), add(MeasureVar::Wsum);
        } else
            throw Error("-vars: unknown variable '" + w + "' (known: press, vel, rhop, wsum, height, all)");
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
    if (cell_div < 1 || cell_div > physics::kCellDivSpacing) throw Error("cell_div must be 1..5 (5: cells of dp)");
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
    if (!physics::makeCellGrid(xmin, ymin, zmin, hi[0] + m, ymax, hi[2] + m, k.h, cell_div, g, 0.0, k.dp))
        throw Error(what + ": the fluid's bounding box needs too many cells" +
                    (cell_div == physics::kCellDivSpacing ? " (or cells of dp need dp <= 2h <= 8 dp)" : ""));
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
                case MeasureVar::Height: h += ";height_" + k; break;
            }
        }
    std::fprintf(f, "%s\n", h.c_str());
    const bool height = std::find(o.vars.begin(), o.vars.end(), MeasureVar::Height) != o.vars.end();
    for (const auto& [idx, path] : parts) {
        const io::PartData d = io::readPartH5(path);
        // height: a vertical SWL line above each point (its points after the others, one call).
        std::vector<Vec3d> all = pts;
        std::vector<physics::SwlLine> lines;
        double masslimit = 0;
        if (height) {
            double ztop = -1e300, mfluid = 0;
            for (std::size_t i = 0; i < d.type.size(); ++i)
                if (d.type[i] == std::uint8_t(ParticleType::Fluid) && d.excluded[i] == 0) {
                    ztop = std::max(ztop, d.pos[3 * i + 2]);
                    if (!d.mass.empty()) mfluid = d.mass[i];
                }
            if (!(mfluid > 0)) throw Error(path + ": no fluid mass (/mass): height needs a format 2 part file");
            const double coef = o.height_coef > 0 ? o.height_coef : physics::swlMassLimitCoef(d.constants.dimension);
            masslimit = coef * mfluid;
            ztop += 2.0 * d.constants.h;
            const double pointdp = 0.5 * d.constants.dp;
            for (const Vec3d& p : pts) {
                // Up to a whole number of dp/2 above the point, so that the spacing is dp/2 as an
                // SWL gauge's line from the point with pointdp dp/2 that reaches above the water.
                const physics::Double3 p0{p.x, p.y, p.z};
                const double top = p.z + std::ceil((ztop - p.z) / pointdp) * pointdp;
                const physics::SwlLine l = p.z < ztop ? physics::swlLine(p0, physics::Double3{p.x, p.y, top}, pointdp)
                                                      : physics::SwlLine{p0, physics::Double3{0, 0, 0}, 0};
                lines.push_back(l);
                for (std::uint32_t k = 0; k < l.count; ++k) {
                    const physics::Double3 q = l.point(k);
                    all.push_back(Vec3d{q.x, q.y, q.z});
                }
            }
        }
        const std::vector<PointSums> s = measurePart(d, all, o.grid, path);
        std::vector<double> surface(pts.size(), 0.0);
        for (std::size_t p = 0, at = pts.size(); p < lines.size(); at += lines[p].count, ++p) {
            std::vector<double> mass(lines[p].count);
            for (std::uint32_t k = 0; k < lines[p].count; ++k) mass[k] = s[at + k].g.mass;
            surface[p] = lines[p].count == 0 ? pts[p].z
                                             : physics::swlSurface(mass.data(), int(lines[p].count), lines[p].point0,
                                                                   lines[p].dir, masslimit).z;
        }
        std::fprintf(f, "%d;%.10g", idx, d.time);
        const double kc = o.kclimit;
        for (MeasureVar v : o.vars)
            for (std::size_t p = 0; p < pts.size(); ++p) {
                const PointSums& q = s[p];
                const physics::GaugeSample& g = q.g;
                switch (v) {
                    case MeasureVar::Press: std::fprintf(f, ";%.9g", physics::shepard(g.press, g.wsum, kc)); break;
                    case MeasureVar::Vel:
                        std::fprintf(f, ";%.9g;%.9g;%.9g", physics::shepard(g.vx, g.wsum, kc),
                                     physics::shepard(g.vy, g.wsum, kc), physics::shepard(g.vz, g.wsum, kc));
                        break;
                    case MeasureVar::Rhop: std::fprintf(f, ";%.9g", physics::shepard(q.rhop, g.wsum, kc)); break;
                    case MeasureVar::Wsum: std::fprintf(f, ";%.9g", g.wsum); break;
                    case MeasureVar::Height: std::fprintf(f, ";%.9g", surface[p]); break;
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
