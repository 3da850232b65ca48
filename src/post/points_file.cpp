// SeaSpring — MIT licence.
/// \file points_file.cpp
/// \brief The points file of `seaspring-post measure` (see points_file.h).
#include "post/points_file.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/error.h"

namespace seaspring::post {

namespace {

std::string trim(const std::string& s) {
    std::size_t a = 0, b = s.size();
    while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
    while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
    return s.substr(a, b - a);
}

std::string upper(std::string s) {
    for (char& ch : s) ch = char(std::toupper(static_cast<unsigned char>(ch)));
    return s;
}

/// Three finite numbers separated by spaces, tabs, commas or semicolons.
Vec3d threeNumbers(const std::string& line, const std::string& path, int lineno, const char* what) {
    std::string s = line;
    std::replace_if(s.begin(), s.end(), [](char ch) { return ch == ',' || ch == ';' || ch == '\t'; }, ' ');
    std::istringstream in(s);
    std::vector<double> v;
    std::string tok;
    while (in >> tok) {
        errno = 0;
        char* end = nullptr;
        const double x = std::strtod(tok.c_str(), &end);
        if (end == tok.c_str() || *end != '\0' || errno == ERANGE || !std::isfinite(x))
            throwInputError(path, lineno, std::string(what) + ": '" + tok + "' is not a number (line: '" + line + "')");
        v.push_back(x);
    }
    if (v.size() != 3)
        throwInputError(path, lineno, std::string(what) + ": expected 3 numbers, found " + std::to_string(v.size()) +
                                          " (line: '" + line + "')");
    return Vec3d{v[0], v[1], v[2]};
}

}  // namespace

std::vector<Vec3d> parsePoints(const std::string& text, const std::string& path) {
    std::istringstream in(text);
    std::string raw;
    int lineno = 0;
    enum class Mode { None, Points, List } mode = Mode::None;
    std::vector<Vec3d> pts;
    Vec3d list[3];
    int nlist = 0, keyword_line = 0;
    static const char* kListWhat[3] = {"POINTSLIST begin (x y z)", "POINTSLIST step (x y z)",
                                       "POINTSLIST count (x y z)"};
    while (std::getline(in, raw)) {
        ++lineno;
        const std::string line = trim(raw.substr(0, raw.find('#')));  // '#' starts a comment
        if (line.empty()) continue;
        if (mode == Mode::None) {
            const std::string key = upper(line);
            if (key == "POINTS") mode = Mode::Points;
            else if (key == "POINTSLIST") mode = Mode::List;
            else
                throwInputError(path, lineno, "expected the keyword POINTS or POINTSLIST, found '" + line + "'");
            keyword_line = lineno;
            continue;
        }
        if (mode == Mode::Points) {
            pts.push_back(threeNumbers(line, path, lineno, "point"));
            continue;
        }
        if (nlist == 3)
            throwInputError(path, lineno, "unexpected line after the three POINTSLIST lines: '" + line + "'");
        list[nlist] = threeNumbers(line, path, lineno, kListWhat[nlist]);
        if (nlist == 2) {
            const double c[3] = {list[2].x, list[2].y, list[2].z};
            for (double v : c)
                if (!(v >= 1 && v <= 1e7 && std::floor(v) == v))
                    throwInputError(path, lineno, "POINTSLIST counts must be positive integers (line: '" + line + "')");
            if (c[0] * c[1] * c[2] > 1e8) throwInputError(path, lineno, "POINTSLIST asks for more than 1e8 points");
        }
        ++nlist;
    }
    if (mode == Mode::None) throwInputError(path, lineno, "no POINTS or POINTSLIST keyword (empty points file)");
    if (mode == Mode::List) {
        if (nlist < 3)
            throwInputError(path, lineno, "POINTSLIST (line " + std::to_string(keyword_line) + ") needs 3 lines (begin, "
                                          "step, count), found " + std::to_string(nlist));
        const Vec3d b = list[0], s = list[1];
        const int nx = int(list[2].x), ny = int(list[2].y), nz = int(list[2].z);
        for (int k = 0; k < nz; ++k)
            for (int j = 0; j < ny; ++j)
                for (int i = 0; i < nx; ++i) pts.push_back(Vec3d{b.x + s.x * i, b.y + s.y * j, b.z + s.z * k});
    }
    if (pts.empty()) throwInputError(path, keyword_line, "POINTS has no point");
    return pts;
}

std::vector<Vec3d> readPointsFile(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    if (!f) throw Error(path + ": cannot read the points file");
    std::ostringstream s;
    s << f.rdbuf();
    return parsePoints(s.str(), path);
}

}  // namespace seaspring::post
