// SeaSpring — MIT licence.
/// \file isosurface.cpp
/// \brief `seaspring-post isosurface` (see isosurface.h).
#include "post/isosurface.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <ostream>

#include <sys/wait.h>

#include "core/error.h"
#include "core/particle_set.h"
#include "physics/gauges.h"
#include "post/measure.h"
#include "post/part_series.h"

#ifndef SEASPRING_TOOLS_DIR
#define SEASPRING_TOOLS_DIR "tools"
#endif

namespace seaspring::post {

namespace fs = std::filesystem;

namespace {

std::string quote(const std::string& s) {
    std::string q = "'";
    for (char ch : s) q += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
    return q + "'";
}

std::string scriptPath(const IsosurfaceOptions& o) {
    if (!o.script.empty()) return o.script;
    const char* env = std::getenv("SEASPRING_TOOLS");
    return (fs::path(env && *env ? env : SEASPRING_TOOLS_DIR) / "isosurface.py").string();
}

}  // namespace

double isosurfaceLevel(const IsosurfaceOptions& o, double massfluid, int dim) {
    if (o.level >= 0) return o.level;
    return o.var == "wsum" ? 0.5 : physics::swlMassLimitCoef(dim) * massfluid;
}

IsoGrid isosurfaceGrid(const io::PartData& d, const IsosurfaceOptions& o, const std::string& what) {
    IsoGrid r;
    const io::PartConstants& k = d.constants;
    if (!(k.h > 0) || !(k.dp > 0) || (k.dimension != 2 && k.dimension != 3))
        throw Error(what + ": attributes h, dp, dimension missing or invalid");
    r.dim = k.dimension;
    const double step = o.distnode > 0 ? o.distnode : o.distnode_dp * k.dp;
    if (!(step > 0)) throw Error("-distnode / -distnode_dp must be > 0");
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for (std::size_t i = 0; i < d.np(); ++i) {
        if (d.type[i] != std::uint8_t(ParticleType::Fluid) || d.excluded[i] != 0) continue;
        if (r.massfluid == 0 && !d.mass.empty()) r.massfluid = d.mass[i];
        for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], d.pos[3 * i + a]), hi[a] = std::max(hi[a], d.pos[3 * i + a]);
    }
    const double yplane = lo[1] <= hi[1] ? lo[1] : 0.0;  // 2D: the particles' plane
    if (!o.limits.empty()) {
        for (int a = 0; a < 3; ++a) lo[a] = o.limits[a], hi[a] = o.limits[a + 3];
    } else if (lo[0] <= hi[0]) {
        const double m = 2.0 * k.h + step;  // the kernel's reach and one node: the surface closes
        for (int a = 0; a < 3; ++a) lo[a] -= m, hi[a] += m;
    } else {
        for (int a = 0; a < 3; ++a) lo[a] = hi[a] = 0;  // no fluid: one node, zero
    }
    io::ImageGrid& g = r.grid;
    double nodes = 1;
    for (int a = 0; a < 3; ++a) {
        const bool flat = r.dim == 2 && a == 1;  // 2D: the particles' plane only
        g.origin[a] = flat ? yplane : lo[a];
        g.spacing[a] = step;
        g.dims[a] = flat ? 1 : int(std::floor((hi[a] - lo[a]) / step + 1e-9)) + 1;
        nodes *= g.dims[a];
    }
    if (nodes > double(1u << 28))
        throw Error(what + ": the grid needs " + std::to_string(nodes) + " nodes (more than 2^28): use a larger -distnode or -limits");
    const std::size_t n = g.nodes();
    std::vector<Vec3d> pts(n);
    for (int z = 0, q = 0; z < g.dims[2]; ++z)
        for (int y = 0; y < g.dims[1]; ++y)
            for (int x = 0; x < g.dims[0]; ++x, ++q)
                pts[std::size_t(q)] = Vec3d{g.origin[0] + x * step, g.origin[1] + y * step, g.origin[2] + z * step};
    std::vector<float> mass(n, 0.f), wsum(n, 0.f);
    if (r.massfluid > 0) {
        const std::vector<PointSums> s = measurePart(d, pts, MeasureGrid{}, what);
        for (std::size_t q = 0; q < n; ++q) mass[q] = float(s[q].g.mass), wsum[q] = float(s[q].g.wsum);
    }
    r.arrays = {{"mass", std::move(mass)}, {"wsum", std::move(wsum)}};
    return r;
}

