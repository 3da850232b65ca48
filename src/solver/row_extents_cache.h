// SeaSpring — MIT licence.
/// \file row_extents_cache.h
/// \brief The engine's row extents (physics/row_extents.h): their memory and when the passes
///        that fill them run.
///        - The host: both blocks' at every force evaluation, for its row tables.
///        - The GPU, fluid block: at every force evaluation (RowExtentsPass, a warp per row,
///          in the pressures' launch), for the fluid and boundary particles' walks of that block
///          (physics/fluid_interaction.h, kExt). NVIDIA H200, against the cell walk: SPHERIC
///          4.36 M and 13.29 M 0.86, laminar+SPS 0.92, FlexStruc Liao 3D 0.94, a disordered
///          flow 1.01–1.02 (docs/performance-large.md, twenty-eighth session).
///        - The GPU, boundary block: for its walk of that block where the walls are fixed, once
///          after the first sort or a restart. With moving boundaries or solids the GPU takes
///          none (a pass at every evaluation cost more than the walk saved: FlexStruc Liao 3D
///          1.029; twenty-seventh session).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

#include "physics/row_extents.h"
#include "solver/launch.h"
#include "solver/particle_passes.h"

namespace seaspring::solver {

/// Items of a pass with `lanes` threads per row of cells of `g` (rows x lanes): a launch indexes
/// them with 32 bits, so a grid with more is refused (std::length_error naming its rows) rather
/// than leaving rows without extents.
inline std::uint32_t rowLaneItems(const physics::CellGrid& g, std::uint32_t lanes) {
    const std::uint64_t n = std::uint64_t(g.ncy) * std::uint64_t(g.ncz) * lanes;
    if (n > 0xffffffffull)
        throw std::length_error("the grid's " + std::to_string(g.ncy) + " x " + std::to_string(g.ncz) +
                                " rows of cells times " + std::to_string(lanes) +
                                " threads per row exceed a launch's 2^32 indices (a coarser -cellmode or a "
                                "smaller domain in y and z)");
    return std::uint32_t(n);
}

template <class Exec>
struct RowExtentsCache {
    typename Exec::template Buffer<float> data;   ///< the host's (both blocks) or the GPU's boundary block's
    typename Exec::template Buffer<float> fluid;  ///< the GPU's fluid block's
    bool bound_done = false;  ///< the GPU's boundary extents hold (reset by a restart)

    /// The GPU's threads per row in fluidPass (a warp: the threads joining a row's shares).
    static constexpr std::uint32_t kRowLanes = 32;

    /// The GPU's fluid-block extents of this evaluation (none on the host): their memory, which
    /// fluidPass fills before the pair loops read it.
    physics::RowExtents fluidExtents(const physics::CellGrid& g) {
        if constexpr (Exec::kCompactPairs) {
            return physics::RowExtents{};
        } else {
            fluid.resize(6 * std::size_t(physics::rowExtentStride(g)));
            return physics::rowExtentsIn(fluid.data(), g);
        }
    }
    /// Items of fluidPass (0 on the host: nothing to run).
    static std::uint32_t fluidItems(const physics::CellGrid& g) {
        return Exec::kCompactPairs ? 0u : rowLaneItems(g, kRowLanes);
    }
    /// The pass that fills fluidExtents' memory from the fluid block (cell starts `cs_fluid`).
    RowExtentsPass fluidPass(const physics::CellGrid& g, const std::uint32_t* cs_fluid,
                             const physics::Float4* poscell) {
        return RowExtentsPass{g, cs_fluid, nullptr, poscell, fluid.data(), kRowLanes};
    }

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
                                                 RowExtentsPass{g, first, second, poscell, data.data(), 1u});
            bound_done = true;
        }
        return physics::rowExtentsIn(data.data(), g);
    }
};

}  // namespace seaspring::solver
