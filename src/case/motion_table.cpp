// SeaSpring — MIT licence.
/// \file motion_table.cpp
#include "case/motion_table.h"

#include <cctype>

#include "core/error.h"

namespace seaspring::model {

/// Splits a data row: fields are separated by blanks and/or one ';' or ','. Two hard
/// separators in a row (or one at the start) give an empty field; one at the end is allowed.
std::vector<std::string> splitFields(const std::string& line) {
    std::vector<std::string> out;
    bool in_field = false, hard = false;  // hard: a ';' or ',' since the last field
    for (char ch : line) {
        const bool sep = ch == ';' || ch == ',';
        if (sep || std::isspace(static_cast<unsigned char>(ch))) {
            if (sep && !in_field && (hard || out.empty())) out.emplace_back();
            hard = (hard && !in_field) || sep;
            in_field = false;
        } else {
            if (!in_field) out.emplace_back();
            in_field = true;
            out.back() += ch;
        }
    }
    return out;
}

MotionTable readTable(std::istream& in, const TableSpec& s) {
    MotionTable t;
    std::string line;
    int n = s.first_line - 1, prev_line = 0;
    bool first = true;
    while (std::getline(in, line)) {
        ++n;
        if (n == 1 && line.compare(0, 3, "\xEF\xBB\xBF") == 0) line.erase(0, 3);  // UTF-8 BOM
        const std::size_t p = line.find_first_not_of(" \t\r\v\f");
        if (p == std::string::npos || line[p] == '#') continue;
        const std::vector<std::string> f = splitFields(line);
        std::vector<double> v(f.size());
        std::size_t bad = 0;
        while (bad < f.size() && toNumber(f[bad], v[bad])) ++bad;
        // A header is a first line with no number at all ("time;x"); a first row that is
        // partly numeric is data with a typo, reported like any other row.
        std::size_t numeric = 0;
        for (std::size_t k = 0; k < f.size(); ++k) {
            double ignored = 0;
            numeric += toNumber(f[k], ignored) ? 1 : 0;
        }
        const bool header = first && s.allow_header && numeric == 0;
        first = false;
        if (bad < f.size()) {
            if (header) continue;
            throwInputError(s.name, n,
                            (f[bad].empty() ? std::string("empty value")
                                            : "value '" + f[bad] + "' is not a finite number") +
                                " in column " + std::to_string(bad + 1) + " (expected " + s.expect +
                                ")" + s.origin);
        }
        const int cols = static_cast<int>(f.size());
        if (cols < s.min_cols || cols > s.max_cols)
            throwInputError(s.name, n,
                            "found " + std::to_string(cols) + " column(s) in '" + line.substr(p) +
                                "', expected " + s.expect + s.origin);
        const double time = v[s.tcol];
        if (!t.time.empty() && !(time > t.time.back()))
            throwInputError(s.name, n,
                            "time " + num(time) + " (column " + std::to_string(s.tcol + 1) +
                                ") is not greater than the time " + num(t.time.back()) +
                                " of line " + std::to_string(prev_line) +
                                ": times must increase strictly" + s.origin);
        const auto pick = [&](int c) { return c < 0 ? 0.0 : v[c]; };
        t.time.push_back(time);
        t.value.push_back({pick(s.cx) * s.factor_x, pick(s.cy), pick(s.cz)});
        prev_line = n;
    }
    return t;
}

}  // namespace seaspring::model
