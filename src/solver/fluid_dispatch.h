// SeaSpring — MIT licence.
/// \file fluid_dispatch.h
/// \brief Turns the run-time physics choice into one compile-time FluidOptions instantiation:
///        `f(Opt{})` is called with the matching option type. Backends split the instantiations
///        by kernel and dimension over several files (dispatchViscoDdt) to keep builds short.
#pragma once

#include "physics/fluid_constants.h"
#include "solver/backend.h"

namespace seaspring::solver {

template <class Kernel, physics::Viscosity kVisco, int kDim, class F>
void dispatchDdt(physics::DensityDiffusion ddt, F&& f) {
    using physics::DensityDiffusion;
    using physics::FluidOptions;
    switch (ddt) {
        case DensityDiffusion::None: f(FluidOptions<Kernel, kVisco, DensityDiffusion::None, kDim>{}); break;
        case DensityDiffusion::Molteni: f(FluidOptions<Kernel, kVisco, DensityDiffusion::Molteni, kDim>{}); break;
        case DensityDiffusion::Fourtakas: f(FluidOptions<Kernel, kVisco, DensityDiffusion::Fourtakas, kDim>{}); break;
        case DensityDiffusion::FourtakasFull: f(FluidOptions<Kernel, kVisco, DensityDiffusion::FourtakasFull, kDim>{}); break;
    }
}

/// Viscosity x density diffusion for one kernel and dimension.
template <class Kernel, int kDim, class F>
void dispatchViscoDdt(const PhysicsChoice& c, F&& f) {
    using physics::Viscosity;
    switch (c.visco) {
        case Viscosity::Artificial: dispatchDdt<Kernel, Viscosity::Artificial, kDim>(c.ddt, f); break;
        case Viscosity::LaminarSps: dispatchDdt<Kernel, Viscosity::LaminarSps, kDim>(c.ddt, f); break;
        case Viscosity::Laminar: dispatchDdt<Kernel, Viscosity::Laminar, kDim>(c.ddt, f); break;
    }
}

/// Viscosity only (no density diffusion): the hydrodynamic force on solids does not depend on it.
template <class Kernel, int kDim, class F>
void dispatchVisco(const PhysicsChoice& c, F&& f) {
    using physics::DensityDiffusion;
    using physics::FluidOptions;
    using physics::Viscosity;
    switch (c.visco) {
        case Viscosity::Artificial: f(FluidOptions<Kernel, Viscosity::Artificial, DensityDiffusion::None, kDim>{}); break;
        case Viscosity::LaminarSps: f(FluidOptions<Kernel, Viscosity::LaminarSps, DensityDiffusion::None, kDim>{}); break;
        case Viscosity::Laminar: f(FluidOptions<Kernel, Viscosity::Laminar, DensityDiffusion::None, kDim>{}); break;
    }
}

}  // namespace seaspring::solver
