// SeaSpring — MIT licence.
/// \file cuda_forces_cubic.cu
/// \brief CUDA force instantiations for the cubic kernel (2D and 3D): the fluid forces and the
///        hydrodynamic force on VCPM solid particles.
#include "cuda/cuda_forces_impl.cuh"
#include "solver/fluid_dispatch.h"

namespace seaspring::cuda {

physics::DtMaxima cudaForces_cubic(const solver::PhysicsChoice& choice, DeviceArrays& a,
                                  std::uint32_t nbound, std::uint32_t nfluid,
                                  const physics::FluidConstants& c, const physics::CellGrid& g) {
    physics::DtMaxima m;
    auto run = [&](auto opt) { m = cudaForcesFor<decltype(opt)>(a, nbound, nfluid, c, g); };
    if (choice.dim == 2) solver::dispatchViscoDdt<physics::CubicKernel, 2>(choice, run);
    else solver::dispatchViscoDdt<physics::CubicKernel, 3>(choice, run);
    return m;
}

void cudaHydroForces_cubic(const solver::PhysicsChoice& choice, DeviceArrays& a, const std::uint32_t* slot,
                          std::uint32_t nsolid, physics::Double3* out, const physics::FluidConstants& c,
                          const physics::CellGrid& g) {
    auto run = [&](auto opt) { cudaHydroForcesFor<decltype(opt)>(a, slot, nsolid, out, c, g); };
    if (choice.dim == 2) solver::dispatchVisco<physics::CubicKernel, 2>(choice, run);
    else solver::dispatchVisco<physics::CubicKernel, 3>(choice, run);
}

}  // namespace seaspring::cuda
