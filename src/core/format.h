// SeaSpring — MIT licence.
/// \file format.h
/// \brief Numbers as text for files and messages (%g): exactText keeps every bit of a double
///        (17 digits, as the resolved case is written), shortText reads better in messages.
#pragma once

#include <cstdio>
#include <string>

#include "core/vec3.h"

namespace seaspring {

/// `v` with `digits` significant digits.
inline std::string formatNumber(double v, int digits) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    return buf;
}
inline std::string exactText(double v) { return formatNumber(v, 17); }
inline std::string shortText(double v, int digits = 10) { return formatNumber(v, digits); }
/// "(x, y, z)" with shortText.
inline std::string shortVec(const Vec3d& v) {
    return "(" + shortText(v.x) + ", " + shortText(v.y) + ", " + shortText(v.z) + ")";
}

}  // namespace seaspring
