// SeaSpring — MIT licence.
/// \file cpu_forces_impl.h
/// \brief The OpenMP force driver for one option set: one loop over boundary particles, one
///        over fluid particles, each calling the shared per-particle interaction; then the SPS
///        stress and the dt maxima (max is exact, so the reduction order does not matter).
#pragma once

#include <omp.h>

#include "cpu/cpu_backend.h"
#include "physics/fluid_interaction.h"
#include "physics/particle_updates.h"
#include "physics/solid_coupling.h"

namespace seaspring::cpu {

inline physics::InteractionInputs interactionInputs(CpuArrays& a, bool sps) {
    physics::InteractionInputs in;
    in.poscell = a.poscell.data();
    in.velrho = a.velrho.data();
    in.cell_start_bound = a.cell_start_bound.data();
    in.cell_start_fluid = a.cell_start_fluid.data();
    in.tau = sps ? a.tau.data() : nullptr;
    in.press_ovrho = a.press_ovrho.data();
    in.bound_near = a.bound_near.empty() ? nullptr : a.bound_near.data();
    return in;
}

/// The hydrodynamic force on boundary particles: out[s] for sorted index slot[s] (the solid
/// particles), or for sorted index s when `slot` is null (the whole boundary block [0, n)),
/// from press_ovrho and tau as the last pressure pass left them.
template <class Opt>
void cpuHydroForcesFor(CpuArrays& a, const std::uint32_t* slot, std::uint32_t n, physics::Double3* out,
                       const physics::FluidConstants& c, const physics::CellGrid& g) {
    const physics::InteractionInputs in = interactionInputs(a, Opt::sps);
#pragma omp parallel for schedule(dynamic, 64)
    for (std::int64_t s = 0; s < std::int64_t(n); ++s)
        out[s] = physics::hydroForceOnBoundary<Opt>(slot ? slot[s] : std::uint32_t(s), in, c, g);
}

template <class Opt>
physics::DtMaxima cpuForcesFor(CpuArrays& a, std::uint32_t nbound, std::uint32_t nfluid,
                               const physics::FluidConstants& c, const physics::CellGrid& g) {
    using namespace physics;
    const InteractionInputs in = interactionInputs(a, Opt::sps);
    const std::int64_t nb = nbound, np = std::int64_t(nbound) + nfluid;
    const ParticleView v = a.view();
#pragma omp parallel
    {
#pragma omp for schedule(static)
        for (std::int64_t i = 0; i < np; ++i) pressureAt(std::uint32_t(i), v, c);
#pragma omp for schedule(dynamic, 512) nowait
        for (std::int64_t i = 0; i < nb; ++i) {
            float ar, visc;
            boundParticleForces<Opt, true>(std::uint32_t(i), in, c, g, ar, visc);
            a.acear[i] = Float4{0.f, 0.f, 0.f, ar};
            a.visc[i] = visc;
        }
#pragma omp for schedule(dynamic, 256)
        for (std::int64_t i = nb; i < np; ++i) {
            const FluidAccum acc = fluidParticleForces<Opt, true>(std::uint32_t(i), in, c, g);
            a.acear[i] = Float4{acc.ax, acc.ay, acc.az, acc.ar};
            a.visc[i] = acc.visc;
            if (Opt::sps) a.gradvel[i] = acc.gradvel;
        }
    }
    if (Opt::sps) {
        // The stress for the next evaluation (DualSPHysics lags it by one evaluation).
#pragma omp parallel for schedule(static)
        for (std::int64_t i = nb; i < np; ++i) spsTauAt(std::uint32_t(i), v, c.sps_smag, c.sps_blin);
    }
    DtMaxima total;
#pragma omp parallel
    {
        DtMaxima local;
#pragma omp for schedule(static) nowait
        for (std::int64_t i = 0; i < np; ++i)
            local = combineDtMaxima(local, dtMaximaAt(std::uint32_t(i), nbound, v, c.dt_all_particles != 0));
#pragma omp critical
        total = combineDtMaxima(total, local);
    }
    return total;
}

}  // namespace seaspring::cpu
