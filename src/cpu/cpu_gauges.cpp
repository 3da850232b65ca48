// SeaSpring — MIT licence.
/// \file cpu_gauges.cpp
/// \brief OpenMP driver of the gauge measurements (physics/gauges.h).
#include "cpu/cpu_gauges.h"

#include "physics/gauges.h"
#include "physics/sph_kernels.h"

namespace seaspring::cpu {

namespace {

template <class Kernel, int kDim>
void samplesFor(const CpuArrays& a, const solver::GaugeQueries& q, const physics::FluidConstants& c,
                const physics::CellGrid& g, solver::GaugeResults& out) {
    const std::int64_t n = std::int64_t(q.points.size());
#pragma omp parallel for schedule(static)
    for (std::int64_t k = 0; k < n; ++k)
        out.samples[k] = physics::gaugeSampleAt<Kernel, kDim>(q.points[k], a.cell_start_fluid.data(),
                                                             a.poscell.data(), a.velrho.data(), c, g);
    const std::int64_t nr = std::int64_t(q.maxz_rows.size());
#pragma omp parallel for schedule(static)
    for (std::int64_t k = 0; k < nr; ++k)
        out.maxz[k] = physics::maxzRowAt<kDim>(q.maxz_rows[k], a.cell_start_fluid.data(), a.pos.data());
}

}  // namespace

void cpuGauges(const solver::PhysicsChoice& choice, const CpuArrays& a, std::uint32_t nbound,
               const solver::GaugeQueries& q, const std::vector<std::uint32_t>& slot_of_id,
               const physics::FluidConstants& c, const physics::CellGrid& g, solver::GaugeResults& out) {
    out.samples.assign(q.points.size(), physics::GaugeSample{});
    out.maxz.assign(q.maxz_rows.size(), -1e300);
    out.positions.assign(q.ids.size(), physics::Double3{0, 0, 0});
    const bool wendland = choice.kernel == physics::KernelType::Wendland;
    if (choice.dim == 3) {
        if (wendland) samplesFor<physics::WendlandKernel, 3>(a, q, c, g, out);
        else samplesFor<physics::CubicKernel, 3>(a, q, c, g, out);
    } else {
        if (wendland) samplesFor<physics::WendlandKernel, 2>(a, q, c, g, out);
        else samplesFor<physics::CubicKernel, 2>(a, q, c, g, out);
    }
    if (q.ids.empty()) return;
    for (std::uint32_t i = 0; i < nbound; ++i)
        physics::gaugePositionAt(i, a.id.data(), a.pos.data(), slot_of_id.data(), out.positions.data());
}

}  // namespace seaspring::cpu
