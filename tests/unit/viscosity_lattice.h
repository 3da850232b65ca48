// SeaSpring — MIT licence.
/// \file viscosity_lattice.h
/// \brief Shared harness of the viscous-flow tests (test_viscosity_channels.cpp,
///        test_viscosity_vortex_sps.cpp): a frozen 2D particle lattice driven by the solver's own
///        pair functions, hand lattice sums, Heun time integration and the x-periodic channel.
///
/// The harness (no periodic boundaries in the solver): particles on a frozen 2D lattice (x, z),
/// h = hdp dp, Wendland, masses rho0 dp^2, density rho0 and pressure zero, a brute-force
/// neighbour list with periodic images, and the solver's own pair functions (fluidPair =
/// fluidPairTerms + addPairTerms, spsTau, makeFluidConstants); the tests only add the body
/// force and a Heun (RK2) time integration with dt = 1/(Gershgorin bound of the operator).
/// Walls: floor(2h/dp) layers of wall particles (kBound pairs) beyond an interface dp/2 from the
/// first fluid row; wall layer k takes 2 v_wall - v(fluid row k, same column).
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <vector>

#include "physics/fluid_constants.h"
#include "physics/fluid_pair_terms.h"
#include "physics/sph_kernels.h"
#include "physics/viscosity.h"

namespace seaspring::test::visc {

using namespace seaspring::physics;

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kRho0 = 1000.0;

/// max(e, x) that keeps a NaN (a blown-up run must fail, not be skipped by std::max).
inline double worse(double e, double x) { return (x > e || std::isnan(x)) ? x : e; }

using OptLam2 = FluidOptions<WendlandKernel, Viscosity::Laminar, DensityDiffusion::None, 2>;
using OptSps2 = FluidOptions<WendlandKernel, Viscosity::LaminarSps, DensityDiffusion::None, 2>;
using OptSps3 = FluidOptions<WendlandKernel, Viscosity::LaminarSps, DensityDiffusion::None, 3>;

/// The fluid constants the solver would make for this lattice (makeFluidConstants): h = hdp dp,
/// masses rho0 dp^dim for fluid and wall, ViscoBoundFactor 1. c0 and B only enter the pressure,
/// which is zero here. `laminar_scale`: LaminarLatticeCorrection's factor (1: DualSPHysics' operator).
inline FluidConstants makeConstants(double dp, double hdp, int dim, double nu, double laminar_scale = 1.0) {
    FluidInputs in;
    in.h = hdp * dp;
    in.dp = dp;
    in.dim = dim;
    in.cs0 = 10.0;
    in.b = 10.0 * 10.0 * kRho0 / 7.0;
    in.rhop0 = kRho0;
    const double vol = dim == 2 ? dp * dp : dp * dp * dp;
    in.massfluid = kRho0 * vol;
    in.massbound = kRho0 * vol;
    in.visco = nu;
    in.visco_bound_factor = 1.0;
    in.laminar_scale = laminar_scale;
    return makeFluidConstants(in);
}

/// Hand lattice sums (double, dp = 1), written from the Wendland formula here rather than
/// taken from the solver: F(r) = -5 aD/h^2 (1 - q/2)^3, aD = 7/(4 pi h^2) (2D) or
/// 21/(16 pi h^3) (3D), over the lattice points b != a with r <= 2h, volume V = 1:
///   grad = -sum F r_z^2                      the SPH gradient of a linear field is grad x this,
///   lap  = -sum F r_z^2 r^2/(r^2 + 0.01 h^2)  the Lo & Shao laminar term of a quadratic field
///          (u = A z^2) is nu (2A) x this, i.e. the operator acts with nu_eff = lap nu.
/// In the continuum both are 1; on the lattice `grad` is 1 - O(1e-3) and `lap` is about 0.985:
/// the eta^2 = 0.01 h^2 regularisation lowers every pair by eta^2/(r^2 + eta^2) (3.8% for a
/// first neighbour at h = 2 dp), which no refinement at fixed h/dp removes.
struct LatticeSums {
    double grad = 0, lap = 0;
};
inline LatticeSums handLatticeSums(double hdp, int dim) {
    const double h = hdp;
    const double ad = dim == 2 ? 7.0 / (4.0 * kPi * h * h) : 21.0 / (16.0 * kPi * h * h * h);
    const int n = int(std::ceil(2.0 * h));
    LatticeSums s;
    for (int i = -n; i <= n; ++i)
        for (int j = (dim == 3 ? -n : 0); j <= (dim == 3 ? n : 0); ++j)
            for (int k = -n; k <= n; ++k) {
                const double r2 = double(i * i + j * j + k * k);
                if (r2 == 0 || r2 > 4.0 * h * h) continue;
                const double q = std::sqrt(r2) / h, w = 1.0 - 0.5 * q;
                const double f = -5.0 * ad / (h * h) * w * w * w;
                s.grad += -f * k * k;
                s.lap += -f * k * k * r2 / (r2 + 0.01 * h * h);
            }
    return s;
}

/// One neighbour of a fluid particle: index into the particle arrays, r_ab = r_a - r_b (of the
/// periodic image), r^2 as the solver forms it (pairOffset).
struct Pair {
    std::uint32_t j;
    float drx, drz, rr2;
};

/// A frozen 2D lattice (x, z; y is the zero dimension as in the solver's 2D): fluid particles
/// [0, nfluid), wall particles after them. Density stays rho0, pressure zero; the fluid
/// particles' accelerations are the solver's pair terms (fluidPair: fluidPairTerms +
/// addPairTerms, the functions the fluid pair loop calls), fluid neighbours first, then wall
/// neighbours (kBound), as fluidParticleForces orders them.
struct Lattice2D {
    FluidConstants c;
    double dp = 0, h = 0;
    std::uint32_t nfluid = 0;
    std::vector<double> x, z;
    std::vector<Float4> velrho;
    std::vector<Float2> press_ovrho;
    std::vector<SymTensor> tau;
    std::vector<std::vector<Pair>> fluid_nb, wall_nb;  ///< per fluid particle

