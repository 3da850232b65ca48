// SeaSpring — MIT licence.
/// \file neighbour_list_store.h
/// \brief The arrays of the fluid particles' neighbour list (-nlist, physics/neighbour_list.h)
///        and their build, written once for both backends (`Buf` is the container: host
///        std::vector or cuda::DeviceBuffer, buffers.h). The engine asks for a build after every
///        sort and whenever the divide's refresh pass finds the list stale.
#pragma once

#include <algorithm>
#include <cstdint>

#include "physics/neighbour_list.h"
#include "solver/backend.h"
#include "solver/buffers.h"
#include "solver/launch.h"
#include "solver/particle_passes.h"

namespace seaspring::solver {

template <template <typename> class Buf>
struct NeighbourListStore {
    bool on = false;      ///< the run uses a list
    bool valid = false;   ///< the list matches the current sort and positions
    std::uint32_t first = 0, stride = 0, cap = 0;
    float skin = 0;       ///< list skin [m]
    Buf<std::uint32_t> nb, count;
    Buf<physics::Float4> pos0;
    std::uint64_t builds = 0;

    /// Set-up for `nfluid` fluid particles after `nbound` boundary ones (no arrays without a list).
    void init(const BackendSetup& s) {
        on = s.list_skin > 0.0;
        valid = false;
        builds = 0;
        first = s.nbound;
        stride = s.nfluid;
        cap = 0;
        skin = float(s.list_skin * s.grid.cellsize);
        nb = Buf<std::uint32_t>();
        count = Buf<std::uint32_t>();
        pos0 = Buf<physics::Float4>();
        if (!on || stride == 0) {
            on = false;
            return;
        }
        count.resize(stride);
        pos0.resize(stride);
    }

    /// The physics view (nb null while there is no valid list).
    physics::NeighbourList view(const physics::FluidConstants& c) {
        physics::NeighbourList l;
        if (!on) return l;
        l.nb = cap > 0 ? nb.data() : nullptr;
        l.count = count.data();
        l.pos0 = pos0.data();
        l.first = first;
        l.stride = stride;
        l.cap = cap;
        physics::setListRadius(l, c, skin);
        return l;
    }

    /// The view the divide's refresh pass tests for staleness (none while no list is valid).
    physics::NeighbourList staleTest(const physics::FluidConstants& c) {
        return valid ? view(c) : physics::NeighbourList{};
    }

    /// Builds the lists of the active fluid particles [first, first + nfluid) from the sorted
    /// fluid block; grows the arrays (10% and 8 entries to spare) and builds again when a
    /// particle has more entries than they hold.
    template <class Exec>
    void build(const Exec& exec, const physics::Float4* poscell, const std::uint32_t* cell_start_fluid,
               const physics::FluidConstants& c, const physics::CellGrid& g, int dim, std::uint32_t nfluid) {
        if (!on) return;
        for (;;) {
            physics::NeighbourList l = view(c);
            l.nb = nb.data();  // cap 0: nothing stored, only counted
            if (dim == 2)
                exec.template forEach<LaunchFluidPairs>(first, first + nfluid,
                                                        NeighbourListPass<2>{l, poscell, cell_start_fluid, c, g});
            else
                exec.template forEach<LaunchFluidPairs>(first, first + nfluid,
                                                        NeighbourListPass<3>{l, poscell, cell_start_fluid, c, g});
            const std::uint32_t most =
                nfluid > 0 ? exec.reduce(first, first + nfluid, 0u, ListCountPass{count.data(), first}, MaxU32Combine{})
                           : 0u;
            if (most <= cap && cap > 0) break;
            cap = std::max<std::uint32_t>(8u, (most + most / 10u + 8u + 7u) / 8u * 8u);
            nb.resize(std::size_t(cap) * stride);
        }
        valid = true;
        ++builds;
    }
};

}  // namespace seaspring::solver