std::string findPvpython(const IsosurfaceOptions& o) {
    if (!o.pvpython.empty()) return o.pvpython;
    const char* env = std::getenv("SEASPRING_PVPYTHON");
    if (env && *env) return env;
    const char* path = std::getenv("PATH");
    std::string p = path ? path : "";
    std::size_t a = 0;
    while (a <= p.size()) {
        std::size_t b = p.find(':', a);
        if (b == std::string::npos) b = p.size();
        const fs::path cand = fs::path(p.substr(a, b - a).empty() ? "." : p.substr(a, b - a)) / "pvpython";
        std::error_code ec;
        if (fs::is_regular_file(cand, ec)) return cand.string();
        a = b + 1;
    }
    return "";
}

int runIsosurface(const IsosurfaceOptions& o, std::ostream& log) {
    if (o.var != "mass" && o.var != "wsum") throw Error("-var: '" + o.var + "' (known: mass, wsum)");
    if (o.savevtk.empty()) throw Error("-savevtk: no output prefix given");
    if (!o.limits.empty() && o.limits.size() != 6)
        throw Error("-limits: expected 6 numbers xmin,ymin,zmin,xmax,ymax,zmax, found " + std::to_string(o.limits.size()));
    for (std::size_t a = 0; a < 3 && !o.limits.empty(); ++a)
        if (!(o.limits[a] <= o.limits[a + 3])) throw Error("-limits: a minimum is above its maximum");
    std::string pv, script;
    if (!o.gridonly) {
        pv = findPvpython(o);
        if (pv.empty())
            throw Error("pvpython (ParaView) not found: the surfaces are contoured by VTK under pvpython. Install ParaView "
                        "(Debian: paraview python3-paraview), set SEASPRING_PVPYTHON or -pvpython, or use -gridonly to "
                        "write the grids (.vti) only and contour them elsewhere with tools/isosurface.py");
        script = scriptPath(o);
        std::error_code ec;
        if (!fs::is_regular_file(script, ec))
            throw Error(script + ": the contouring script is missing (set SEASPRING_TOOLS to the sources' tools folder, or -script)");
    }
    const auto parts = listPartFiles(o.dirin, o.first, o.last);
    const fs::path parent = fs::path(o.savevtk).parent_path();
    std::error_code ec;
    if (!parent.empty()) fs::create_directories(parent, ec);
    log << "isosurface: " << parts.size() << " part file(s) (" << parts.front().first << ".." << parts.back().first
        << ") in " << o.dirin << ", array " << o.var << "\n";
    const std::string list = o.savevtk + "_isosurface.txt";
    AtomicTextFile jobs(list);  // one line per part: level, grid, surface (read by isosurface.py)
    for (const auto& [idx, path] : parts) {
        const io::PartData d = io::readPartH5(path);
        const IsoGrid g = isosurfaceGrid(d, o, path);
        char name[32];
        std::snprintf(name, sizeof name, "_%04d", idx);
        const std::string vti = o.savevtk + name + ".vti", vtp = o.savevtk + name + ".vtp";
        io::writeImageVti(vti, g.grid, g.arrays);
        const double level = isosurfaceLevel(o, g.massfluid, g.dim);
        std::fprintf(jobs.file(), "%.9g\t%s\t%s\n", level, vti.c_str(), vtp.c_str());
        log << "  " << vti << ": " << g.grid.dims[0] << " x " << g.grid.dims[1] << " x " << g.grid.dims[2]
            << " nodes, level " << level << "\n";
    }
    jobs.commit();
    if (o.gridonly) {
        log << "isosurface: grids written (-gridonly); contour them with: pvpython " << SEASPRING_TOOLS_DIR
            << "/isosurface.py --array " << o.var << " --jobs " << list << "\n";
        return int(parts.size());
    }
    const std::string cmd = quote(pv) + " " + quote(script) + " --array " + o.var + " --jobs " + quote(list);
    log << "isosurface: " << cmd << "\n" << std::flush;
    const int rc = std::system(cmd.c_str());
    if (rc != 0)
        throw Error("pvpython failed (" + (WIFEXITED(rc) ? "exit code " + std::to_string(WEXITSTATUS(rc)) : std::string("signal")) +
                    "): " + cmd);
    log << "isosurface: " << parts.size() << " surface(s) written as " << o.savevtk << "_NNNN.vtp\n";
    return int(parts.size());
}

}  // namespace seaspring::post
