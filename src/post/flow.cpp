// SeaSpring — MIT licence.
/// \file flow.cpp
/// \brief `seaspring-post flow` (see flow.h).
#include "post/flow.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <ostream>

#include "core/error.h"
#include "core/particle_set.h"
#include "post/part_series.h"

namespace seaspring::post {

using physics::Double3;

physics::PlaneSection makeSection(const std::vector<double>& plane, const std::vector<double>& limits) {
    if (plane.size() != 6)
        throw Error("-plane: expected 6 numbers x,y,z,nx,ny,nz (a point and the normal), found " +
                    std::to_string(plane.size()));
    for (double v : plane)
        if (!std::isfinite(v)) throw Error("-plane: a value is not finite");
    const double len = std::sqrt(plane[3] * plane[3] + plane[4] * plane[4] + plane[5] * plane[5]);
    if (!(len > 0)) throw Error("-plane: the normal (" + std::to_string(plane[3]) + ", " + std::to_string(plane[4]) +
                                ", " + std::to_string(plane[5]) + ") is zero");
    physics::PlaneSection s;
    s.o = Double3{plane[0], plane[1], plane[2]};
    s.n = Double3{plane[3] / len, plane[4] / len, plane[5] / len};
    const double inf = std::numeric_limits<double>::infinity();
    s.lo = Double3{-inf, -inf, -inf};
    s.hi = Double3{inf, inf, inf};
    if (!limits.empty()) {
        if (limits.size() != 6)
            throw Error("-limits: expected 6 numbers xmin,ymin,zmin,xmax,ymax,zmax, found " + std::to_string(limits.size()));
        const char* axis = "xyz";
        for (int a = 0; a < 3; ++a)
            if (!(limits[a] <= limits[a + 3]))
                throw Error(std::string("-limits: ") + axis[a] + "min " + std::to_string(limits[a]) + " > " + axis[a] +
                            "max " + std::to_string(limits[a + 3]));
        s.lo = Double3{limits[0], limits[1], limits[2]};
        s.hi = Double3{limits[3], limits[4], limits[5]};
    }
    return s;
}

FlowCount flowBetween(const physics::PlaneSection& s, const io::PartData& a, const io::PartData& b,
                      const std::string& what) {
    if (a.np() != b.np())
        throw Error(what + ": " + std::to_string(b.np()) + " particles, the previous part file " +
                    std::to_string(a.np()) + " (not parts of the same run?)");
    if (b.mass.empty()) throw Error(what + ": no /mass (a version 1 part file): cannot count mass");
    FlowCount c;
    const auto fluid = std::uint8_t(ParticleType::Fluid);
    for (std::size_t i = 0; i < b.np(); ++i) {
        if (b.type[i] != fluid || a.excluded[i] != 0 || b.excluded[i] != 0) continue;
        const Double3 p0{a.pos[3 * i], a.pos[3 * i + 1], a.pos[3 * i + 2]};
        const Double3 p1{b.pos[3 * i], b.pos[3 * i + 1], b.pos[3 * i + 2]};
        const int dir = physics::sectionCrossing(s, p0, p1);
        if (dir == 0) continue;
        (dir > 0 ? c.npos : c.nneg) += 1;
        const double m = double(b.mass[i]);
        c.mass += dir * m;
        c.volume += dir * m / double(b.rhop[i]);
    }
    return c;
}

int runFlow(const FlowOptions& o, std::ostream& log) {
    const physics::PlaneSection s = makeSection(o.plane, o.limits);
    const auto parts = listPartFiles(o.dirin, o.first, o.last);
    if (parts.size() < 2)
        throw Error(o.dirin + "/data: flow needs at least two part files in the range (found " +
                    std::to_string(parts.size()) + ")");
    log << "flow: plane through (" << s.o.x << ", " << s.o.y << ", " << s.o.z << ") with normal (" << s.n.x << ", "
        << s.n.y << ", " << s.n.z << "), " << parts.size() << " part file(s) (" << parts.front().first << ".."
        << parts.back().first << ") in " << o.dirin << "\n";
    AtomicTextFile out(o.savecsv);
    std::FILE* f = out.file();
    std::fprintf(f, "part;time;npos;nneg;mass;volume;massflow;volumeflow;masstotal;volumetotal\n");
    io::PartData prev = io::readPartH5(parts[0].second);
    double mtot = 0, vtot = 0;
    int rows = 0;
    for (std::size_t k = 1; k < parts.size(); ++k) {
        io::PartData d = io::readPartH5(parts[k].second);
        const double dt = d.time - prev.time;
        if (!(dt > 0))
            throw Error(parts[k].second + ": time " + std::to_string(d.time) + " is not after the previous part's " +
                        std::to_string(prev.time));
        const FlowCount c = flowBetween(s, prev, d, parts[k].second);
        mtot += c.mass;
        vtot += c.volume;
        std::fprintf(f, "%d;%.10g;%lld;%lld;%.9g;%.9g;%.9g;%.9g;%.9g;%.9g\n", parts[k].first, d.time, c.npos, c.nneg,
                     c.mass, c.volume, c.mass / dt, c.volume / dt, mtot, vtot);
        ++rows;
        prev = std::move(d);
    }
    out.commit();
    log << "flow: " << rows << " row(s) written to " << o.savecsv << " (net " << mtot << " kg, " << vtot << " m^3)\n";
    return rows;
}

}  // namespace seaspring::post
