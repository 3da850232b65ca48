// SeaSpring — MIT licence.
/// \file boundary_normals.cpp
#include "gencase/boundary_normals.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <ostream>

#include "core/error.h"

namespace seaspring::gencase {

namespace fs = std::filesystem;

namespace {

constexpr const char* kActualSuffix = "_Actual.vtk";

/// "PREFIX_X_Actual.vtk" (or "PREFIX_Actual.vtk" for X = "") -> X.
bool matchSetFile(const std::string& file, const std::string& prefix, const std::string& suffix,
                  std::string& set) {
    if (prefix.empty() || file.size() < prefix.size() + suffix.size()) return false;
    if (file.compare(0, prefix.size(), prefix) != 0) return false;
    if (file.compare(file.size() - suffix.size(), suffix.size(), suffix) != 0) return false;
    const std::string mid = file.substr(prefix.size(), file.size() - prefix.size() - suffix.size());
    if (!mid.empty() && mid[0] != '_') return false;
    set = mid.empty() ? mid : mid.substr(1);
    return true;
}

const ShapeSet* resolveGeometryFile(const XmlSource& src, pugi::xml_node geo, const std::vector<ShapeSet>& sets,
                                    const std::string& case_name) {
    src.checkAttributes(geo, {"file"});
    const std::string file = src.text(geo, "file");
    std::string set;
    bool matched = false;
    for (const std::string& prefix : {std::string("[CaseName]"), case_name})
        matched = matched || matchSetFile(file, prefix, kActualSuffix, set);
    if (!matched) {
        std::string dp_set;
        for (const std::string& prefix : {std::string("[CaseName]"), case_name})
            if (matchSetFile(file, prefix, "_Dp.vtk", dp_set))
                src.fail(geo, "file=\"" + file + "\": shapes in dp mode are not supported; SeaSpring keeps the "
                              "actual shapes (<setshapemode>actual</setshapemode>): use \"[CaseName]_" + dp_set +
                              "_Actual.vtk\"");
        const fs::path path = fs::path(src.directory()) / file;
        std::error_code ec;
        if (fs::exists(path, ec))
            src.fail(geo, "file=\"" + file + "\": reading an external VTK geometry for normals is not supported "
                          "yet; draw the interface with <drawbox> while <setactive drawshapes=\"1\"/> and name it "
                          "with <shapeout file=\"X\"/>, then use \"[CaseName]_X_Actual.vtk\"");
        src.fail(geo, "file=\"" + file + "\" names no shape set of this case (expected \"[CaseName]_X_Actual.vtk\" "
                      "for a set X written by <shapeout file=\"X\"/>) and no existing file");
    }
    for (const ShapeSet& s : sets) {
        if (s.name != set) continue;
        if (s.faces.empty())
            src.fail(geo, "file=\"" + file + "\": shape set '" + set + "' (<shapeout> at line " +
                          std::to_string(s.line) + ") has no faces: SeaSpring records <drawbox> faces only "
                          "while <setactive drawshapes=\"1\"/> is set");
        return &s;
    }
    std::string known;
    for (const ShapeSet& s : sets) known += (known.empty() ? "'" : ", '") + s.name + "'";
    src.fail(geo, "file=\"" + file + "\": no shape set '" + set + "' was written by <shapeout file=\"" + set +
                  "\"/> before this point (shape sets: " + (known.empty() ? "none" : known) + ")");
}

/// A face ready for the distance search: its bounding box grown by the reach.
struct SearchFace {
    ShapeFace f;
    Vec3d lo, hi;
};

double norm2(Vec3d a) { return dot(a, a); }

std::vector<SearchFace> prepareFaces(const std::vector<ShapeFace>& faces, double reach, bool two_d,
                                     const std::string& file) {
    std::vector<SearchFace> out;
    for (ShapeFace f : faces) {
        if (two_d) {
            if (std::fabs(f.normal.y) > 1 - 1e-9) continue;  // front/back: the plane of the case itself
            if (std::fabs(f.normal.y) > 1e-9)
                throwInputError(file, f.line, "a face of this shape is tilted out of the x-z plane; in a 2D case "
                                              "the normals interface must be perpendicular to it");
            f.origin.y = f.u.y = f.v.y = f.normal.y = 0;
            if (norm2(f.v) > norm2(f.u)) f.u = f.v;  // the face's extent in x-z: one segment
            f.v = {0, 0, 0};
            if (norm2(f.u) == 0) continue;
        } else if (norm2(cross(f.u, f.v)) == 0) {
            continue;  // zero area: not part of an interface
        }
        SearchFace s{f, f.origin, f.origin};
        for (const Vec3d c : {f.origin + f.u, f.origin + f.v, f.origin + f.u + f.v}) {
            s.lo = {std::min(s.lo.x, c.x), std::min(s.lo.y, c.y), std::min(s.lo.z, c.z)};
            s.hi = {std::max(s.hi.x, c.x), std::max(s.hi.y, c.y), std::max(s.hi.z, c.z)};
        }
        s.lo = s.lo - Vec3d{reach, reach, reach};
        s.hi = s.hi + Vec3d{reach, reach, reach};
        out.push_back(s);
    }
    return out;
}

/// Nearest point of the rectangle origin + s u + t v (s, t in [0, 1]) to p.
Vec3d nearestOnFace(const ShapeFace& f, Vec3d p) {
    const Vec3d r = p - f.origin;
    const double uu = norm2(f.u), vv = norm2(f.v);
    const double s = uu > 0 ? std::clamp(dot(r, f.u) / uu, 0.0, 1.0) : 0.0;
    const double t = vv > 0 ? std::clamp(dot(r, f.v) / vv, 0.0, 1.0) : 0.0;
    return f.origin + s * f.u + t * f.v;
}

Vec3f ghostVector(Vec3d p, const std::vector<SearchFace>& faces, double reach2, double on_plane) {
    bool found = false;
    double best = reach2;
    Vec3d best_q = p;
    for (const SearchFace& s : faces) {
        if (p.x < s.lo.x || p.x > s.hi.x || p.y < s.lo.y || p.y > s.hi.y || p.z < s.lo.z || p.z > s.hi.z) continue;
        if (!(dot(s.f.origin - p, s.f.normal) > on_plane)) continue;  // p is not behind the face
        const Vec3d q = nearestOnFace(s.f, p);
        const double d2 = norm2(q - p);
        if (d2 < best || (!found && d2 <= best)) {
            best = d2;
            best_q = q;
            found = true;
        }
    }
    if (!found) return {0.f, 0.f, 0.f};
    return {float(2 * (best_q.x - p.x)), float(2 * (best_q.y - p.y)), float(2 * (best_q.z - p.z))};
}

}  // namespace

NormalsRequest readNormals(const XmlSource& src, pugi::xml_node normals, const ExpressionEvaluator& ev,
                           const std::vector<ShapeSet>& sets, const std::string& case_name) {
    NormalsRequest r;
    if (!normals || XmlSource::isDisabled(normals)) return r;
    r.active = src.boolean(normals, "active", true);  // GenCase computes normals unless active="false"
    if (!r.active) return r;
    src.checkAttributes(normals, {"active"});
    pugi::xml_node dist, geo;
    for (pugi::xml_node c : normals.children()) {
        if (c.type() != pugi::node_element || XmlSource::isDisabled(c)) continue;
        const std::string name = c.name();
        pugi::xml_node& slot = name == "distanceh" ? dist : geo;
        if (name != "distanceh" && name != "geometryfile")
            src.fail(c, "is not supported in <normals>: SeaSpring computes normals from a shape set only "
                        "(supported: <distanceh>, <geometryfile>; see docs/case-format.md)");
        if (slot) src.fail(c, "is given twice in <normals>");
        slot = c;
    }
    if (dist) {
        src.checkAttributes(dist, {"value"});
        src.checkChildren(dist, {});
        r.distanceh = src.number(dist, "value", ev, 2.0);
        if (!(r.distanceh > 0)) src.fail(dist, "value=" + std::to_string(r.distanceh) + ": must be > 0");
    }
    if (!geo)
        src.fail(normals, "needs <geometryfile file=\"[CaseName]_X_Actual.vtk\"/>: the shape set X (written by "
                          "<shapeout file=\"X\"/>) that holds the boundary interface");
    src.checkChildren(geo, {});
    r.shapes = resolveGeometryFile(src, geo, sets, case_name);
    return r;
}

std::vector<Vec3f> computeGhostVectors(const std::vector<Vec3d>& pos, std::size_t nbound,
                                       const std::vector<ShapeFace>& faces, double reach, double dp,
                                       bool two_d, const std::string& file, GhostVectorStats* stats) {
    SEASPRING_CHECK(nbound <= pos.size(), "nbound ", nbound, " exceeds the particle count ", pos.size());
    const std::vector<SearchFace> search = prepareFaces(faces, reach, two_d, file);
    const double reach2 = reach * reach, on_plane = 1e-9 * dp;
    std::vector<Vec3f> out(nbound);
    const long long n = static_cast<long long>(nbound);
#pragma omp parallel for schedule(static)
    for (long long i = 0; i < n; ++i) {
        Vec3d p = pos[static_cast<std::size_t>(i)];
        if (two_d) p.y = 0;
        out[static_cast<std::size_t>(i)] = ghostVector(p, search, reach2, on_plane);
    }
    if (stats) {
        *stats = GhostVectorStats{};
        for (const Vec3f& g : out) {
            const double len = std::sqrt(double(g.x) * g.x + double(g.y) * g.y + double(g.z) * g.z);
            if (len > 0) ++stats->with_normal;
            else ++stats->without_normal;
            stats->max_length = std::max(stats->max_length, len);
        }
    }
    return out;
}

void printNormalsSummary(std::ostream& log, const std::string& set_name, const GhostVectorStats& s, double dp) {
    log << "Normals (mDBC, shape set '" << set_name << "'): " << s.with_normal << " boundary particles with a ghost "
        << "vector, " << s.without_normal << " without; max |ghost vector| = " << s.max_length / dp << " dp\n";
}

}  // namespace seaspring::gencase
