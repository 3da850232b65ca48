// SeaSpring — MIT licence.
/// \file engine_checkpoint.h
/// \brief Engine<Exec>'s restart files: saveState writes every state array (forEachStateArray),
///        the solids' sub-cycle clock and the counters; loadState checks that the file was
///        written for this case and set-up (particle, cell and solid counts, each array's size)
///        and reads them back. Included at the end of engine.h.
#pragma once

#include <string>
#include <type_traits>
#include <vector>

#include "core/error.h"
#include "solver/engine.h"

namespace seaspring::solver {

template <class Exec>
void Engine<Exec>::saveState(CheckpointData& out) {
    noForcesAhead("saveState");
    exec_.synchronize();
    forEachStateArray([&](const std::string& name, auto& buf, bool) {
        std::vector<std::remove_pointer_t<decltype(buf.data())>> host;
        copyToHost(buf, host);
        out.putArray("engine/" + name, host);
    });
    if (solid_.n > 0) {
        out.reals["engine/solid_t0"] = solid_.t0;
        out.reals["engine/solid_span"] = solid_.span;
    }
    out.ints["engine/np"] = (long long)(setup_.nbound) + setup_.nfluid;
    out.ints["engine/nbound"] = nbound_;
    out.ints["engine/nfluid_active"] = nfluid_;
    out.ints["engine/nsolid"] = solid_.n;
    out.ints["engine/ncells"] = setup_.grid.cellCount();
    out.ints["engine/sorted"] = sorted_ ? 1 : 0;
    out.ints["engine/divides"] = (long long)counts_.divides;
    out.ints["engine/sorts"] = (long long)counts_.sorts;
    out.ints["engine/boundary_sorts"] = (long long)counts_.boundary_sorts;
    out.ints["engine/merged_sorts"] = (long long)counts_.merged_sorts;
    out.ints["engine/cells_switched"] = cells_switched_ ? 1 : 0;
    out.ints["engine/cell_switch_divide"] = (long long)counts_.cell_switch_divide;
    out.ints["engine/cell_switch_shared"] = (long long)counts_.cell_switch_shared;
    out.ints["engine/cell_switch_fluid"] = (long long)counts_.cell_switch_fluid;
}

template <class Exec>
void Engine<Exec>::loadState(const CheckpointData& in) {
    dropForcesAhead();
    solid_end_checked_ = false;
    row_ext_.bound_done = false;  // the boundary block's positions and cells are the file's
    auto expect = [&](const char* name, long long want) {
        const long long got = in.integer(std::string("engine/") + name);
        if (got != want)
            throw Error(in.source + ": restart file was written for another case or set-up (" + name + " " +
                        std::to_string(got) + ", this run has " + std::to_string(want) + ")");
    };
    // The cells the file's arrays are sorted into (files written before the switch existed: the
    // first ones).
    const bool switched = in.has("engine/cells_switched") && in.integer("engine/cells_switched") != 0;
    if (switched && !setup_.cell_switch.on)
        throw Error(in.source + ": restart file written after its run's cells switched to cells of h, and this "
                                "run has no such switch (a restart continues the same run: give the same options)");
    if (switched != cells_switched_) useCells(switched);
    expect("np", (long long)(setup_.nbound) + setup_.nfluid);
    expect("nbound", nbound_);
    expect("nsolid", solid_.n);
    expect("ncells", setup_.grid.cellCount());
    forEachStateArray([&](const std::string& name, auto& buf, bool same_size) {
        using T = std::remove_pointer_t<decltype(buf.data())>;
        const std::vector<T> host = in.getArray<T>("engine/" + name);
        if (same_size && host.size() != buf.size())
            throw Error(in.source + ": restart array '" + name + "' has " + std::to_string(host.size()) +
                        " elements, this run has " + std::to_string(buf.size()) +
                        " (a run with other options wrote it)");
        assignFrom(buf, host);
    });
    if (solid_.n > 0) {
        solid_.t0 = in.real("engine/solid_t0");
        solid_.span = in.real("engine/solid_span");
    }
    nfluid_ = std::uint32_t(in.integer("engine/nfluid_active"));
    // Particles removed in their slots since the file's last sort (their PosCell is the file's).
    removed_ = nfluid_ == 0u ? 0u
                             : exec_.reduce(nbound_, nbound_ + nfluid_, 0u, RemovedCountPass{p_.poscell.data()},
                                            CountCombine{});
    sorted_ = in.integer("engine/sorted") != 0;
    counts_.divides = (unsigned long long)in.integer("engine/divides");
    counts_.sorts = (unsigned long long)in.integer("engine/sorts");
    // A count only (files written before it was kept have none).
    counts_.boundary_sorts =
        in.has("engine/boundary_sorts") ? (unsigned long long)in.integer("engine/boundary_sorts") : 0ull;
    counts_.merged_sorts = in.has("engine/merged_sorts") ? (unsigned long long)in.integer("engine/merged_sorts") : 0ull;
    auto count = [&](const char* name) {
        const std::string key = std::string("engine/") + name;
        return in.has(key) ? (unsigned long long)in.integer(key) : 0ull;
    };
    counts_.cell_switch_divide = count("cell_switch_divide");
    counts_.cell_switch_shared = count("cell_switch_shared");
    counts_.cell_switch_fluid = count("cell_switch_fluid");
}

}  // namespace seaspring::solver
