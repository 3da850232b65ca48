// SeaSpring — MIT licence.
/// \file fluid_constants.h
/// \brief Run-time constants of the fluid interaction (float, as used per pair), made from the
///        case values in one place (makeFluidConstants), and the compile-time option set that
///        selects one specialised interaction.
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
    float ddtgz = 0;        ///< -rhop0 g_z / B
    float sps_smag = 0;     ///< SPS constants (makeSpsConstants)
    float sps_blin = 0;
    int dt_all_particles = 0;  ///< DtAllParticles: boundary velocities enter the dt criterion
};

/// The case values the fluid constants are made from (host; makeFluidConstants).
struct FluidInputs {
    double h = 0;                   ///< smoothing length [m]
    double dp = 0;                  ///< particle spacing [m]
    int dim = 3;                    ///< 2 or 3
    double cs0 = 0;                 ///< reference sound speed [m/s]
    double b = 0;                   ///< Tait B [Pa]
    double rhop0 = 0;               ///< reference density [kg/m^3]
    double massfluid = 0;           ///< [kg]
    double massbound = 0;           ///< [kg]
    double visco = 0;               ///< Visco: alpha (artificial) or nu (laminar)
    double visco_bound_factor = 1;  ///< ViscoBoundFactor
    double ddt_value = 0;           ///< DensityDTValue delta
    double gravity_z = 0;           ///< g_z [m/s^2]
    bool dt_all_particles = false;  ///< DtAllParticles
};

/// The fluid constants of a case (host): kernel constants, eta2 = (0.1 h)^2, Tait B and 1/rho0,
/// viscosity (x ViscoBoundFactor for boundary neighbours), DDT delta 2h and -rho0 g_z / B (the
/// hydrostatic term of Fourtakas' DDT, see density_diffusion.h), SPS constants.
inline FluidConstants makeFluidConstants(const FluidInputs& in) {
    const double h = in.h, rho0 = in.rhop0;
    FluidConstants f;
    f.ker = makeKernelConstants(h, in.dp, in.dim);
    f.eta2 = float((0.1 * h) * (0.1 * h));
    f.cs0 = float(in.cs0);
    f.cteb = float(in.b);
    f.rhop0 = float(rho0);
    f.ovrhop0 = float(1.0 / rho0);
    f.massfluid = float(in.massfluid);
    f.massbound = float(in.massbound);
    f.visco = float(in.visco);
    f.visco_bound = float(in.visco * in.visco_bound_factor);
    f.ddtkh = float(in.ddt_value * 2.0 * h);
    // rhoH_ab = rho_b^H - rho_a^H needs +rho0|g|/B for gravity along -z (see density_diffusion.h).
    f.ddtgz = float(-rho0 * in.gravity_z / in.b);
    const SpsConstants sps = makeSpsConstants(in.dp, in.dim);
    f.sps_smag = sps.smag;
    f.sps_blin = sps.blin;
    f.dt_all_particles = in.dt_all_particles ? 1 : 0;
    return f;
}

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
