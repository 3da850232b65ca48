// SeaSpring — MIT licence.
/// \file cpu_forces_wendland.cpp
/// \brief CPU force instantiations for the wendland kernel (2D and 3D).
#include "cpu/cpu_forces_impl.h"
#include "solver/fluid_dispatch.h"

namespace seaspring::cpu {

physics::DtMaxima cpuForces_wendland(const solver::PhysicsChoice& choice, CpuArrays& a,
                                 std::uint32_t nbound, std::uint32_t nfluid,
                                 const physics::FluidConstants& c, const physics::CellGrid& g) {
    physics::DtMaxima m;
    auto run = [&](auto opt) { m = cpuForcesFor<decltype(opt)>(a, nbound, nfluid, c, g); };
    if (choice.dim == 2) solver::dispatchViscoDdt<physics::WendlandKernel, 2>(choice, run);
    else solver::dispatchViscoDdt<physics::WendlandKernel, 3>(choice, run);
    return m;
}

void cpuHydroForces_wendland(const solver::PhysicsChoice& choice, CpuArrays& a, const std::uint32_t* slot,
                         std::uint32_t nsolid, physics::Double3* out, const physics::FluidConstants& c,
                         const physics::CellGrid& g) {
    auto run = [&](auto opt) { cpuHydroForcesFor<decltype(opt)>(a, slot, nsolid, out, c, g); };
    if (choice.dim == 2) solver::dispatchVisco<physics::WendlandKernel, 2>(choice, run);
    else solver::dispatchVisco<physics::WendlandKernel, 3>(choice, run);
}

}  // namespace seaspring::cpu
