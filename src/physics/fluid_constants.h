// SeaSpring — MIT licence.
/// \file fluid_constants.h
/// \brief Run-time constants of the fluid interaction (float, as used per pair) and the
///        compile-time option set that selects one specialised interaction.
#pragma once

#include "physics/density_diffusion.h"
#include "physics/sph_kernels.h"
#include "physics/viscosity.h"

namespace seaspring::physics {

struct FluidConstants {
    KernelConstants ker;
    float eta2 = 0;         ///< (0.1 h)^2
    float cs0 = 0;          ///< reference sound speed [m/s]
    float cteb = 0;         ///< Tait B [Pa]
    float rhop0 = 0;        ///< reference density [kg/m^3]
    float ovrhop0 = 0;      ///< 1/rhop0
    float massfluid = 0;    ///< [kg]
    float massbound = 0;    ///< [kg]
    float visco = 0;        ///< alpha (artificial) or nu (laminar) for fluid neighbours
    float visco_bound = 0;  ///< the same times ViscoBoundFactor, for boundary neighbours
    float ddtkh = 0;        ///< delta * 2h
    float ddtgz = 0;        ///< rhop0 g_z / B
    float sps_smag = 0;     ///< SPS constants (makeSpsConstants)
    float sps_blin = 0;
    int dt_all_particles = 0;  ///< DtAllParticles: boundary velocities enter the dt criterion
};

/// The options that specialise the fluid interaction at compile time.
template <class KernelT, Viscosity kVisco, DensityDiffusion kDdt, int kDim>
struct FluidOptions {
    using Kernel = KernelT;
    static constexpr Viscosity visco = kVisco;
    static constexpr DensityDiffusion ddt = kDdt;
    static constexpr int dim = kDim;
    static constexpr bool sps = kVisco == Viscosity::LaminarSps;
};

}  // namespace seaspring::physics
