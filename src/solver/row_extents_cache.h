// SeaSpring — MIT licence.
/// \file row_extents_cache.h
/// \brief The engine's row extents (physics/row_extents.h): their memory and when the pass that
///        fills them runs. On the host both blocks' at every force evaluation, for its row
///        tables; on the GPU the boundary block's, for its walk of that block, where the walls
///        are fixed: once after the first sort or a restart. With moving boundaries or solids the
///        GPU takes none (a pass at every evaluation cost more than the walk saved: FlexStruc Liao
///        3D 1.029 on an NVIDIA H200; docs/performance-large.md, twenty-seventh session).
#pragma once

#include <cstdint>

#include "physics/row_extents.h"
#include "solver/launch.h"
#include "solver/particle_passes.h"

namespace seaspring::solver {

template <class Exec>
struct RowExtentsCache {
    typename Exec::template Buffer<float> data;
    bool bound_done = false;  ///< the GPU's boundary extents hold (reset by a restart)

    /// The extents this force evaluation's pair loops read (none: the GPU with moving walls).
    physics::RowExtents update(Exec& exec, const physics::CellGrid& g, const std::uint32_t* cs_fluid,
                               const std::uint32_t* cs_bound, const physics::Float4* poscell, bool movers) {
        constexpr bool kHost = Exec::kCompactPairs;
        if (!kHost && movers) return physics::RowExtents{};
        if (kHost || !bound_done) {
            data.resize(6 * std::size_t(physics::rowExtentStride(g)));
            const std::uint32_t* first = kHost ? cs_fluid : cs_bound;  // the host: both blocks
            const std::uint32_t* second = kHost ? cs_bound : nullptr;
            exec.template forEach<LaunchDefault>(0u, std::uint32_t(g.ncy) * std::uint32_t(g.ncz),
                                                 RowExtentsPass{g, first, second, poscell, data.data()});
            bound_done = true;
        }
        return physics::rowExtentsIn(data.data(), g);
    }
};

}  // namespace seaspring::solver
