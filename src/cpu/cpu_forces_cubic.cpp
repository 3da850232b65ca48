// SeaSpring — MIT licence.
/// \file cpu_forces_cubic.cpp
/// \brief CPU force instantiations for the cubic kernel (2D and 3D).
#include "cpu/cpu_forces_impl.h"
#include "solver/fluid_dispatch.h"

namespace seaspring::cpu {

physics::DtMaxima cpuForces_cubic(const solver::PhysicsChoice& choice, CpuArrays& a,
                                 std::uint32_t nbound, std::uint32_t nfluid,
                                 const physics::FluidConstants& c, const physics::CellGrid& g) {
    physics::DtMaxima m;
    auto run = [&](auto opt) { m = cpuForcesFor<decltype(opt)>(a, nbound, nfluid, c, g); };
    if (choice.dim == 2) solver::dispatchViscoDdt<physics::CubicKernel, 2>(choice, run);
    else solver::dispatchViscoDdt<physics::CubicKernel, 3>(choice, run);
    return m;
}

void cpuHydroForces_cubic(const solver::PhysicsChoice& choice, CpuArrays& a, const std::uint32_t* slot,
                         std::uint32_t nsolid, physics::Double3* out, const physics::FluidConstants& c,
                         const physics::CellGrid& g) {
    auto run = [&](auto opt) { cpuHydroForcesFor<decltype(opt)>(a, slot, nsolid, out, c, g); };
    if (choice.dim == 2) solver::dispatchVisco<physics::CubicKernel, 2>(choice, run);
    else solver::dispatchVisco<physics::CubicKernel, 3>(choice, run);
}

}  // namespace seaspring::cpu
