// SeaSpring — MIT licence.
/// \file sorted_block.cpp
/// \brief A part file's block sorted as the solver's divide sorts it (see sorted_block.h).
#include "post/sorted_block.h"

#include <algorithm>

namespace seaspring::post {

std::vector<std::uint32_t> appendSortedBlock(const io::PartData& d, const std::vector<std::uint32_t>& members,
                                             const physics::CellGrid& g, int dim, SortedParticles& s, double y2d) {
    const std::size_t n = members.size(), base = s.poscell.size();
    std::vector<std::uint64_t> key(n);
    std::vector<physics::Float4> pc(n);
    for (std::size_t k = 0; k < n; ++k) {
        const std::uint32_t i = members[k];
        const double y = dim == 2 && !std::isnan(y2d) ? y2d : d.pos[3 * i + 1];
        std::uint32_t cell;
        pc[k] = physics::makePosCell(g, physics::Double3{d.pos[3 * i], y, d.pos[3 * i + 2]}, cell);
        key[k] = physics::sortKey(cell, d.id[i], false);
    }
    std::vector<std::uint32_t> order(n);
    for (std::size_t k = 0; k < n; ++k) order[k] = std::uint32_t(k);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
    const std::uint32_t ncell = g.cellCount();
    std::vector<std::uint32_t> cs(std::size_t(ncell) + 1, 0);
    s.poscell.resize(base + n);
    s.velrho.resize(base + n);
    s.index.resize(base + n);
    for (std::size_t k = 0; k < n; ++k) {
        const std::uint32_t o = order[k], i = members[o];
        s.poscell[base + k] = pc[o];
        s.velrho[base + k] = physics::Float4{d.vel[3 * i], d.vel[3 * i + 1], d.vel[3 * i + 2], d.rhop[i]};
        s.index[base + k] = i;
        ++cs[std::size_t(key[o] >> 32) + 1];
    }
    cs[0] = std::uint32_t(base);
    for (std::uint32_t q = 0; q < ncell; ++q) cs[q + 1] += cs[q];
    return cs;
}

}  // namespace seaspring::post
