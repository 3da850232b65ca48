// SeaSpring — MIT licence.
/// \file shape_set.cpp
#include "gencase/shape_set.h"

#include <cerrno>
#include <cstring>
#include <fstream>

#include "core/error.h"

namespace seaspring::gencase {

namespace {

/// R * d (the rotation part of `m` only: directions are not translated).
Vec3d rotated(const Affine& m, Vec3d d) {
    return {m.r[0][0] * d.x + m.r[0][1] * d.y + m.r[0][2] * d.z,
            m.r[1][0] * d.x + m.r[1][1] * d.y + m.r[1][2] * d.z,
            m.r[2][0] * d.x + m.r[2][1] * d.y + m.r[2][2] * d.z};
}

ShapeFace makeFace(const Affine& m, Vec3d origin, Vec3d u, Vec3d v, Vec3d outward, bool invert, int line) {
    ShapeFace f;
    f.origin = m.apply(origin);
    f.u = rotated(m, u);
    f.v = rotated(m, v);
    f.normal = rotated(m, invert ? -1.0 * outward : outward);
    if (dot(cross(f.u, f.v), f.normal) < 0) std::swap(f.u, f.v);
    f.line = line;
    return f;
}

}  // namespace

std::vector<ShapeFace> boxShapeFaces(const Affine& m, Vec3d lo, Vec3d hi, unsigned faces, bool invert,
                                     int line) {
    if (faces & BoxSolid) faces = FacesAll;
    const Vec3d ex{hi.x - lo.x, 0, 0}, ey{0, hi.y - lo.y, 0}, ez{0, 0, hi.z - lo.z};
    std::vector<ShapeFace> out;
    if (faces & FaceLeft) out.push_back(makeFace(m, lo, ey, ez, {-1, 0, 0}, invert, line));
    if (faces & FaceRight) out.push_back(makeFace(m, {hi.x, lo.y, lo.z}, ey, ez, {1, 0, 0}, invert, line));
    if (faces & FaceFront) out.push_back(makeFace(m, lo, ex, ez, {0, -1, 0}, invert, line));
    if (faces & FaceBack) out.push_back(makeFace(m, {lo.x, hi.y, lo.z}, ex, ez, {0, 1, 0}, invert, line));
    if (faces & FaceBottom) out.push_back(makeFace(m, lo, ex, ey, {0, 0, -1}, invert, line));
    if (faces & FaceTop) out.push_back(makeFace(m, {lo.x, lo.y, hi.z}, ex, ey, {0, 0, 1}, invert, line));
    return out;
}

std::string shapeFileName(const std::string& case_name, const std::string& set_name) {
    return case_name + (set_name.empty() ? "" : "_" + set_name) + "_Actual.vtk";
}

void writeShapeVtk(const std::string& path, const ShapeSet& set) {
    std::ofstream os(path);
    if (!os) throw Error(formatLocation(path, 0, std::string("cannot create the shape file: ") + std::strerror(errno)));
    os.precision(17);
    const std::size_t n = set.faces.size();
    os << "# vtk DataFile Version 3.0\nSeaSpring shape set '" << set.name << "'\nASCII\nDATASET POLYDATA\n";
    os << "POINTS " << 4 * n << " double\n";
    for (const ShapeFace& f : set.faces) {
        const Vec3d c[4] = {f.origin, f.origin + f.u, f.origin + f.u + f.v, f.origin + f.v};
        for (const Vec3d& p : c) os << p.x << ' ' << p.y << ' ' << p.z << '\n';
    }
    os << "POLYGONS " << n << ' ' << 5 * n << '\n';
    for (std::size_t i = 0; i < n; ++i)
        os << "4 " << 4 * i << ' ' << 4 * i + 1 << ' ' << 4 * i + 2 << ' ' << 4 * i + 3 << '\n';
    os << "CELL_DATA " << n << "\nNORMALS normal double\n";
    for (const ShapeFace& f : set.faces) os << f.normal.x << ' ' << f.normal.y << ' ' << f.normal.z << '\n';
    os << "SCALARS line int 1\nLOOKUP_TABLE default\n";
    for (const ShapeFace& f : set.faces) os << f.line << '\n';
    os.close();
    if (!os) throw Error(formatLocation(path, 0, "cannot write the shape file (disk full?)"));
}

}  // namespace seaspring::gencase
