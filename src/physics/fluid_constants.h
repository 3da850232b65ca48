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
    /// Fourtakas' rhoH_ab as a cubic in z_a - z_b, from ddtgz = -rhop0 g_z / B
    /// (density_diffusion.h).
    HydrostaticCubic ddt_hyd;
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
    /// Multiplies nu in the laminar term (LaminarLatticeCorrection: 1 / laminarLatticeRatio; 1 for
    /// artificial viscosity or without the correction).
    double laminar_scale = 1;
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
    f.visco = float(in.visco * in.laminar_scale);
    f.visco_bound = float(in.visco * in.laminar_scale * in.visco_bound_factor);
    f.ddtkh = float(in.ddt_value * 2.0 * h);
    // rhoH_ab = rho_b^H - rho_a^H needs +rho0|g|/B for gravity along -z (see density_diffusion.h).
    f.ddt_hyd = makeHydrostaticCubic(-rho0 * in.gravity_z / in.b, rho0);
    const SpsConstants sps = makeSpsConstants(in.dp, in.dim);
    f.sps_smag = sps.smag;
    f.sps_blin = sps.blin;
    f.dt_all_particles = in.dt_all_particles ? 1 : 0;
    return f;
}

/// The bias of the laminar term on the particle lattice (host; LaminarLatticeCorrection). Lo &
/// Shao's operator sums 4 nu m_b (r.grad W)/((rho_a + rho_b)(r^2 + eta^2)) v_ab. For a shear
/// flow u(z) on a regular lattice of spacing dp (volume V = dp^dim a particle) it acts with
///   nu_eff = ratio nu,  ratio = sum_b V (-F(r_b)) z_b^2 r_b^2/(r_b^2 + eta^2)
/// over the lattice points b within 2h (F the kernel's gradient factor, z the shear axis). The
/// continuum value of sum V (-F) z^2 is 1; eta^2 = 0.01 h^2 lowers every pair by
/// eta^2/(r^2 + eta^2), and the lattice sum of the second moment misses 1 a little: with
/// Wendland in 2D, ratio = 0.98488 at h = 1.5 dp (0.9974 without eta) and 0.98492 at h = 2 dp
/// (0.9992 without eta); 0.98863 in 3D at h = 2 dp. It does not depend on dp at fixed h/dp, so no
/// refinement removes it. Computed for the square or cubic lattice gencase fills with; a flow
/// that keeps its particles near a lattice has about this bias.
template <class Kernel>
inline double laminarLatticeRatio(double h, double dp, int dim) {
    const KernelConstants k = makeKernelConstants(h, dp, dim);
    const double eta2 = (0.1 * h) * (0.1 * h);
    const int n = int(std::ceil(2.0 * h / dp));
    double sum = 0;
    for (int i = -n; i <= n; ++i)
        for (int j = (dim == 3 ? -n : 0); j <= (dim == 3 ? n : 0); ++j)
            for (int l = -n; l <= n; ++l) {
                const double x = i * dp, y = j * dp, z = l * dp, r2 = x * x + y * y + z * z;
                if (r2 == 0.0 || r2 > 4.0 * h * h) continue;
                const double f = -double(Kernel::gradFactor(float(r2), k));
                sum += f * z * z * r2 / (r2 + eta2);
            }
    return sum * (dim == 3 ? dp * dp * dp : dp * dp);
}

/// The same for the run's kernel type.
inline double laminarLatticeRatio(KernelType kernel, double h, double dp, int dim) {
    return kernel == KernelType::Cubic ? laminarLatticeRatio<CubicKernel>(h, dp, dim)
                                       : laminarLatticeRatio<WendlandKernel>(h, dp, dim);
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
