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

}  // namespace seaspring::cpu
