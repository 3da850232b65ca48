// SeaSpring — MIT licence.
/// \file motion_table.h
/// \brief Reading the data files of file-driven movements (mvrectfile, mvrotfile): columns
///        split by blanks, ';' or ',', an optional header line, strictly increasing time.
#pragma once

#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <istream>
#include <string>
#include <vector>

#include "case/motion.h"

namespace seaspring::model {

/// Text of a double: 17 digits (exact round trip through strtod) or fewer for messages.
inline std::string num(double v, int digits = 15) {
    char b[40];
    std::snprintf(b, sizeof b, "%.*g", digits, v);
    return b;
}

inline bool toNumber(const std::string& s, double& v) {
    char* end = nullptr;
    v = std::strtod(s.c_str(), &end);
    return !s.empty() && end == s.c_str() + s.size() && std::isfinite(v);
}


/// Splits a data row: fields are separated by blanks and/or one ';' or ','. Two hard
/// separators in a row (or one at the start) give an empty field; one at the end is allowed.
std::vector<std::string> splitFields(const std::string& line);

/// How to read a data table, and how to name it in messages.
struct TableSpec {
    std::string name;    ///< file named in messages
    int first_line = 1;  ///< number of the stream's first line
    int min_cols = 2, max_cols = INT_MAX;
    bool allow_header = true;                ///< a first line that is not all numbers is skipped
    int tcol = 0, cx = 1, cy = -1, cz = -1;  ///< columns of time and value x,y,z (-1: 0)
    double factor_x = 1;                     ///< multiplies value.x (angles to radians)
    std::string expect, origin;  ///< the expected columns; the case element using the data
};

/// Reads a table; blank lines and '#' lines are skipped, times must increase strictly.
/// Errors name the data file and its line.
MotionTable readTable(std::istream& in, const TableSpec& s);

}  // namespace seaspring::model
