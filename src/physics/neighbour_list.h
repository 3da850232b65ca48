// SeaSpring — MIT licence.
/// \file neighbour_list.h
/// \brief The fluid particles' neighbour list (option -nlist): the fluid-block candidates of
///        each fluid particle within 2h + a list skin, kept across force evaluations while no
///        particle has moved half the list skin since it was built.
///
/// Order and exactness. In a block sorted by (cell, id), forEachCandidateRow visits rows by z
/// then y and, inside a row, a contiguous index range: the fluid neighbours of a particle are
/// visited in ascending index order. The list holds the candidates within sqrt(r2) in that
/// order, and a force evaluation applies the same exact test (isNeighbour) to each entry, with
/// the offset computed by the same operations as the row walk (listedPairOffset = pairOffset in
/// the row frame of the candidate's cell). So a list that holds every neighbour gives the row
/// walk's sums bit for bit: the state hashes do not depend on the option.
///
/// A list holds every neighbour while every particle stays within half the list skin s of where
/// it was at the build: a pair out of the list was farther than 2h + s apart, and two moves of
/// less than s/2 bring it no closer than 2h. listStaleAt tests 0.495 s (1% left for rounding:
/// the positions are cell-relative floats, errors ~1e-7 of a cell). The cells do not change
/// between two sorts, so the move is a PosCell difference; a sort rebuilds the list.
///
/// Reach: the row walk reaches range = cell_div + 1 cells when the grid has a skin; a pair
/// 2h + s apart, each particle up to the grid skin outside its cell, lies in reach while
/// s + 2 skin < 1 cell (checked where the run is set up).
///
/// Layout: entry e of fluid particle i at nb[e * stride + (i - first)] (consecutive particles'
/// entries side by side: coalesced on the GPU); count[i - first] entries, at most cap.
#pragma once

#include <cstdint>

#include "physics/cell_grid.h"
#include "physics/fluid_constants.h"
#include "physics/neighbour_rows.h"
#include "physics/sph_types.h"

namespace seaspring::physics {

/// The largest list skin + 2 x the grid skin, in cells (the reach condition above, 1% spare).
constexpr double kMaxListReach = 0.99;

/// The list's arrays and constants (pointers of the executing backend; nb null: no list).
struct NeighbourList {
    std::uint32_t* nb = nullptr;     ///< entries, column-major (see the file comment)
    std::uint32_t* count = nullptr;  ///< entries per fluid particle
    Float4* pos0 = nullptr;          ///< PosCell at the build, per fluid particle
    std::uint32_t first = 0;         ///< index of the first fluid particle (nbound)
    std::uint32_t stride = 0;        ///< fluid particles the arrays are sized for
    std::uint32_t cap = 0;           ///< entries per particle the arrays hold
    float r2 = 0;                    ///< (2h + s)^2: the list's radius squared [m^2]
    float stale2 = 0;                ///< (0.495 s)^2: a larger move since the build makes it stale
};

/// The list's radius squared and stale bound for a list skin `s` [m] (host only).
inline void setListRadius(NeighbourList& l, const FluidConstants& c, float s) {
    const float r = 2.f * c.ker.h + s;
    l.r2 = r * r;
    const float half = 0.495f * s;
    l.stale2 = half * half;
}

/// Offset r_ab of candidate b (PosCell psb) from particle a (PosCell psa) and its square, by the
/// same operations as pairOffset in the frame of b's row (rowFrame, forEachCandidateRow).
template <int kDim>
SEASPRING_HD_INLINE float listedPairOffset(const Float4& psa, const Float4& psb, const CellGrid& g, float& drx,
                                           float& dry, float& drz) {
    const int cax = packedCellX(g, psa.w);
    const float rowdy = kDim == 3 ? g.cellsizef * float(packedCellY(g, psa.w) - packedCellY(g, psb.w)) : 0.f;
    const float rowdz = g.cellsizef * float(packedCellZ(g, psa.w) - packedCellZ(g, psb.w));
    return pairOffset<kDim>(rowFrame(psa, rowdy, rowdz), psb, cax, g, drx, dry, drz);
}

/// Builds fluid particle i's list from the fluid block (`cell_start_fluid`): the candidates b != i
/// within sqrt(l.r2), in row-walk order, at most l.cap of them stored; count[] gets how many
/// there are (the caller grows the arrays and builds again when one has more than l.cap).
template <int kDim>
SEASPRING_HD inline std::uint32_t buildNeighbourListAt(std::uint32_t i, const NeighbourList& l, const Float4* poscell,
                                                       const std::uint32_t* cell_start_fluid, FluidConstants c,
                                                       const CellGrid& g) {
    const Float4 psa = poscell[i];
    const std::uint32_t k = i - l.first;
    c.ker.kernelsize2 = l.r2;  // the row walk's reach: the list's radius
    std::uint32_t n = 0;
    forEachCandidateRow<kDim>(psa, cell_start_fluid, c, g, [&](std::uint32_t pb, std::uint32_t pe, const Float4& par, int cax) {
        for (std::uint32_t j = pb; j < pe; ++j) {
            float drx, dry, drz;
            const float rr2 = pairOffset<kDim>(par, poscell[j], cax, g, drx, dry, drz);
            if (rr2 > l.r2 || j == i) continue;
            if (n < l.cap) l.nb[std::size_t(n) * l.stride + k] = j;
            ++n;
        }
    });
    l.count[k] = n;
    l.pos0[k] = psa;
    return n;
}

/// True when fluid particle i has moved more than 0.495 list skins since the build (PosCell
/// refreshed in its cell: the caller runs this after refreshPosCellAt).
SEASPRING_HD_INLINE bool listStaleAt(std::uint32_t i, const NeighbourList& l, const Float4* poscell) {
    const Float4 p = poscell[i], q = l.pos0[i - l.first];
    const float dx = p.x - q.x, dy = p.y - q.y, dz = p.z - q.z;
    return fma32(dx, dx, fma32(dy, dy, dz * dz)) > l.stale2;
}

}  // namespace seaspring::physics