    void add(double px, double pz) {
        x.push_back(px);
        z.push_back(pz);
    }

    /// Neighbours by brute force over all particles and their periodic images (period lx in
    /// x, lz in z; 0: not periodic). Positions are frozen, so the list is built once.
    void buildNeighbours(double lx, double lz) {
        const std::size_t np = x.size();
        velrho.assign(np, Float4{0, 0, 0, float(kRho0)});
        press_ovrho.assign(np, Float2{0.f, float(1.0 / kRho0)});
        tau.assign(np, SymTensor{0, 0, 0, 0, 0, 0});
        fluid_nb.assign(nfluid, {});
        wall_nb.assign(nfluid, {});
        const double rmax = 2.0 * h * (1.0 + 1e-9);
        for (std::uint32_t a = 0; a < nfluid; ++a)
            for (std::uint32_t b = 0; b < np; ++b) {
                const double dx0 = x[a] - x[b], dz0 = z[a] - z[b];
                // Images b + (m lx, n lz) with |dx0 - m lx| <= 2h (and the same in z).
                const int m0 = lx > 0 ? int(std::ceil((dx0 - rmax) / lx)) : 0;
                const int m1 = lx > 0 ? int(std::floor((dx0 + rmax) / lx)) : 0;
                const int n0 = lz > 0 ? int(std::ceil((dz0 - rmax) / lz)) : 0;
                const int n1 = lz > 0 ? int(std::floor((dz0 + rmax) / lz)) : 0;
                for (int m = m0; m <= m1; ++m)
                    for (int n = n0; n <= n1; ++n) {
                        const float drx = float(dx0 - m * lx), drz = float(dz0 - n * lz);
                        const float rr2 = fma32(drx, drx, drz * drz);  // pairOffset<2>
                        if (!isNeighbour(rr2, c)) continue;
                        (b < nfluid ? fluid_nb : wall_nb)[a].push_back(Pair{b, drx, drz, rr2});
                    }
            }
    }

    InteractionInputs inputs() const {
        InteractionInputs in;
        in.velrho = velrho.data();
        in.press_ovrho = press_ovrho.data();
        in.tau = tau.data();
        return in;
    }

    /// The accumulated terms of fluid particle a (FluidAccum: acceleration, gradvel, ...).
    template <class Opt>
    FluidAccum forces(std::uint32_t a) const {
        const InteractionInputs in = inputs();
        const Float4 va = velrho[a];
        const Float2 pa = press_ovrho[a];
        const SymTensor taua = tau[a];
        FluidAccum acc;
        for (const Pair& p : fluid_nb[a])
            fluidPair<Opt, false>(p.j, p.drx, 0.f, p.drz, p.rr2, va, pa.y, pa.x, taua, in, c, acc);
        for (const Pair& p : wall_nb[a])
            fluidPair<Opt, true>(p.j, p.drx, 0.f, p.drz, p.rr2, va, pa.y, pa.x, taua, in, c, acc);
        return acc;
    }

