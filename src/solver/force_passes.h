// SeaSpring — MIT licence.
/// \file force_passes.h
/// \brief The pair-loop passes of a force evaluation, specialised at compile time on what
///        each reads: the fluid particles' loop on (kernel, viscosity, density diffusion,
///        dimension), the boundary particles' loop on (kernel, dimension), the hydrodynamic
///        force on boundary particles on (kernel, viscosity, dimension). Declared here,
///        defined in force_passes_impl.h, and instantiated once per backend, kernel and
///        dimension in the units CMake generates from force_instances.in (src/CMakeLists.txt).
#pragma once

#include <cstdint>

#include "physics/cell_grid.h"
#include "physics/fluid_constants.h"
#include "physics/fluid_pair_terms.h"
#include "physics/mdbc.h"
#include "physics/particle_updates.h"
#include "solver/backend.h"

namespace seaspring::solver {

/// What the pair loops read and write (pointers of the executing backend).
struct ForceArgs {
    physics::ParticleView v;
    physics::InteractionInputs in;  ///< tau set only with SPS
    physics::FluidConstants c;
    physics::CellGrid g;
    std::uint32_t nbound = 0, np = 0;
    /// With solids: the hydrodynamic force on boundary particles hydro_slot[0, nhydro) (sorted
    /// indices), written to hydro_out, in the same launch as the pair loops (pairs()).
    const std::uint32_t* hydro_slot = nullptr;
    std::uint32_t nhydro = 0;
    physics::Double3* hydro_out = nullptr;
    /// Pair lanes of the fluid loop (physics/fluid_interaction.h): a power of two, 2^lane_shift.
    std::uint32_t lanes = 1, lane_shift = 0;
};

template <class Exec, class Kernel, int kDim>
struct ForcePasses {
    /// The pair loops of one force evaluation: boundary particles [0, nbound) and fluid
    /// particles [nbound, np), after the pressure pass (acear, visc and, with SPS, gradvel),
    /// and the hydrodynamic force on a.hydro_slot (solids) with the boundary particles.
    static void pairs(const Exec& exec, const PhysicsChoice& choice, const ForceArgs& a);
    /// The hydrodynamic force on boundary particles: out[s] for sorted index slot[s], or for
    /// sorted index s when `slot` is null.
    static void hydro(const Exec& exec, const PhysicsChoice& choice, const ForceArgs& a, const std::uint32_t* slot,
                      std::uint32_t n, physics::Double3* out);
    /// mDBC and the pressure pass in one launch: the density (and velocity) of boundary
    /// particles [0, a.nbound) from their ghost nodes (physics/mdbc.h), each followed by its
    /// pressure, beside the fluid particles' pressure [a.nbound, a.np) (which reads nothing mDBC
    /// writes).
    static void mdbcAndPressure(const Exec& exec, physics::SlipMode slip, const ForceArgs& a,
                                const physics::MdbcInputs& in, const physics::MdbcConstants& m);
};

/// Calls f(Kernel{}, std::integral_constant<int, dim>{}) for the run's kernel and dimension.
template <class F>
void dispatchKernelDim(const PhysicsChoice& c, F&& f) {
    if (c.kernel == physics::KernelType::Wendland) {
        if (c.dim == 2) f(physics::WendlandKernel{}, std::integral_constant<int, 2>{});
        else f(physics::WendlandKernel{}, std::integral_constant<int, 3>{});
    } else {
        if (c.dim == 2) f(physics::CubicKernel{}, std::integral_constant<int, 2>{});
        else f(physics::CubicKernel{}, std::integral_constant<int, 3>{});
    }
}

}  // namespace seaspring::solver
