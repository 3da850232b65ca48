// SeaSpring — MIT licence.
/// \file force_passes_impl.h
/// \brief The definitions of force_passes.h: the pair-loop functors (each calls one function of
///        physics/fluid_interaction.h or physics/solid_coupling.h) and the run-time to
///        compile-time option dispatch. Included only by the generated per-option units.
#pragma once

#include "core/lane_group.h"
#include "physics/fluid_interaction.h"
#include "physics/solid_coupling.h"
#include "solver/force_passes.h"
#include "solver/launch.h"
#include "solver/particle_passes.h"

namespace seaspring::solver {

/// Writes fluid particle i's completed sums.
template <class Opt>
SEASPRING_HD inline void writeFluidAccum(const physics::ParticleView& v, std::uint32_t i, const physics::FluidAccum& acc) {
    v.acear[i] = physics::Float4{acc.ax, acc.ay, acc.az, acc.ar};
    v.visc[i] = acc.visc;
    if (Opt::sps) v.gradvel[i] = acc.gradvel;
}

/// Fluid particle i: all its pairs, every pair lane in one call, in the batched form (the
/// host's path; the GPU's is FluidLanesPass, same bits).
template <class Opt>
struct FluidForcesPass {
    ForceArgs a;
    SEASPRING_HOST_FLATTEN SEASPRING_HD void operator()(std::uint32_t i) const {
        writeFluidAccum<Opt>(a.v, i, physics::fluidParticleForces<Opt, true>(i, a.in, a.c, a.g, a.lanes));
    }
};

/// The GPU's fluid loop takes each row's neighbours of the fluid block from a bit mask (physics::
/// fluidPairsInRowMasked) for the laminar families: their pair arithmetic (about 120
/// instructions with SPS) is large enough for the extra offset per pair to pay where the
/// threads of a warp find their neighbours at different candidate steps; with artificial
/// viscosity, and for the boundary block, the direct loop stays (docs/performance-large.md,
/// sixteenth and twentieth sessions).
template <class Opt>
constexpr bool kMaskedRows = Opt::visco != physics::Viscosity::Artificial;

/// One pair lane of a fluid particle (the GPU's path): index k of [0, nfluid * lanes) is lane
/// k mod lanes of fluid particle nbound + k / lanes. A particle's lanes are consecutive threads
/// of one warp (the launch's indices start at 0, its blocks are whole warps and lanes divide
/// 32), which combine their partial sums (combineAcrossLanes: the tree of
/// physics::combineLanes); the first lane writes. kMask: each row's neighbours found into a
/// bit mask first (physics::fluidPairsInRowMasked; the same bits), by default for the laminar
/// families (kMaskedRows).
template <class Opt, bool kMask = kMaskedRows<Opt>>
struct FluidLanesPass {
    ForceArgs a;
    SEASPRING_HD void operator()(std::uint32_t k) const {
        const std::uint32_t lane = k & (a.lanes - 1u);
        const std::uint32_t i = a.nbound + (k >> a.lane_shift);
        physics::FluidAccum acc = physics::fluidLanePartial<Opt, kMask, true>(i, lane, a.lanes, a.in, a.c, a.g);
        acc = combineAcrossLanes(acc, a.lanes, physics::CombineLanePair<Opt>{});
        if (lane != 0u) return;
        physics::finishFluidAccum<Opt>(acc);
        writeFluidAccum<Opt>(a.v, i, acc);
    }
};

/// DBC boundary particle i: continuity and the viscous dt measure.
template <class Opt, bool kCompact>
struct BoundForcesPass {
    ForceArgs a;
    SEASPRING_HOST_FLATTEN SEASPRING_HD void operator()(std::uint32_t i) const {
        float ar, visc;
        physics::boundParticleForces<Opt, kCompact, !kCompact>(i, a.in, a.c, a.g, ar, visc);
        a.v.acear[i] = physics::Float4{0.f, 0.f, 0.f, ar};
        a.v.visc[i] = visc;
    }
};

/// The hydrodynamic force on boundary particle slot[s] (or s).
template <class Opt>
struct HydroForcePass {
    ForceArgs a;
    const std::uint32_t* slot;
    physics::Double3* out;
    SEASPRING_HD void operator()(std::uint32_t s) const {
        out[s] = physics::hydroForceOnBoundary<Opt>(slot ? slot[s] : s, a.in, a.c, a.g);
    }
};

/// Index i < nbound: boundary particle i; else the hydrodynamic force of slot i - nbound
/// (one range, so that both run in the boundary loop's launch).
template <class BoundPass, class HydroPass>
struct BoundThenHydroPass {
    BoundPass bound;
    HydroPass hydro;
    std::uint32_t nbound;
    SEASPRING_HOST_FLATTEN SEASPRING_HD void operator()(std::uint32_t i) const {
        if (i < nbound) bound(i);
        else hydro(i - nbound);
    }
};

/// mDBC boundary particle i (physics::mdbcBoundaryAt), then its pressure (physics::pressureAt).
template <class Kernel, int kDim>
struct MdbcPass {
    physics::ParticleView v;
    physics::MdbcInputs in;
    physics::SlipMode slip;
    physics::FluidConstants c;
    physics::MdbcConstants m;
    physics::CellGrid g;
    SEASPRING_HD void operator()(std::uint32_t i) const {
        physics::mdbcBoundaryAt<Kernel, kDim>(i, v, in, slip, c, m, g);
        physics::pressureAt(i, v, c);
    }
};

/// Calls f(FluidOptions<...>{}) for the run's viscosity and density diffusion.
template <class Kernel, int kDim, class F>
void dispatchViscoDdt(const PhysicsChoice& c, F&& f) {
    using physics::DensityDiffusion;
    using physics::FluidOptions;
    using physics::Viscosity;
    auto ddt = [&](auto visco) {
        constexpr Viscosity kV = decltype(visco)::value;
        switch (c.ddt) {
            case DensityDiffusion::None: f(FluidOptions<Kernel, kV, DensityDiffusion::None, kDim>{}); break;
            case DensityDiffusion::Molteni: f(FluidOptions<Kernel, kV, DensityDiffusion::Molteni, kDim>{}); break;
            case DensityDiffusion::Fourtakas: f(FluidOptions<Kernel, kV, DensityDiffusion::Fourtakas, kDim>{}); break;
            case DensityDiffusion::FourtakasFull:
                f(FluidOptions<Kernel, kV, DensityDiffusion::FourtakasFull, kDim>{});
                break;
        }
    };
    switch (c.visco) {
        case Viscosity::Artificial: ddt(std::integral_constant<Viscosity, Viscosity::Artificial>{}); break;
        case Viscosity::LaminarSps: ddt(std::integral_constant<Viscosity, Viscosity::LaminarSps>{}); break;
        case Viscosity::Laminar: ddt(std::integral_constant<Viscosity, Viscosity::Laminar>{}); break;
    }
}

/// Calls f(FluidOptions<Kernel, visco, None, kDim>{}) for the run's viscosity (the hydrodynamic
/// force does not read the density diffusion).
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

template <class Exec, class Kernel, int kDim>
void ForcePasses<Exec, Kernel, kDim>::pairs(const Exec& exec, const PhysicsChoice& choice, const ForceArgs& a) {
    using physics::DensityDiffusion;
    using physics::FluidOptions;
    using physics::Viscosity;
    constexpr bool kCompact = Exec::kCompactPairs;
    // The boundary loop reads only the kernel and the dimension. The two loops are independent
    // (each writes its own particles' acear and visc; both read the pressure pass's results). On
    // the CPU the threads that finish their share of the (uneven) boundary loop go on to the fluid.
    using BoundOpt = FluidOptions<Kernel, Viscosity::Artificial, DensityDiffusion::None, kDim>;
    // The fluid loop: the host takes a particle per call (all its pair lanes), the GPU a lane per
    // thread over [0, nfluid * lanes).
    const std::uint32_t fb = kCompact ? a.nbound : 0u;
    const std::uint32_t fe = kCompact ? a.np : (a.np - a.nbound) << a.lane_shift;
    dispatchViscoDdt<Kernel, kDim>(choice, [&](auto opt) {
        using Opt = decltype(opt);
        using FluidPass = std::conditional_t<kCompact, FluidForcesPass<Opt>, FluidLanesPass<Opt>>;
        const FluidPass fluid{a};
        const BoundForcesPass<BoundOpt, kCompact> bound{a};
        if (a.nhydro == 0) {
            exec.template forEachIndependent<LaunchBoundPairs, LaunchFluidPairs>(0u, a.nbound, bound, fb, fe, fluid);
        } else {
            using HydroOpt = FluidOptions<Kernel, Opt::visco, DensityDiffusion::None, kDim>;
            const BoundThenHydroPass<BoundForcesPass<BoundOpt, kCompact>, HydroForcePass<HydroOpt>> both{
                bound, HydroForcePass<HydroOpt>{a, a.hydro_slot, a.hydro_out}, a.nbound};
            exec.template forEachIndependent<LaunchBoundPairs, LaunchFluidPairs>(0u, a.nbound + a.nhydro, both, fb,
                                                                                 fe, fluid);
        }
    });
}

template <class Exec, class Kernel, int kDim>
void ForcePasses<Exec, Kernel, kDim>::hydro(const Exec& exec, const PhysicsChoice& choice, const ForceArgs& a,
                                            const std::uint32_t* slot, std::uint32_t n, physics::Double3* out) {
    if (n == 0) return;
    dispatchVisco<Kernel, kDim>(choice, [&](auto opt) {
        exec.template forEach<LaunchHydro>(0u, n, HydroForcePass<decltype(opt)>{a, slot, out});
    });
}

template <class Exec, class Kernel, int kDim>
void ForcePasses<Exec, Kernel, kDim>::mdbcAndPressure(const Exec& exec, physics::SlipMode slip, const ForceArgs& a,
                                                      const physics::MdbcInputs& in, const physics::MdbcConstants& m) {
    exec.template forEachIndependent<LaunchBoundPairs, LaunchFluidPairs>(
        0u, a.nbound, MdbcPass<Kernel, kDim>{a.v, in, slip, a.c, m, a.g}, a.nbound, a.np, PressurePass{a.v, a.c});
}

}  // namespace seaspring::solver