    /// A time step for the explicit integration: 1 / (Gershgorin bound of the laminar
    /// operator's largest eigenvalue, 2 max_a sum_b |cv_ab|), so that lambda dt <= 1 (Heun
    /// is stable to 2).
    double stableDt() const {
        const InteractionInputs in = inputs();
        const SymTensor zero{0, 0, 0, 0, 0, 0};
        double worst = 0;
        for (std::uint32_t a = 0; a < nfluid; ++a) {
            double s = 0;
            const Float4 va = velrho[a];
            for (const Pair& p : fluid_nb[a])
                s += std::fabs(
                    fluidPairTerms<OptLam2, false>(p.j, p.drx, 0.f, p.drz, p.rr2, va, 1e-3f, 0.f, zero, in, c).cv);
            for (const Pair& p : wall_nb[a])
                s += std::fabs(
                    fluidPairTerms<OptLam2, true>(p.j, p.drx, 0.f, p.drz, p.rr2, va, 1e-3f, 0.f, zero, in, c).cv);
            worst = std::max(worst, 2.0 * s);
        }
        return 1.0 / worst;
    }
};

/// State of the explicit integration (double; the solver's pair terms see it as float).
struct Velocities {
    std::vector<double> u, w;
};

/// Heun (RK2) integration of dv/dt = laminar(v) + (gx, 0) from `t` to `t_end` with steps of at
/// most `dt`. `load(state)` writes the state into the lattice's velrho (fluid and walls).
template <class Load>
inline void integrate(Lattice2D& lat, Velocities& v, double& t, double t_end, double dt, double gx, Load load) {
    const std::uint32_t n = lat.nfluid;
    std::vector<double> k1u(n), k1w(n), k2u(n), k2w(n);
    Velocities mid = v;
    auto rates = [&](const Velocities& s, std::vector<double>& ku, std::vector<double>& kw) {
        load(s);
        for (std::uint32_t a = 0; a < n; ++a) {
            const FluidAccum acc = lat.forces<OptLam2>(a);
            ku[a] = double(acc.ax) + gx;
            kw[a] = double(acc.az);
        }
    };
    while (t < t_end * (1 - 1e-12)) {
        const double step = std::min(dt, t_end - t);
        rates(v, k1u, k1w);
        for (std::uint32_t a = 0; a < n; ++a) {
            mid.u[a] = v.u[a] + step * k1u[a];
            mid.w[a] = v.w[a] + step * k1w[a];
        }
        rates(mid, k2u, k2w);
        for (std::uint32_t a = 0; a < n; ++a) {
            v.u[a] += 0.5 * step * (k1u[a] + k2u[a]);
            v.w[a] += 0.5 * step * (k1w[a] + k2w[a]);
        }
        t += step;
    }
}

// ---------------------------------------------------------------------------------------------
// Channel: x-periodic, walls at z = 0 and z = L = nz dp (the interfaces, dp/2 from the first
// and last fluid rows), `layers` rows of wall particles beyond each. Wall layer l of the bottom
// wall (z = -(l + 1/2) dp) is the mirror of fluid row l across z = 0, so it takes the velocity
// 2 v_wall - v(fluid row l, same column); the top wall mirrors row nz - 1 - l across z = L.

struct Channel {
    Lattice2D lat;
    int nx = 0, nz = 0, layers = 0;
    double lz = 0;
    std::vector<std::uint32_t> mirror;  ///< wall particle (index - nfluid) -> fluid particle
    std::vector<bool> top;              ///< wall particle is in the top wall
    double u_top = 0;                   ///< top wall velocity (Couette); bottom wall fixed

    Channel(int nz_, int nx_, double dp, double hdp, double nu, double laminar_scale = 1.0) : nx(nx_), nz(nz_) {
        lat.dp = dp;
        lat.h = hdp * dp;
        lat.c = makeConstants(dp, hdp, 2, nu, laminar_scale);
        lz = nz * dp;
        layers = int(std::floor(2.0 * hdp + 1e-9));  // wall rows within 2h of the first fluid row
        for (int k = 0; k < nz; ++k)
            for (int i = 0; i < nx; ++i) lat.add((i + 0.5) * dp, (k + 0.5) * dp);
        lat.nfluid = std::uint32_t(lat.x.size());
        for (int l = 0; l < layers; ++l)
            for (int i = 0; i < nx; ++i) {
                lat.add((i + 0.5) * dp, -(l + 0.5) * dp);
                mirror.push_back(std::uint32_t(l * nx + i));
                top.push_back(false);
                lat.add((i + 0.5) * dp, lz + (l + 0.5) * dp);
                mirror.push_back(std::uint32_t((nz - 1 - l) * nx + i));
                top.push_back(true);
            }
        lat.buildNeighbours(nx * dp, 0.0);
    }

    double zOfRow(int k) const { return (k + 0.5) * lat.dp; }

    /// Writes fluid velocities and the mirrored wall velocities into velrho.
    void load(const Velocities& v) {
        for (std::uint32_t a = 0; a < lat.nfluid; ++a)
            lat.velrho[a] = Float4{float(v.u[a]), 0.f, float(v.w[a]), float(kRho0)};
        for (std::size_t q = 0; q < mirror.size(); ++q) {
            const std::uint32_t f = mirror[q];
            const double vw = top[q] ? u_top : 0.0;
            lat.velrho[lat.nfluid + q] = Float4{float(2.0 * vw - v.u[f]), 0.f, float(-v.w[f]), float(kRho0)};
        }
    }

    /// Row profile (column 0) and the largest difference between columns of a row (the flow
    /// is x-invariant: a check on the periodic harness).
    std::vector<double> profile(const Velocities& v, double* column_spread = nullptr) const {
        std::vector<double> p(nz);
        double spread = 0;
        for (int k = 0; k < nz; ++k) {
            p[k] = v.u[std::size_t(k) * nx];
            for (int i = 1; i < nx; ++i) spread = worse(spread, std::fabs(v.u[std::size_t(k) * nx + i] - p[k]));
        }
        if (column_spread) *column_spread = spread;
        return p;
    }
};

/// Wall-clock seconds since t0 (the tests print their run time).
inline double seconds(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace seaspring::test::visc
