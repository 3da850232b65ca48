// SeaSpring — MIT licence.
/// \file gauge_arrays.h
/// \brief The gauges' arrays of a backend (the queries of solver/gauge_system.h and their
///        answers) and how they are answered from the sorted particle arrays: the gauge passes
///        of particle_passes.h run by the execution policy. Written once for both backends
///        (`Buf`: std::vector or cuda::DeviceBuffer).
#pragma once

#include <cstdint>
#include <vector>

#include "physics/particle_fields.h"
#include "solver/backend.h"
#include "solver/buffers.h"
#include "solver/force_passes.h"
#include "solver/launch.h"
#include "solver/particle_passes.h"

namespace seaspring::solver {

template <template <typename> class Buf>
struct GaugeArrays {
    Buf<physics::Float4> points;        ///< PosCell of each kernel-sum point
    Buf<physics::MaxzRow> rows;         ///< rows of cells of the maxz gauges
    Buf<physics::GaugeSample> samples;  ///< answers, query order
    Buf<double> maxz;
    Buf<physics::Double3> positions;    ///< of the particles asked for by id
    Buf<std::uint32_t> slot_of_id;      ///< per boundary id, its slot in `positions`
    std::uint32_t nids = 0;

    /// The queries of a run (after init; `nbound` boundary particles).
    void set(const GaugeQueries& q, std::uint32_t nbound) {
        assignFrom(points, q.points);
        assignFrom(rows, q.maxz_rows);
        samples.resize(q.points.size());
        maxz.resize(q.maxz_rows.size());
        assignFrom(positions, std::vector<physics::Double3>(q.ids.size(), physics::Double3{0, 0, 0}));
        nids = std::uint32_t(q.ids.size());
        if (nids > 0) assignFrom(slot_of_id, gaugeSlotsOfIds(q.ids, nbound));
    }

    /// The answers for the sorted state `v` (fluid cell ranges `cs_fluid`), into `out`.
    template <class Exec>
    void answer(const Exec& exec, const BackendSetup& setup, const std::uint32_t* cs_fluid,
                const physics::ParticleView& v, std::uint32_t nbound, GaugeResults& out) {
        const std::uint32_t npts = std::uint32_t(points.size()), nrows = std::uint32_t(rows.size());
        dispatchKernelDim(setup.physics, [&](auto kernel, auto dim) {
            constexpr int kDim = decltype(dim)::value;
            exec.template forEach<LaunchGauges>(
                0u, npts,
                GaugeSamplePass<decltype(kernel), kDim>{points.data(), cs_fluid, v.poscell, v.velrho, setup.fluid,
                                                        setup.grid, samples.data()});
            exec.template forEach<LaunchGauges>(
                0u, nrows, MaxzRowPass<kDim>{rows.data(), cs_fluid, v.pos, v.poscell, maxz.data()});
        });
        if (nids > 0)
            exec.template forEach<LaunchGauges>(0u, nbound,
                                                GaugePositionPass{v.id, v.pos, slot_of_id.data(), positions.data()});
        copyToHost(samples, out.samples);
        copyToHost(maxz, out.maxz);
        copyToHost(positions, out.positions);
    }
};

}  // namespace seaspring::solver
