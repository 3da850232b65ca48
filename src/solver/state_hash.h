// SeaSpring — MIT licence.
/// \file state_hash.h
/// \brief The run's state hash: 64-bit FNV-1a over every particle in id order (the fields flagged
///        physics::kHashed in the field table: position as
///        double, velocity and density as float, exclusion reason), printed at the end of
///        every run; equal hashes mean bit-identical states.
#pragma once

#include <cstdint>
#include <string>

#include "solver/backend.h"

namespace seaspring::solver {

std::uint64_t stateHash(const HostState& s);
/// 16 lower-case hex digits.
std::string hashHex(std::uint64_t h);

}  // namespace seaspring::solver
