// SeaSpring — MIT licence.
/// \file cell_grid.h
/// \brief The cell grid of the neighbour search and the cell-relative float positions
///        ("PosCell", as DualSPHysics) used by every pair interaction.
///
/// Cells are cubes of size 2h/cell_div (or one particle spacing, kCellDivSpacing) over the
/// simulation domain (x fastest). A particle's
/// PosCell is (x - ox, y - oy, z - oz, packed cell coordinates) with (ox, oy, oz) its cell's
/// origin: offsets stay small, so float pair distances keep double-like accuracy in long
/// domains. Pair distance: (local_a - local_b) + cellsize * (cell_a - cell_b), exact in the
/// cell difference whatever cell a particle was assigned to.
///
/// Skin (Verlet-style, without a neighbour list): between two sorts a particle keeps the cell
/// it was sorted into while it stays within `skinf` of that cell along every axis (its PosCell
/// is refreshed from its position in that cell). The neighbour search then treats every cell as
/// grown by the skin (searchBox's margin) and searches one cell further (`range`), so every
/// neighbour is still visited; a divide sorts again only when a particle has left its grown
/// cell (refreshPosCellAt). Skin 0: a sort at every divide.
#pragma once

#include <cmath>
#include <cstdint>

#include "core/host_device.h"
#include "physics/sph_types.h"

namespace seaspring::physics {

struct CellGrid {
    double minx = 0, miny = 0, minz = 0;  ///< domain minimum [m]
    double cellsize = 0;                   ///< [m]
    float cellsizef = 0;                   ///< float(cellsize)
    float ovcellsizef = 0;                 ///< 1 / cellsizef
    int ncx = 1, ncy = 1, ncz = 1;         ///< cells per axis
    int range = 1;                         ///< cells searched on each side (cell_div or cellsToReach, + 1 with a skin)
    int cell_div = 1;                      ///< cell mode: cells of 2h/cell_div (1..4), of dp (kCellDivSpacing)
    float skinf = 0;                       ///< skin [m] (0: sorted at every divide)
    std::uint32_t bitsx = 1, bitsy = 1;    ///< packed cell: cx | cy << bitsx | cz << (bitsx+bitsy)
    std::uint32_t maskx = 1, masky = 1;

