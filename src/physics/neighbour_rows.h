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

#include <cstdint>

#include "core/simd8.h"
#include "physics/cell_grid.h"
#include "physics/fluid_constants.h"
#include "physics/row_extents.h"
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

#if SEASPRING_SIMD8
/// packedCellX of eight lanes (the host's SIMD candidate loop).
inline simd::Vec8i packedCellX(const CellGrid& g, simd::Vec8f w) { return simd::bitsAnd(w, g.maskx); }
static_assert(sizeof(Float4) == 4 * sizeof(float), "simd::loadQuads reads PosCells as four packed floats");
#endif

/// Offset r_ab = r_a - r_b of a candidate b of the row and its squared length; `par` is a's
/// rowFrame for that row. `psb` is b's PosCell (Float4; the host's SIMD loop also passes eight
/// candidates at once as simd::Quad8, each lane the same operations, so the same bits).
template <int kDim, class P, class F = decltype(P::x)>
SEASPRING_HD_INLINE F pairOffset(const Float4& par, const P& psb, int cax, const CellGrid& g, F& drx, F& dry,
                                 F& drz) {
    drx = fma32(F(g.cellsizef), toFloat(cax - packedCellX(g, psb.w)), par.x - psb.x);
    if constexpr (kDim == 3) dry = par.y - psb.y;
    else dry = F(0.f);
    drz = par.z - psb.z;
    if constexpr (kDim == 3) return fma32(drx, drx, fma32(dry, dry, drz * drz));
    else return fma32(drx, drx, drz * drz);
}

/// The exact neighbour test of a pair (inside the kernel support, not the particle itself); for
/// eight lanes, a lane mask.
template <class F>
SEASPRING_HD_INLINE auto isNeighbour(F rr2, const FluidConstants& c) {
    return rr2 <= F(c.ker.kernelsize2) && rr2 >= F(kAlmostZero);
}

/// The cells around a particle's cell that its neighbour search visits: rows y0..y1, z0..z1
/// (2D: y0 = y1 = 0) of at most 2 range + 1 cells each.
struct SearchBox {
    int cax, cay, caz, y0, y1, z0, z1;
    float margin;  ///< rowSpan's safety margin and the grid's skin [m]
};

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

/// Slack of rowsAlongY, in cells: far above the rounding of rowCells' test.
constexpr float kRowsAlongYSlack = 1e-3f;

/// The y cells [y0, y1] of the rows at z gap `gz` (cellGap) that rowCells can accept: the
/// nearest face of a row further along y lies more than sqrt(r^2 - gz^2) + the margin +
/// kRowsAlongYSlack cells away, so its gap exceeds what rowCells accepts by the slack, and
/// rowCells would reject it. Testing only these rows visits exactly the rows rowCells accepts
/// (the same rows, candidates and order: no result changes, pair lanes included). False when no row at
/// this z is in reach (rowCells would reject them all: gy^2 + gz^2 >= gz^2 > r^2). 2D: the
/// one row y = 0 when gz is in reach.
template <int kDim>
SEASPRING_HD_INLINE bool rowsAlongY(const SearchBox& b, const Float4& psa, float gz, const FluidConstants& c,
                                    const CellGrid& g, int& y0, int& y1) {
    const float rem = c.ker.kernelsize2 - gz * gz;
    if (rem < 0.f) return false;
    y0 = b.y0;
    y1 = b.y1;
    if (kDim == 3) {
        const float dy = sqrtf(rem) + fma32(kRowsAlongYSlack, g.cellsizef, b.margin);
        const int k0 = int(floorf((psa.y - dy) * g.ovcellsizef));
        const int k1 = int(floorf((psa.y + dy) * g.ovcellsizef));
        y0 = maxi(y0, b.cay + k0);
        y1 = mini(y1, b.cay + k1);
    }
    return y0 <= y1;
}

/// The z rows of `box` in reach of `psa` (ascending): fn(z, rowdz, gz, ylo, yhi) with rowdz
/// the row frame's z shift, gz the z gap (cellGap) and [ylo, yhi] the y rows to test
/// (rowsAlongY). forEachRowInReach's outer loop, shared with the host's RowTable.
template <int kDim, class ZFn>
SEASPRING_HD_INLINE void forEachZInReach(const SearchBox& box, const Float4& psa, const FluidConstants& c,
                                         const CellGrid& g, ZFn fn) {
    for (int z = box.z0; z <= box.z1; ++z) {
        const float rowdz = g.cellsizef * float(box.caz - z);
        const float gz = cellGap(z - box.caz, psa.z, g.cellsizef, box.margin);
        int ylo, yhi;
        if (!rowsAlongY<kDim>(box, psa, gz, c, g, ylo, yhi)) continue;
        fn(z, rowdz, gz, ylo, yhi);
    }
}

