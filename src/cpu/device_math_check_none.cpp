// SeaSpring — MIT licence.
/// \file device_math_check_none.cpp
/// \brief deviceSqrtNormalRangeMismatches and deviceReciprocalNormalRangeMismatches of a build
///        without the CUDA backend: nothing to check (the host's forms are their definitions).
#include "core/device_math_check.h"

namespace seaspring {

DeviceMathCheck deviceSqrtNormalRangeMismatches(std::uint32_t, std::uint32_t, bool) {
    DeviceMathCheck r;
    r.why = "this build has no CUDA backend (configure with -DSEASPRING_CUDA=ON)";
    return r;
}

DeviceMathCheck deviceReciprocalNormalRangeMismatches(std::uint32_t, std::uint32_t, bool) {
    return deviceSqrtNormalRangeMismatches(0, 0, false);
}

}  // namespace seaspring