    SEASPRING_HD std::uint32_t cellCount() const {
        return std::uint32_t(ncx) * std::uint32_t(ncy) * std::uint32_t(ncz);
    }
    SEASPRING_HD std::uint32_t linear(int cx, int cy, int cz) const {
        return std::uint32_t(cx) + std::uint32_t(ncx) * (std::uint32_t(cy) + std::uint32_t(ncy) * std::uint32_t(cz));
    }
};

/// Cell coordinates of a position, clamped to the grid. A NaN coordinate (an unstable VCPM
/// solid: boundary particles are never excluded) gives cell 0 rather than an undefined int
/// conversion; finite coordinates take the same branches as a plain clamp.
SEASPRING_HD inline void cellOf(const CellGrid& g, const Double3& p, int& cx, int& cy, int& cz) {
    const double fx = floor((p.x - g.minx) / g.cellsize);
    const double fy = floor((p.y - g.miny) / g.cellsize);
    const double fz = floor((p.z - g.minz) / g.cellsize);
    cx = !(fx >= 0.0) ? 0 : (fx >= double(g.ncx) ? g.ncx - 1 : int(fx));
    cy = !(fy >= 0.0) ? 0 : (fy >= double(g.ncy) ? g.ncy - 1 : int(fy));
    cz = !(fz >= 0.0) ? 0 : (fz >= double(g.ncz) ? g.ncz - 1 : int(fz));
}

/// The PosCell of a position: offsets from its cell's origin and the packed cell.
SEASPRING_HD inline Float4 makePosCell(const CellGrid& g, const Double3& p, std::uint32_t& linear_cell) {
    int cx, cy, cz;
    cellOf(g, p, cx, cy, cz);
    linear_cell = g.linear(cx, cy, cz);
    Float4 r;
    r.x = float(p.x - (g.minx + double(cx) * g.cellsize));
    r.y = float(p.y - (g.miny + double(cy) * g.cellsize));
    r.z = float(p.z - (g.minz + double(cz) * g.cellsize));
    const std::uint32_t packed = std::uint32_t(cx) | (std::uint32_t(cy) << g.bitsx) |
                                 (std::uint32_t(cz) << (g.bitsx + g.bitsy));
    r.w = uintBitsToFloat(packed);
    return r;
}

/// A fluid particle removed from the run between two sorts (excluded at a divide that did not
/// sort): it keeps its slot in its block until the next sort moves it past the block's active
/// end, with NaN offsets and its packed cell. No pair test accepts a NaN offset (isNeighbour,
/// mDBC's and the gauges' tests are false for NaN), row extents leave it out, and the passes
/// over the active range skip it (removedFromRun): it takes part in nothing, as if sorted out.
SEASPRING_HD inline Float4 removedPosCell(float packed) {
    const float nan = uintBitsToFloat(0x7FC00000u);  // a quiet NaN, the same bits on every backend
    return Float4{nan, nan, nan, packed};
}
/// Whether a PosCell is removedPosCell's (no particle in the run has a NaN offset: a position
/// that is not finite is excluded, kExcludedNotFinite, and removed at the next divide).
SEASPRING_HD inline bool removedFromRun(const Float4& poscell) { return !(poscell.x == poscell.x); }

SEASPRING_HD inline int packedCellX(const CellGrid& g, float w);
SEASPRING_HD inline int packedCellY(const CellGrid& g, float w);
SEASPRING_HD inline int packedCellZ(const CellGrid& g, float w);

/// Between two sorts (skin > 0): the PosCell of a position in the cell `packed` it was sorted
/// into (same arithmetic as makePosCell). `outside` = the position lies more than the skin
/// outside that cell along some axis, or is not finite: the next divide must sort.
SEASPRING_HD inline Float4 posCellInCell(const CellGrid& g, const Double3& p, float packed, bool& outside) {
    const int cx = packedCellX(g, packed), cy = packedCellY(g, packed), cz = packedCellZ(g, packed);
    Float4 r;
    r.x = float(p.x - (g.minx + double(cx) * g.cellsize));
    r.y = float(p.y - (g.miny + double(cy) * g.cellsize));
    r.z = float(p.z - (g.minz + double(cz) * g.cellsize));
    r.w = packed;
    const float lo = -g.skinf, hi = g.cellsizef + g.skinf;
    outside = !(r.x >= lo && r.x <= hi && r.y >= lo && r.y <= hi && r.z >= lo && r.z <= hi);
    return r;
}

SEASPRING_HD inline int packedCellX(const CellGrid& g, float w) {
    return int(floatBitsToUint(w) & g.maskx);
}
SEASPRING_HD inline int packedCellY(const CellGrid& g, float w) {
    return int((floatBitsToUint(w) >> g.bitsx) & g.masky);
}
SEASPRING_HD inline int packedCellZ(const CellGrid& g, float w) {
    return int(floatBitsToUint(w) >> (g.bitsx + g.bitsy));
}

/// The linear cell index of a packed cell.
SEASPRING_HD inline std::uint32_t linearCellOf(const CellGrid& g, float w) {
    return g.linear(packedCellX(g, w), packedCellY(g, w), packedCellZ(g, w));
}

/// Whether a particle of a sorted block shares its cell with another particle of that block
/// (`cell_start`: the block's cell ranges; the particle's cell from its PosCell). A fluid on its
/// initial lattice in cells of one spacing centred on it (solver/grid_origin.h) has one particle
/// per cell and none shares; a disordered fluid packs some cells with two or more. The rule of
/// the cells' switch (solver/cell_switch.h), read right after a sort.
SEASPRING_HD inline bool sharesItsCell(const Float4& poscell, const std::uint32_t* cell_start, const CellGrid& g) {
    const std::uint32_t c = linearCellOf(g, poscell.w);
    return cell_start[c + 1u] - cell_start[c] >= 2u;
}

/// Scalar forms of the lane operations that cellGap and rowSpan are written with (the host's
/// row table evaluates them on eight rows at once with core/simd8.h's: the same operations).
/// float(x), exact for a cell difference.
SEASPRING_HD_INLINE float toFloat(int x) { return float(x); }
/// m ? a : b.
SEASPRING_HD_INLINE float choose(bool m, float a, float b) { return m ? a : b; }
/// The IEEE square root.
SEASPRING_HD_INLINE float sqrtIeee(float x) { return sqrtf(x); }
/// int(floorf(x)).
SEASPRING_HD_INLINE int floorToInt(float x) { return int(floorf(x)); }

/// Distance along one axis from a point at offset `o` in its cell ([0, cellsize]) to the
/// nearest face of the cell `k` cells away (0 for k = 0), less `margin`, floored at 0.
/// I, F: int and float, or eight lanes of each (simd::Vec8i, simd::Vec8f).
template <class I, class F>
SEASPRING_HD_INLINE F cellGap(I k, F o, float cs, float margin) {
    const F d = choose(k > I(0), toFloat(k) * F(cs) - o, choose(k < I(0), o - toFloat(k + I(1)) * F(cs), F(0.f)));
    const F dm = d - F(margin);
    return choose(dm > F(0.f), dm, F(0.f));
}

/// The x cells [x0, x1] of one row of cells that can hold particles within sqrt(r2) of a point
/// at offset `ox` in cell `cax`, `gyz2` being the squared gap from the point to the row in y
/// and z (cellGap). False when no cell of the row is in reach. With margin > 0 the span is
/// conservative: every pair that passes the exact pair test (float r^2 <= r2) lies inside it,
/// so skipping the rest changes no result; it only spares the candidates out of reach
/// (rows at the corners of the search box and cells beyond the sphere along x).
/// I, F as cellGap; for lanes the result is a lane mask (x0, x1 undefined in lanes out of reach).
template <class I, class F>
SEASPRING_HD_INLINE auto rowSpan(const CellGrid& g, int cax, F ox, F gyz2, float r2, float margin, I& x0, I& x1) {
    constexpr bool kScalar = sizeof(F) == sizeof(float);
    const F rem = F(r2) - gyz2;
    if constexpr (kScalar) {
        if (rem < 0.f) return false;
    }
    const F dx = sqrtIeee(rem) + F(margin);
    const I k0 = floorToInt((ox - dx) * F(g.ovcellsizef));
    const I k1 = floorToInt((ox + dx) * F(g.ovcellsizef));
    x0 = maxi(I(cax) + maxi(k0, I(-g.range)), I(0));
    x1 = mini(I(cax) + mini(k1, I(g.range)), I(g.ncx - 1));
    if constexpr (kScalar) return x0 <= x1;
    else return rem >= F(0.f) && x0 <= x1;
}

/// Sort key: cell then particle id for active particles; excluded particles after all cells
/// (still ordered by id). Keys are unique, so any correct sort gives the same order.
constexpr std::uint64_t kExcludedCell = 0xFFFFFFFFull;
SEASPRING_HD inline std::uint64_t sortKey(std::uint32_t linear_cell, std::uint32_t id, bool excluded) {
    const std::uint64_t cell = excluded ? kExcludedCell : std::uint64_t(linear_cell);
    return (cell << 32) | std::uint64_t(id);
}

/// Largest skin, as a fraction of the cell size: one more cell on each side of the search box
/// covers a particle and its neighbour both up to half a cell outside their cells.
constexpr double kMaxSkinFraction = 0.5;
/// The default skin (-skin) of large runs (smaller runs: solver::resolveSkin): measured in
/// docs/performance-large.md.
constexpr double kDefaultSkinFraction = 0.05;

/// The cell mode of cells one particle spacing dp wide (-cellmode:dp); modes 1..4 are cells of
/// 2h/cell_div. With h between 1.5 dp and 2 dp (DualSPHysics' default coefh 1 in 3D gives
/// h = 1.73 dp) neither h/2 nor 2h/3 is a whole number of spacings; cells of dp are, so the grid
/// can be centred on the fluid's lattice (solver/grid_origin.h), and the search reaches
/// cellsToReach(h, dp) cells (4 there).
constexpr int kCellDivSpacing = 5;

/// The least n with n cells of `cellsize` spanning 2h: the cells a search reaches on each side.
inline int cellsToReach(double h, double cellsize) {
    int n = 1;
    while (double(n) * cellsize < 2.0 * h && n < 64) ++n;
    return n;
}

/// The most cells a search may reach with cells of dp (2h <= 8 dp): the near flags' window
/// (particle_updates.h) holds at most 31 cells, 2 (reach + 1) + 1 with a skin.
constexpr int kMaxSpacingReach = 8;

/// The cell size of mode `cell_div`: 2h/cell_div for 1..4, dp for kCellDivSpacing.
inline double cellSizeOfMode(double h, double dp, int cell_div) {
    return cell_div == kCellDivSpacing ? dp : 2.0 * h / double(cell_div);
}

/// Builds the grid over [min, max] with cells of mode `cell_div` (cellSizeOfMode: 2h/cell_div,
/// or dp for kCellDivSpacing) and a skin of `skin_fraction` cells (0 <= skin_fraction <=
/// kMaxSkinFraction; host only). Returns false when the packed cell does not fit 32 bits, there
/// are too many cells, or cells of dp are asked for with dp <= 0, dp > 2h or 2h > 8 dp
/// (kMaxSpacingReach).
inline bool makeCellGrid(double minx, double miny, double minz, double maxx, double maxy,
                         double maxz, double h, int cell_div, CellGrid& g, double skin_fraction = 0.0,
                         double dp = 0.0) {
    if (cell_div == kCellDivSpacing && !(dp > 0.0 && dp <= 2.0 * h && cellsToReach(h, dp) <= kMaxSpacingReach))
        return false;
    g.minx = minx;
    g.miny = miny;
    g.minz = minz;
    g.cellsize = cellSizeOfMode(h, dp, cell_div);
    g.cellsizef = float(g.cellsize);
    g.ovcellsizef = 1.f / g.cellsizef;
    g.cell_div = cell_div;
    const int reach = cell_div == kCellDivSpacing ? cellsToReach(h, g.cellsize) : cell_div;
    g.range = reach + (skin_fraction > 0.0 ? 1 : 0);
    g.skinf = float(skin_fraction * g.cellsize);
    auto count = [&](double lo, double hi) { return int(std::floor((hi - lo) / g.cellsize)) + 1; };
    g.ncx = count(minx, maxx);
    g.ncy = count(miny, maxy);
    g.ncz = count(minz, maxz);
    auto bits = [](int n) {
        std::uint32_t b = 1;
        while ((1u << b) < std::uint32_t(n)) ++b;
        return b;
    };
    g.bitsx = bits(g.ncx);
    g.bitsy = bits(g.ncy);
    const std::uint32_t bitsz = bits(g.ncz);
    g.maskx = (1u << g.bitsx) - 1u;
    g.masky = (1u << g.bitsy) - 1u;
    const double cells = double(g.ncx) * double(g.ncy) * double(g.ncz);
    return g.bitsx + g.bitsy + bitsz <= 32 && cells < 4.0e9 - 2.0;
}

}  // namespace seaspring::physics