/// The rows of cells around `psa`'s cell that can hold a neighbour of it (by z then y,
/// ascending), whatever the block: fn(c0, c1, par, cax) for each row in reach, [c0, c1) its
/// linear cells (rowCells), `par` = psa's rowFrame for that row and `cax` = psa's cell in x (the
/// arguments of pairOffset). The one row walk of every pair loop: forEachCandidateRow takes a
/// block's candidates from it, and the host builds one RowTable per particle from it for all
/// its blocks.
template <int kDim, class RowFn>
SEASPRING_HD_INLINE void forEachRowInReach(const Float4& psa, const FluidConstants& c, const CellGrid& g, RowFn fn) {
    const SearchBox box = searchBox<kDim>(psa, g);
    forEachZInReach<kDim>(box, psa, c, g, [&](int z, float rowdz, float gz, int ylo, int yhi) {
        for (int y = ylo; y <= yhi; ++y) {
            std::uint32_t c0, c1;
            if (!rowCells<kDim>(box, psa, y, z, gz, c, g, c0, c1)) continue;
            const float rowdy = g.cellsizef * float(box.cay - y);
            Float4 par = rowFrame(psa, rowdy, rowdz);
            SEASPRING_MATERIALIZE(par.y);  // once per row, not per candidate
            SEASPRING_MATERIALIZE(par.z);
            fn(c0, c1, par, box.cax);
        }
    });
}

/// The rows in reach of `psa` (forEachRowInReach) in one block (`cell_start` of that block),
/// calling fn(pb, pe, par, cax) for each: candidates [pb, pe) (absolute indices), `par` and
/// `cax` as forEachRowInReach gives them. `fn` is a lambda or functor passed by value (inlined
/// on both backends).
template <int kDim, class RowFn>
SEASPRING_HD_INLINE void forEachCandidateRow(const Float4& psa, const std::uint32_t* cell_start,
                                             const FluidConstants& c, const CellGrid& g, RowFn fn) {
    forEachRowInReach<kDim>(psa, c, g, [&](std::uint32_t c0, std::uint32_t c1, const Float4& par, int cax) {
        fn(cell_start[c0], cell_start[c1], par, cax);
    });
}

/// forEachCandidateRow for a block whose rows' extents are `ext` (row_extents.h): the rows of
/// forEachZInReach tested against their particles' extents (rowSpanInExtent) instead of their
/// cells. Every row and cell that can hold a neighbour, in the same order (in practice fewer
/// rows and cells than the cell walk's), so the same neighbours in the same order; pair lanes by
/// index keep every lane's sum. The GPU's walks: of the fluid block on that block's extents of
/// the evaluation, of the boundary block on its own where the walls are fixed.
template <int kDim, class RowFn>
SEASPRING_HD_INLINE void forEachCandidateRowInExtents(const Float4& psa, const std::uint32_t* cell_start,
                                                      const RowExtents& ext, const FluidConstants& c,
                                                      const CellGrid& g, RowFn fn) {
    const SearchBox box = searchBox<kDim>(psa, g);
    const float margin = kRowSpanMargin * g.cellsizef;  // the extents hold the skin
    forEachZInReach<kDim>(box, psa, c, g, [&](int z, float rowdz, float, int ylo, int yhi) {
        for (int y = ylo; y <= yhi; ++y) {
            const std::uint32_t r = std::uint32_t(y) + std::uint32_t(g.ncy) * std::uint32_t(z);
            const float lo[3] = {ext.lo[0][r], kDim == 3 ? ext.lo[1][r] : 0.f, ext.lo[2][r]};
            const float hi[3] = {ext.hi[0][r], kDim == 3 ? ext.hi[1][r] : 0.f, ext.hi[2][r]};
            const float rowdy = g.cellsizef * float(box.cay - y);
            Float4 par = rowFrame(psa, rowdy, rowdz);
            int x0, x1;
            if (!rowSpanInExtent<kDim>(g, box.cax, psa.x, par.y, par.z, lo, hi, c.ker.kernelsize2, margin, x0, x1))
                continue;
            SEASPRING_MATERIALIZE(par.y);  // once per row, not per candidate
            SEASPRING_MATERIALIZE(par.z);
            const std::uint32_t row = r * std::uint32_t(g.ncx);
            fn(cell_start[row + std::uint32_t(x0)], cell_start[row + std::uint32_t(x1) + 1u], par, box.cax);
        }
    });
}

/// The rows in reach of one particle (forEachRowInReach), kept for all the blocks it visits
/// (the host's path): row k has linear cells [c0[k], c1[k]) and the row frame (x, py[k], pz[k]).
/// With SEASPRING_SIMD8 (the host's AVX2 build) eight rows along y are tested at once: rowCells'
/// cellGap and rowSpan and the row frame's y evaluated on lanes (the same operations, so the
/// same rows and bits), the rows in reach packed in order. With row extents (`ext`, row_extents.h)
/// each row is tested against its particles' extents instead of its cells (rowSpanInExtent):
/// every row and cell that can hold a neighbour (in practice fewer than the cells give), in the
/// same order.
struct RowTable {
    static constexpr int kCap = 256;  ///< rows at most; a larger search box: `full` (not built)
    static constexpr int kPad = 8;    ///< room for the lanes' stores at the table's end
    int n = 0;
    bool full = false;
    int cax = 0;
    std::uint32_t c0[kCap + kPad], c1[kCap + kPad];
    float py[kCap + kPad], pz[kCap + kPad];

