// SeaSpring — MIT licence.
/// \file device_math_check.h
/// \brief Checks, on the device, that the GPU's own forms of IEEE operations give their bits:
///        physics::sqrtNormalRange against sqrtf and physics::reciprocalNormalRange against its
///        definition (reciprocalNormalRangeSpec) for every float of a range.
#pragma once

#include <cstdint>
#include <string>

namespace seaspring {

struct DeviceMathCheck {
    bool ran = false;             ///< false: no CUDA backend or no device (`why` says which)
    std::string why;
    std::uint64_t checked = 0;    ///< floats compared
    std::uint64_t mismatches = 0; ///< of them, with other bits
    std::uint32_t first_mismatch_bits = 0;  ///< the smallest such input's bits (if any)
};

/// Every float whose bits lie in [first_bits, last_bits] (positive floats: their bits order them
/// like their values): how many give other bits in physics::sqrtNormalRange than in sqrtf, on the
/// first CUDA device. `rough`: the first approximation x * rsqrt(x) instead of sqrtNormalRange,
/// the check's control (it must find mismatches).
DeviceMathCheck deviceSqrtNormalRangeMismatches(std::uint32_t first_bits, std::uint32_t last_bits, bool rough = false);

/// The same for physics::reciprocalNormalRange against physics::reciprocalNormalRangeSpec (every
/// float: first_bits 0, last_bits 0xffffffff, negative ones and NaNs included; the bits compare
/// exactly, NaN's too). `rough`: the approximate reciprocal alone (MUFU.RCP), the control.
DeviceMathCheck deviceReciprocalNormalRangeMismatches(std::uint32_t first_bits, std::uint32_t last_bits,
                                                      bool rough = false);

}  // namespace seaspring
