// SeaSpring — MIT licence.
/// \file version.h
#pragma once

namespace seaspring {
inline constexpr const char* kVersion = "0.1.0";
}