    template <int kDim>
    SEASPRING_HD void build(const Float4& psa, const FluidConstants& c, const CellGrid& g,
                            const RowExtents& ext = RowExtents{}) {
        const SearchBox box = searchBox<kDim>(psa, g);
        n = 0;
        full = (box.z1 - box.z0 + 1) * (box.y1 - box.y0 + 1) > kCap;
        if (full) return;
        const bool with_ext = ext.lo[0] != nullptr;
        const float ext_margin = kRowSpanMargin * g.cellsizef;  // the extents hold the skin
#if SEASPRING_SIMD8
        cax = box.cax;
        forEachZInReach<kDim>(box, psa, c, g, [&](int z, float rowdz, float gz, int ylo, int yhi) {
            const float gz2 = gz * gz;
            const float rowz = psa.z + rowdz;  // rowFrame's z
            for (int y0 = ylo; y0 <= yhi; y0 += 8) {
                const simd::Vec8i y = simd::iota(y0);
                const simd::Vec8f rowdy = simd::Vec8f(g.cellsizef) * toFloat(simd::Vec8i(box.cay) - y);
                const simd::Vec8f rowy = simd::Vec8f(psa.y) + rowdy;  // rowFrame's y
                simd::Vec8i x0, x1;
                simd::Mask8 in;
                if (with_ext) {
                    const std::uint32_t r = std::uint32_t(y0) + std::uint32_t(g.ncy) * std::uint32_t(z);
                    const simd::Vec8f lo[3] = {simd::load(ext.lo[0] + r), simd::load(ext.lo[1] + r),
                                               simd::load(ext.lo[2] + r)};
                    const simd::Vec8f hi[3] = {simd::load(ext.hi[0] + r), simd::load(ext.hi[1] + r),
                                               simd::load(ext.hi[2] + r)};
                    in = rowSpanInExtent<kDim>(g, box.cax, simd::Vec8f(psa.x), rowy, simd::Vec8f(rowz), lo, hi,
                                               c.ker.kernelsize2, ext_margin, x0, x1);
                } else {
                    simd::Vec8f gy(0.f);
                    if constexpr (kDim == 3)
                        gy = cellGap(y - simd::Vec8i(box.cay), simd::Vec8f(psa.y), g.cellsizef, box.margin);
                    in = rowSpan(g, box.cax, simd::Vec8f(psa.x), gy * gy + simd::Vec8f(gz2), c.ker.kernelsize2,
                                 box.margin, x0, x1);
                }
                const unsigned bits = (in && y <= simd::Vec8i(yhi)).bits();
                // g.linear(0, y, z) (the unsigned product's low bits, as the scalar's)
                const simd::Vec8i row = simd::Vec8i(g.ncx) * (y + simd::Vec8i(g.ncy) * simd::Vec8i(z));
                simd::leftPackStore(c0 + n, row + x0, bits);
                simd::leftPackStore(c1 + n, row + x1 + simd::Vec8i(1), bits);
                simd::leftPackStore(py + n, rowy, bits);
                simd::leftPackStore(pz + n, simd::Vec8f(rowz), bits);
                n += __builtin_popcount(bits);
            }
        });
#else
        forEachRowInReach<kDim>(psa, c, g, [&](std::uint32_t r0, std::uint32_t r1, const Float4& par, int x) {
            cax = x;
            if (with_ext) {  // the row's cells narrowed to its extents (or the row dropped)
                const std::uint32_t row = r0 / std::uint32_t(g.ncx), first = row * std::uint32_t(g.ncx);
                const float lo[3] = {ext.lo[0][row], ext.lo[1][row], ext.lo[2][row]};
                const float hi[3] = {ext.hi[0][row], ext.hi[1][row], ext.hi[2][row]};
                int x0, x1;
                if (!rowSpanInExtent<kDim>(g, x, psa.x, par.y, par.z, lo, hi, c.ker.kernelsize2, ext_margin, x0, x1))
                    return;
                r0 = r0 > first + std::uint32_t(x0) ? r0 : first + std::uint32_t(x0);
                r1 = r1 < first + std::uint32_t(x1) + 1u ? r1 : first + std::uint32_t(x1) + 1u;
                if (r0 >= r1) return;
            }
            c0[n] = r0;
            c1[n] = r1;
            py[n] = par.y;
            pz[n] = par.z;
            ++n;
        });
#endif
    }
    /// fn(pb, pe, par, cax) for the rows in the block of `cell_start`, as forEachCandidateRow.
    template <class RowFn>
    SEASPRING_HD void forEachCandidateRow(const Float4& psa, const std::uint32_t* cell_start, RowFn fn) const {
        for (int k = 0; k < n; ++k) fn(cell_start[c0[k]], cell_start[c1[k]], Float4{psa.x, py[k], pz[k], psa.w}, cax);
    }
};

}  // namespace seaspring::physics
