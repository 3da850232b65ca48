// SeaSpring — MIT licence.
/// \file gauge_arrays.h
/// \brief The gauges' arrays of a backend (the queries of solver/gauge_system.h and their
///        answers) and how they are answered from the sorted particle arrays: the gauge passes
///        of particle_passes.h run by the execution policy. Written once for both backends
///        (`Buf`: std::vector or cuda::DeviceBuffer).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "physics/particle_fields.h"
#include "solver/backend.h"
#include "solver/buffers.h"
#include "solver/force_passes.h"
#include "solver/launch.h"
#include "solver/particle_passes.h"

namespace seaspring::solver {

/// The gauges' queries placed on a cell grid: each point's PosCell (its cell clamped to the
/// grid: reads stay in it), and the rows of cells of each maxz column, column k's rows being
/// [row_first[k], row_first[k + 1]). Host code; the backends answer from these (GaugeArrays),
/// and place them again when their cells change (BackendSetup::cell_switch).
struct GaugeCells {
    std::vector<physics::Float4> points;
    std::vector<physics::MaxzRow> rows;
    std::vector<std::uint32_t> row_first;
};
inline GaugeCells gaugeCellsOn(const GaugeQueries& q, const physics::CellGrid& g, int dim) {
    GaugeCells r;
    for (const physics::Double3& p : q.points) {
        std::uint32_t cell;
        r.points.push_back(physics::makePosCell(g, p, cell));
    }
    r.row_first.push_back(0u);
    for (const MaxzColumn& c : q.columns) {
        int x0, y0, z0, x1, y1, z1;
        physics::cellOf(g, c.lo, x0, y0, z0);
        physics::cellOf(g, c.hi, x1, y1, z1);
        if (g.skinf > 0.f) {  // a particle may lie up to the skin (< 1 cell) outside its cell
            x0 = std::max(x0 - 1, 0), y0 = std::max(y0 - 1, 0), z0 = std::max(z0 - 1, 0);
            x1 = std::min(x1 + 1, g.ncx - 1), y1 = std::min(y1 + 1, g.ncy - 1), z1 = std::min(z1 + 1, g.ncz - 1);
        }
        if (dim == 2) y0 = y1 = 0;
        for (int z = z0; z <= z1; ++z)
            for (int y = y0; y <= y1; ++y) r.rows.push_back(physics::MaxzRow{g.linear(0, y, z), x0, x1, c.lx, c.ly, c.r2});
        r.row_first.push_back(std::uint32_t(r.rows.size()));
    }
    return r;
}

template <template <typename> class Buf>
struct GaugeArrays {
    Buf<physics::Float4> points;        ///< PosCell of each kernel-sum point
    Buf<physics::MaxzRow> rows;         ///< rows of cells of the maxz gauges
    Buf<physics::GaugeSample> samples;  ///< answers, query order
    Buf<double> maxz;                   ///< per row
    Buf<physics::Double3> positions;    ///< of the particles asked for by id
    Buf<std::uint32_t> slot_of_id;      ///< per boundary id, its slot in `positions`
    std::uint32_t nids = 0;
    GaugeQueries queries;               ///< as set (placed again by regrid)
    std::vector<std::uint32_t> row_first;  ///< column k's rows: [row_first[k], row_first[k + 1])
    std::vector<double> maxz_host;      ///< the rows' answers, reduced to the columns'
    int dim = 3;
    bool any = false;

    /// The queries of a run (after init; `nbound` boundary particles), placed on grid `g`.
    void set(const GaugeQueries& q, std::uint32_t nbound, const physics::CellGrid& g, int dimensions) {
        queries = q;
        dim = dimensions;
        any = true;
        regrid(g);
        samples.resize(q.points.size());
        assignFrom(positions, std::vector<physics::Double3>(q.ids.size(), physics::Double3{0, 0, 0}));
        nids = std::uint32_t(q.ids.size());
        if (nids > 0) assignFrom(slot_of_id, gaugeSlotsOfIds(q.ids, nbound));
    }
    /// The queries placed on grid `g` (the backend's cells changed; nothing set: nothing to do).
    void regrid(const physics::CellGrid& g) {
        if (!any) return;
        const GaugeCells c = gaugeCellsOn(queries, g, dim);
        assignFrom(points, c.points);
        assignFrom(rows, c.rows);
        maxz.resize(c.rows.size());
        row_first = c.row_first;
    }

    /// The answers for the sorted state `v` (fluid cell ranges `cs_fluid`), into `out`.
    template <class Exec>
    void answer(const Exec& exec, const BackendConfig& setup, const std::uint32_t* cs_fluid,
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
        copyToHost(maxz, maxz_host);
        out.maxz.assign(row_first.empty() ? 0u : row_first.size() - 1u, -1e300);  // none in reach: -1e300
        for (std::size_t k = 0; k + 1 < row_first.size(); ++k)
            for (std::uint32_t r = row_first[k]; r < row_first[k + 1]; ++r) out.maxz[k] = std::max(out.maxz[k], maxz_host[r]);
        copyToHost(positions, out.positions);
    }
};

}  // namespace seaspring::solver
