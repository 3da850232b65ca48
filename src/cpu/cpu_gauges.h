// SeaSpring — MIT licence.
/// \file cpu_gauges.h
/// \brief The gauges' kernel sums, maxz rows and particle positions on the CPU.
#pragma once

#include <cstdint>
#include <vector>

#include "cpu/cpu_backend.h"
#include "solver/backend.h"

namespace seaspring::cpu {

/// Marks ids that no gauge asks for.
constexpr std::uint32_t kNoGaugeSlot = 0xFFFFFFFFu;

/// For each boundary id, its index in `ids` (kNoGaugeSlot when not wanted). Ids beyond the
/// boundary block are ignored (the gauge system asks only for boundary/solid particles).
std::vector<std::uint32_t> gaugeSlots(const std::vector<std::uint32_t>& ids, std::uint32_t nbound);

/// Answers the queries for the current sorted state.
void cpuGauges(const solver::PhysicsChoice& choice, const CpuArrays& a, std::uint32_t nbound,
               const solver::GaugeQueries& q, const std::vector<std::uint32_t>& slot_of_id,
               const physics::FluidConstants& c, const physics::CellGrid& g, solver::GaugeResults& out);

}  // namespace seaspring::cpu
