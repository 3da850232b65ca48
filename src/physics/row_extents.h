// SeaSpring — MIT licence.
/// \file row_extents.h
/// \brief Row extents: for each row of cells (fixed y and z cells, every x), the least and
///        greatest cell-relative offsets, along each axis, of the particles it holds now. The
///        host's row table (neighbour_rows.h, RowTable) and the GPU's walks
///        (forEachCandidateRowInExtents) test a row against them instead of against the row's
///        cells: where the particles of a row lie on a line or a lattice inside their cells
///        (still water, the first steps of every run), far fewer rows and cells are in reach
///        (docs/performance-large.md, twenty-seventh and twenty-eighth sessions).
///
/// Exact: the extents bound the positions the pair loops read, so a row or cell that fails the
/// test holds no particle that could pass the exact pair test (isNeighbour). The neighbours and
/// their order are unchanged, and with pair lanes (a candidate's lane is its index mod the
/// lanes, fluid_interaction.h) so is every lane's sum: the host's row table and the GPU's walks,
/// which skip different candidates (each its own extents), give the same bits as the cell walk.
#pragma once

#include <cstdint>

#include "physics/cell_grid.h"
#include "physics/sph_types.h"

namespace seaspring::physics {

/// A row's extents when it holds no particle: every gap to it is then out of reach.
constexpr float kEmptyRowExtent = 1e30f;
/// Room after each extent array for the host's eight-row loads (RowTable::build).
constexpr std::uint32_t kRowExtentPad = 8;

/// The extents of rows r = y + ncy z, one array per bound (lo[axis][r], hi[axis][r], axis x, y,
/// z); null lo[0]: none (the rows' cells are tested).
struct RowExtents {
    const float* lo[3] = {nullptr, nullptr, nullptr};
    const float* hi[3] = {nullptr, nullptr, nullptr};
};

/// Floats of the extent arrays of a grid: six arrays of rows + kRowExtentPad.
SEASPRING_HD inline std::uint32_t rowExtentStride(const CellGrid& g) {
    return std::uint32_t(g.ncy) * std::uint32_t(g.ncz) + kRowExtentPad;
}
SEASPRING_HD inline RowExtents rowExtentsIn(const float* data, const CellGrid& g) {
    const std::uint32_t s = rowExtentStride(g);
    RowExtents e;
    for (int a = 0; a < 3; ++a) {
        e.lo[a] = data + (2 * a) * s;
        e.hi[a] = data + (2 * a + 1) * s;
    }
    return e;
}

/// One row's extents being formed: least and greatest offsets along x, y, z.
struct RowExtentAccum {
    float lo[3] = {kEmptyRowExtent, kEmptyRowExtent, kEmptyRowExtent};
    float hi[3] = {-kEmptyRowExtent, -kEmptyRowExtent, -kEmptyRowExtent};
    /// Particle offsets o joined (a NaN offset is left out: no pair test accepts it).
    SEASPRING_HD void add(const float* o) {
        for (int a = 0; a < 3; ++a) {
            lo[a] = o[a] < lo[a] ? o[a] : lo[a];
            hi[a] = o[a] > hi[a] ? o[a] : hi[a];
        }
    }
    /// Two accumulators joined (exact in any order: minima and maxima).
    SEASPRING_HD void join(const RowExtentAccum& b) {
        for (int a = 0; a < 3; ++a) {
            lo[a] = b.lo[a] < lo[a] ? b.lo[a] : lo[a];
            hi[a] = b.hi[a] > hi[a] ? b.hi[a] : hi[a];
        }
    }
};

/// Lane `lane` of `lanes`' share of row r's extents over the particles of one block (cell
/// starts `cs_a`) or two (and `cs_b`, when not null): in each block, its particles j with
/// j mod lanes = lane (the GPU joins a warp's shares, the host takes lanes 1).
SEASPRING_HD inline RowExtentAccum rowExtentShare(std::uint32_t r, std::uint32_t lane, std::uint32_t lanes,
                                                  const CellGrid& g, const std::uint32_t* cs_a,
                                                  const std::uint32_t* cs_b, const Float4* poscell) {
    RowExtentAccum e;
    const std::uint32_t c0 = r * std::uint32_t(g.ncx), c1 = c0 + std::uint32_t(g.ncx);
    const std::uint32_t* blocks[2] = {cs_a, cs_b};
    for (const std::uint32_t* cs : blocks) {
        if (cs == nullptr) continue;
        const std::uint32_t pe = cs[c1];
        for (std::uint32_t j = cs[c0] + lane; j < pe; j += lanes) {
            const Float4 p = poscell[j];
            const float o[3] = {p.x, p.y, p.z};
            e.add(o);
        }
    }
    return e;
}

/// Row r's extents written into `data` (arrays as rowExtentsIn).
SEASPRING_HD inline void storeRowExtent(std::uint32_t r, const CellGrid& g, const RowExtentAccum& e, float* data) {
    const std::uint32_t s = rowExtentStride(g);
    for (int a = 0; a < 3; ++a) {
        data[(2 * a) * s + r] = e.lo[a];
        data[(2 * a + 1) * s + r] = e.hi[a];
    }
}

/// Row r's extents over the particles of one block (cell starts `cs_a`) or two (and `cs_b`, when
/// not null) into `data` (rowExtentStride(g) floats per array, arrays as rowExtentsIn). Minima
/// and maxima are exact in any order; a NaN offset (a particle no pair test accepts) is left out.
SEASPRING_HD inline void rowExtentAt(std::uint32_t r, const CellGrid& g, const std::uint32_t* cs_a,
                                     const std::uint32_t* cs_b, const Float4* poscell, float* data) {
    storeRowExtent(r, g, rowExtentShare(r, 0u, 1u, g, cs_a, cs_b, poscell), data);
}

/// Distance along one axis from offset `a` to the interval [lo, hi], less `margin`, floored at 0.
/// F: a float or eight lanes (simd::Vec8f).
template <class F>
SEASPRING_HD_INLINE F axisGap(F a, F lo, F hi, float margin) {
    const F d = choose(a > hi, a - hi, choose(lo > a, lo - a, F(0.f)));
    const F dm = d - F(margin);
    return choose(dm > F(0.f), dm, F(0.f));
}

/// rowSpan's x cells [x0, x1] from a row's extents: the point at offsets (ox in its cell `cax`,
/// ay and az in the row's frame: rowFrame's y and z), the row's particles at cell-relative
/// offsets within [lo, hi] along each axis (2D: y not tested). A cell cb is in reach when a
/// particle at any x offset of the extent in it can be within sqrt(r2) (+ margin) of the point.
/// False (for lanes, a lane mask) when no cell is. I, F as rowSpan.
template <int kDim, class I, class F>
SEASPRING_HD_INLINE auto rowSpanInExtent(const CellGrid& g, int cax, F ox, F ay, F az, const F* lo, const F* hi,
                                         float r2, float margin, I& x0, I& x1) {
    constexpr bool kScalar = sizeof(F) == sizeof(float);
    F gyz2 = F(0.f);
    const F gz = axisGap(az, lo[2], hi[2], margin);
    if constexpr (kDim == 3) {
        const F gy = axisGap(ay, lo[1], hi[1], margin);
        gyz2 = gy * gy;
    }
    gyz2 = gyz2 + gz * gz;
    const F rem = F(r2) - gyz2;
    if constexpr (kScalar) {
        if (!(rem >= 0.f)) return false;
    }
    const F dx = sqrtIeee(rem) + F(margin);
    // cs (cb - cax) >= ox - hi - dx and <= ox - lo + dx (the offset fma of pairOffset).
    const I k0 = I(0) - floorToInt((hi[0] + dx - ox) * F(g.ovcellsizef));
    const I k1 = floorToInt((ox - lo[0] + dx) * F(g.ovcellsizef));
    x0 = maxi(I(cax) + maxi(k0, I(-g.range)), I(0));
    x1 = mini(I(cax) + mini(k1, I(g.range)), I(g.ncx - 1));
    if constexpr (kScalar) return x0 <= x1;
    else return rem >= F(0.f) && x0 <= x1;
}

}  // namespace seaspring::physics
