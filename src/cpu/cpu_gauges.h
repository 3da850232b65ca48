// SeaSpring — MIT licence.
/// \file cpu_gauges.h
/// \brief The gauges' kernel sums, maxz rows and particle positions on the CPU.
#pragma once

#include <cstdint>
#include <vector>

#include "cpu/cpu_backend.h"
#include "solver/backend.h"

namespace seaspring::cpu {

/// Answers the queries for the current sorted state (`slot_of_id`: solver::gaugeSlotsOfIds).
void cpuGauges(const solver::PhysicsChoice& choice, const CpuArrays& a, std::uint32_t nbound,
               const solver::GaugeQueries& q, const std::vector<std::uint32_t>& slot_of_id,
               const physics::FluidConstants& c, const physics::CellGrid& g, solver::GaugeResults& out);

}  // namespace seaspring::cpu
