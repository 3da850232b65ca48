// SeaSpring — MIT licence.
/// \file cuda_forces_cubic.cu
/// \brief CUDA force instantiations for the cubic kernel (2D and 3D).
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

}  // namespace seaspring::cuda
