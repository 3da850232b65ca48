// SeaSpring — MIT licence.
/// \file cpu_solid.h
/// \brief OpenMP driver of the VCPM solids: the arrays (solver::SolidArrays in host memory,
///        solid-index order) and the loops of a sub-cycle over the shared functions of
///        physics/vcpm.h and physics/solid_coupling.h.
#pragma once

#include <cstdint>
#include <vector>

#include "physics/particle_updates.h"
#include "physics/vcpm.h"
#include "solver/backend.h"
#include "solver/solid_arrays.h"

namespace seaspring::cpu {

class CpuSolid {
public:
    void init(const solver::SolidSetup& s, const physics::StepConstants& step);
    bool empty() const { return a_.n == 0; }
    std::uint32_t size() const { return a_.n; }

    /// slot[s] = sorted index of solid particle s, from the sorted ids of the boundary block.
    void updateSlots(const std::uint32_t* id, std::uint32_t nbound);
    const std::uint32_t* slots() const { return a_.slot.data(); }
    physics::Double3* fluidForce() { return a_.fluid_force.data(); }

    /// n sub-steps of dt from time t0 (clamp nodes moved by `motions` over the whole interval).
    void steps(double t0, double dt, int n, const std::vector<physics::RigidMotionGpu>& motions);
    /// Positions and velocities into the boundary block (sorted arrays) after a sub-cycle of
    /// length dt; `ledger`: accumulate the impulse and work of the hydrodynamic force.
    void toBoundary(double dt, bool ledger, physics::Double3* bpos, physics::Float4* bvelrho);
    void save() { a_.save(); }
    void restore() { a_.restore(); }
    void download(solver::HostState& out) const { a_.download(out); }

private:
    void evaluationSums(const physics::Double3* ep, double f);

    physics::StepConstants step_;
    solver::SolidArrays<solver::HostBuffer> a_;
};

}  // namespace seaspring::cpu
