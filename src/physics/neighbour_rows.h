// SeaSpring — MIT licence.
/// \file neighbour_rows.h
/// \brief The neighbour search shared by every pair loop (fluid and boundary forces, the
///        hydrodynamic force on solids, gauges): the search box of a particle, the rows of cells
///        in it that can hold a neighbour and their candidate ranges, visited in one fixed order
///        by forEachCandidateRow; the pair offset in a row's frame and the neighbour test.
///
/// Row order: by z then y (ascending); inside a row, the contiguous particle range of its cells
/// (sorted by cell, then id). Every loop visits its candidates through forEachCandidateRow, so
/// all of them see the same rows, the same row floats and the same candidate order.
#pragma once

#include <cmath>
#include <cstdint>

#include "physics/cell_grid.h"
#include "physics/fluid_constants.h"
#include "physics/sph_types.h"

namespace seaspring::physics {

/// The most pair lanes of the fluid loop (fluid_interaction.h; a power of two: the host keeps
/// this many partial sums per particle).
constexpr std::uint32_t kMaxPairLanes = 8;

/// Safety margin of the row spans, in cells: absorbs the rounding of the span arithmetic. The
/// grid's skin is added to it: a candidate may lie up to the skin outside its cell (cell_grid.h).
constexpr float kRowSpanMargin = 1e-3f;

/// Particle a's cell offsets moved into the frame of one row of cells: y + rowdy, z + rowdz,
/// rowdy/rowdz = cellsize * (a's cell - the row's cell) in y/z. Computed once per row.
SEASPRING_HD_INLINE Float4 rowFrame(const Float4& psa, float rowdy, float rowdz) {
    return Float4{psa.x, psa.y + rowdy, psa.z + rowdz, psa.w};
}

/// Offset r_ab = r_a - r_b of a candidate b of the row and its squared length; `par` is a's
/// rowFrame for that row.
template <int kDim>
SEASPRING_HD_INLINE float pairOffset(const Float4& par, const Float4& psb, int cax, const CellGrid& g,
                                     float& drx, float& dry, float& drz) {
    drx = fma32(g.cellsizef, float(cax - packedCellX(g, psb.w)), par.x - psb.x);
    dry = kDim == 3 ? par.y - psb.y : 0.f;
    drz = par.z - psb.z;
    return kDim == 3 ? fma32(drx, drx, fma32(dry, dry, drz * drz)) : fma32(drx, drx, drz * drz);
}

/// The exact neighbour test of a pair (inside the kernel support, not the particle itself).
SEASPRING_HD_INLINE bool isNeighbour(float rr2, const FluidConstants& c) {
    return rr2 <= c.ker.kernelsize2 && rr2 >= kAlmostZero;
}

/// The cells around a particle's cell that its neighbour search visits: rows y0..y1, z0..z1
/// (2D: y0 = y1 = 0) of at most 2 range + 1 cells each.
struct SearchBox {
    int cax, cay, caz, y0, y1, z0, z1;
    float margin;        ///< rowSpan's safety margin and the grid's skin [m]
    float margin_exact;  ///< the safety margin alone (gaps to a row's extent, which holds the skin) [m]
};

// ---- row extents ----------------------------------------------------------------------------
// The extent of a row of cells in one block: the least and greatest PosCell offsets of the
// particles sorted into the row's cells along each axis (offsets from their own cell's origin:
// the cells of a row share their y and z, and along x each particle is its cell's). Computed at
// every force evaluation from the positions it reads (solver's RowExtentsPass), it bounds them
// exactly: a row whose extent lies beyond the support holds no neighbour, and the cells of a
// row in reach are those whose particles' x range can meet the support. On a lattice (the
// particles of a row on one line, at one offset in their cells) these are the sphere's own
// rows and spans: SPHERIC's h = 2 dp on cells of one spacing visits 49 rows and 257 candidates
// for 256 neighbours instead of 69 rows and 461 candidates (docs/performance-large.md). The
// neighbours, their order and so every sum are the same as without extents; only the
// candidates that pair lanes number change.

/// The extent of a row of cells (PosCell offsets, [lo, hi] per axis; 2D: y unused).
struct RowExtent {
    float xlo, xhi, ylo, yhi, zlo, zhi;
};

/// The extent of no particle: every gap to it is infinite.
SEASPRING_HD_INLINE RowExtent emptyRowExtent() {
    const float inf = INFINITY;
    return RowExtent{inf, -inf, inf, -inf, inf, -inf};
}

/// [lo, hi] joined with [vlo, vhi] (NaN is left out: a particle with a NaN offset is no
/// neighbour; an empty range, lo > hi, adds nothing).
SEASPRING_HD_INLINE void joinRange(float& lo, float& hi, float vlo, float vhi) {
    lo = vlo < lo ? vlo : lo;
    hi = vhi > hi ? vhi : hi;
}

/// Extent e grown by PosCell p.
SEASPRING_HD_INLINE RowExtent growRowExtent(RowExtent e, const Float4& p) {
    joinRange(e.xlo, e.xhi, p.x, p.x);
    joinRange(e.ylo, e.yhi, p.y, p.y);
    joinRange(e.zlo, e.zhi, p.z, p.z);
    return e;
}

/// Two extents joined (exact in any order but for the sign of a zero, which canonicalRowExtent
/// removes).
SEASPRING_HD_INLINE RowExtent joinRowExtents(RowExtent a, const RowExtent& b) {
    joinRange(a.xlo, a.xhi, b.xlo, b.xhi);
    joinRange(a.ylo, a.yhi, b.ylo, b.yhi);
    joinRange(a.zlo, a.zhi, b.zlo, b.zhi);
    return a;
}

/// The extent with -0 written as +0 (v + 0 is +0 for v = -0, v otherwise): the same bits
/// whatever order the particles were joined in.
SEASPRING_HD_INLINE RowExtent canonicalRowExtent(const RowExtent& e) {
    return RowExtent{e.xlo + 0.f, e.xhi + 0.f, e.ylo + 0.f, e.yhi + 0.f, e.zlo + 0.f, e.zhi + 0.f};
}

/// The extent of particles [pb, pe) taken every `stride`-th from pb (a share of one row: the
/// shares of a row joined give its extent).
SEASPRING_HD_INLINE RowExtent rowExtentOf(const Float4* poscell, std::uint32_t pb, std::uint32_t pe,
                                          std::uint32_t stride) {
    RowExtent e = emptyRowExtent();
    for (std::uint32_t j = pb; j < pe; j += stride) e = growRowExtent(e, poscell[j]);
    return e;
}

/// The gap from offset `o` (in the row's frame) to an extent [lo, hi] along one axis, less
/// `margin`, at least 0; infinite for an empty extent.
SEASPRING_HD_INLINE float rowExtentGap(float o, float lo, float hi, float margin) {
    const float below = lo - o, above = o - hi;
    const float dm = (below > above ? below : above) - margin;
    return dm > 0.f ? dm : 0.f;
}

/// rowSpan for a row of extent [xlo, xhi] along x: the cells k (from `cax`) whose particles'
/// x, k cellsize + [xlo, xhi], can come within sqrt(r2 - gyz2) + margin of offset `ox`.
SEASPRING_HD_INLINE bool rowSpanInExtent(const CellGrid& g, int cax, float ox, float gyz2, float r2, float margin,
                                         float xlo, float xhi, int& x0, int& x1) {
    const float rem = r2 - gyz2;
    if (rem < 0.f) return false;
    const float dx = sqrtf(rem) + margin;
    const int k0 = int(ceilf((ox - dx - xhi) * g.ovcellsizef));
    const int k1 = int(floorf((ox + dx - xlo) * g.ovcellsizef));
    x0 = cax + (k0 > -g.range ? k0 : -g.range);
    x1 = cax + (k1 < g.range ? k1 : g.range);
    if (x0 < 0) x0 = 0;
    if (x1 > g.ncx - 1) x1 = g.ncx - 1;
    return x0 <= x1;
}

template <int kDim>
SEASPRING_HD_INLINE SearchBox searchBox(const Float4& psa, const CellGrid& g) {
    SearchBox b;
    b.cax = packedCellX(g, psa.w);
    b.cay = kDim == 3 ? packedCellY(g, psa.w) : 0;
    b.caz = packedCellZ(g, psa.w);
    b.y0 = kDim == 3 ? maxi(b.cay - g.range, 0) : 0;
    b.y1 = kDim == 3 ? mini(b.cay + g.range, g.ncy - 1) : 0;
    b.z0 = maxi(b.caz - g.range, 0);
    b.z1 = mini(b.caz + g.range, g.ncz - 1);
    b.margin = fma32(kRowSpanMargin, g.cellsizef, g.skinf);
    b.margin_exact = kRowSpanMargin * g.cellsizef;
    return b;
}

/// The cells of row (y, z) in reach of `psa`: linear cells [c0, c1) (rowSpan). `gz` = the row's
/// gap in z (cellGap, once per z). False when the row is out of reach.
template <int kDim>
SEASPRING_HD_INLINE bool rowCells(const SearchBox& b, const Float4& psa, int y, int z, float gz,
                                  const FluidConstants& c, const CellGrid& g, std::uint32_t& c0,
                                  std::uint32_t& c1) {
    const float gy = kDim == 3 ? cellGap(y - b.cay, psa.y, g.cellsizef, b.margin) : 0.f;
    int x0, x1;
    if (!rowSpan(g, b.cax, psa.x, gy * gy + gz * gz, c.ker.kernelsize2, b.margin, x0, x1)) return false;
    const std::uint32_t row = g.linear(0, y, z);
    c0 = row + std::uint32_t(x0);
    c1 = row + std::uint32_t(x1) + 1u;
    return true;
}

/// The rows of cells around `psa`'s cell that can hold a neighbour of it (by z then y,
/// ascending): fn(c0, c1, par, cax) for each row in reach, [c0, c1) its linear cells (rowCells),
/// `par` = psa's rowFrame for that row and `cax` = psa's cell in x (the arguments of
/// pairOffset). `extents` (one block's, per row y + ncy z; null: none): a row is in reach and
/// spans by the gap to its extent, else by the gap to its cells. The one row walk of every
/// pair loop: forEachCandidateRow takes a block's candidates from it, and the host builds a
/// RowTable per particle and block from it.
template <int kDim, class RowFn>
SEASPRING_HD_INLINE void forEachRowInReach(const Float4& psa, const FluidConstants& c, const CellGrid& g, RowFn fn,
                                           const RowExtent* extents = nullptr) {
    const SearchBox box = searchBox<kDim>(psa, g);
    for (int z = box.z0; z <= box.z1; ++z) {
        const float rowdz = g.cellsizef * float(box.caz - z);
        const float gz = extents ? 0.f : cellGap(z - box.caz, psa.z, g.cellsizef, box.margin);
        for (int y = box.y0; y <= box.y1; ++y) {
            const float rowdy = g.cellsizef * float(box.cay - y);
            Float4 par = rowFrame(psa, rowdy, rowdz);
            std::uint32_t c0, c1;
            if (extents) {
                const RowExtent& e = extents[std::uint32_t(y) + std::uint32_t(g.ncy) * std::uint32_t(z)];
                const float ey = kDim == 3 ? rowExtentGap(par.y, e.ylo, e.yhi, box.margin_exact) : 0.f;
                const float ez = rowExtentGap(par.z, e.zlo, e.zhi, box.margin_exact);
                int x0, x1;
                if (!rowSpanInExtent(g, box.cax, psa.x, ey * ey + ez * ez, c.ker.kernelsize2, box.margin_exact, e.xlo,
                                     e.xhi, x0, x1))
                    continue;
                const std::uint32_t row = g.linear(0, y, z);
                c0 = row + std::uint32_t(x0);
                c1 = row + std::uint32_t(x1) + 1u;
            } else if (!rowCells<kDim>(box, psa, y, z, gz, c, g, c0, c1)) {
                continue;
            }
            SEASPRING_MATERIALIZE(par.y);  // once per row, not per candidate
            SEASPRING_MATERIALIZE(par.z);
            fn(c0, c1, par, box.cax);
        }
    }
}

/// The rows in reach of `psa` (forEachRowInReach) in one block (`cell_start` of that block),
/// calling fn(pb, pe, par, cax) for each: candidates [pb, pe) (absolute indices), `par` and
/// `cax` as forEachRowInReach gives them. `fn` is a lambda or functor passed by value (inlined
/// on both backends).
template <int kDim, class RowFn>
SEASPRING_HD_INLINE void forEachCandidateRow(const Float4& psa, const std::uint32_t* cell_start,
                                             const FluidConstants& c, const CellGrid& g, RowFn fn,
                                             const RowExtent* extents = nullptr) {
    forEachRowInReach<kDim>(
        psa, c, g,
        [&](std::uint32_t c0, std::uint32_t c1, const Float4& par, int cax) {
            fn(cell_start[c0], cell_start[c1], par, cax);
        },
        extents);
}

/// The rows in reach of one particle (forEachRowInReach), kept for all the blocks it visits, or
/// built per block with row extents (the host's path): row k has linear cells [c0[k], c1[k])
/// and the row frame (x, py[k], pz[k]).
struct RowTable {
    static constexpr int kCap = 256;  ///< rows at most; a larger search box: `full` (not built)
    int n = 0;
    bool full = false;
    int cax = 0;
    std::uint32_t c0[kCap], c1[kCap];
    float py[kCap], pz[kCap];

    /// The rows of forEachRowInReach for `psa` (with one block's `extents`, or none).
    template <int kDim>
    SEASPRING_HD void build(const Float4& psa, const FluidConstants& c, const CellGrid& g,
                            const RowExtent* extents = nullptr) {
        const SearchBox box = searchBox<kDim>(psa, g);
        n = 0;
        full = (box.z1 - box.z0 + 1) * (box.y1 - box.y0 + 1) > kCap;
        if (full) return;
        forEachRowInReach<kDim>(
            psa, c, g,
            [&](std::uint32_t r0, std::uint32_t r1, const Float4& par, int x) {
                c0[n] = r0;
                c1[n] = r1;
                py[n] = par.y;
                pz[n] = par.z;
                cax = x;
                ++n;
            },
            extents);
    }
    /// fn(pb, pe, par, cax) for the rows in the block of `cell_start`, as forEachCandidateRow.
    template <class RowFn>
    SEASPRING_HD void forEachCandidateRow(const Float4& psa, const std::uint32_t* cell_start, RowFn fn) const {
        for (int k = 0; k < n; ++k) fn(cell_start[c0[k]], cell_start[c1[k]], Float4{psa.x, py[k], pz[k], psa.w}, cax);
    }
};

}  // namespace seaspring::physics
