// SeaSpring — MIT licence.
/// \file gauges.h
/// \brief The measurements of `<special><gauges>` (DualSPHysics' JGauge* conventions), one
///        source for both backends:
///   - kernel sums at a point over its fluid neighbours (velocity, pressure, SWL mass):
///       wsum = sum_j V_j W_j,  V_j = m_j / rho_j,
///       v = sum_j V_j W_j v_j / wsum,  p = sum_j V_j W_j p_j / wsum  (Shepard-corrected;
///       no correction, value 0, where wsum < kclimit: the point is not in the fluid),
///       mass = sum_j V_j W_j m_j (SWL: ~ m inside the fluid, falls to 0 across the surface);
///   - the free surface along a line of points: the first point whose mass drops below
///     masslimit after one above it, linearly interpolated between the two (JGaugeSwl);
///   - the highest fluid particle within distlimit (horizontally) of a vertical line (JGaugeMaxZ);
///   - the crossing of a plane section by a particle between two saved times (seaspring-post
///     flow, DualSPHysics' FlowTool).
/// Unlike DualSPHysics' gauges, a particle exactly at the point counts (it carries the largest
/// weight; only a particle's pair with itself is excluded in the force loops).
/// Sums run in the neighbour order of the force loops (forEachCandidateRow: rows by z then y,
/// cells sorted by cell then id) and accumulate in double, so both backends give the same bits.
#pragma once

#include <cmath>
#include <cstdint>

#include "physics/cell_grid.h"
#include "physics/eos_tait.h"
#include "physics/fluid_constants.h"
#include "physics/neighbour_rows.h"
#include "physics/sph_types.h"

namespace seaspring::physics {

/// Kernel sums of one gauge point.
struct GaugeSample {
    double wsum = 0;                ///< sum V W (1 inside the fluid, less near a surface)
    double mass = 0;                ///< sum V W m [kg]
    double vx = 0, vy = 0, vz = 0;  ///< sum V W v
    double press = 0;               ///< sum V W p
    double rho = 0;                 ///< sum V W rho (seaspring-post's density)
};

/// The kernel sums at a gauge point whose PosCell (makePosCell) is `pt`, over the fluid block
/// (`cell_start_fluid` holds absolute indices into poscell/velrho).
template <class Kernel, int kDim>
SEASPRING_HD inline GaugeSample gaugeSampleAt(const Float4& pt, const std::uint32_t* cell_start_fluid,
                                              const Float4* poscell, const Float4* velrho,
                                              const FluidConstants& c, const CellGrid& g) {
    GaugeSample s;
    forEachCandidateRow<kDim>(pt, cell_start_fluid, c, g, [&](std::uint32_t pb, std::uint32_t pe, const Float4& par,
                                                              int cax) {
        for (std::uint32_t j = pb; j < pe; ++j) {
            float drx, dry, drz;
            const float rr2 = pairOffset<kDim>(par, poscell[j], cax, g, drx, dry, drz);
            if (!(rr2 <= c.ker.kernelsize2)) continue;  // r = 0 counts (not a self-pair)
            const Float4 vj = velrho[j];
            const double w = double(Kernel::value(rr2, c.ker)) * (double(c.massfluid) / double(vj.w));
            s.wsum += w;
            s.mass += w * double(c.massfluid);
            s.vx += w * double(vj.x);
            s.vy += w * double(vj.y);
            s.vz += w * double(vj.z);
            s.press += w * double(taitPressure7(vj.w, c.cteb, c.ovrhop0));
            s.rho += w * double(vj.w);
        }
    });
    return s;
}

/// A sum divided by wsum (Shepard correction), or 0 where wsum < kclimit.
SEASPRING_HD inline double shepard(double sum, double wsum, double kclimit) {
    return wsum >= kclimit && wsum > 0.0 ? sum / wsum : 0.0;
}

/// The SWL gauge's default mass limit, as a fraction of the fluid particle mass (JGaugeSwl:
/// 0.5 in 3D, 0.4 in 2D; <masslimit coef=> overrides it).
inline double swlMassLimitCoef(int dim) { return dim == 3 ? 0.5 : 0.4; }

/// The points of a free-surface line from p0 towards p2 spaced about `pointdp` (JGaugeSwl):
/// np = floor(|p2 - p0| / pointdp), one more when the rest is at least 0.1 pointdp (at least 1);
/// point k = p0 + k dir, k = 0..np (count = np + 1). The in-run SWL gauge and seaspring-post
/// measure's height both take their points from here.
struct SwlLine {
    Double3 point0{0, 0, 0}, dir{0, 0, 0};
    std::uint32_t count = 0;
    Double3 point(std::uint32_t k) const { return Double3{point0.x + dir.x * k, point0.y + dir.y * k, point0.z + dir.z * k}; }
};
inline SwlLine swlLine(const Double3& p0, const Double3& p2, double pointdp) {
    const double dx = p2.x - p0.x, dy = p2.y - p0.y, dz = p2.z - p0.z;
    const double dis = std::sqrt(dx * dx + dy * dy + dz * dz);
    auto np = std::uint32_t(dis / pointdp);
    if (dis - pointdp * np >= pointdp * 0.1) ++np;
    if (np < 1) np = 1;
    const double step = dis / np;
    SwlLine l;
    l.point0 = p0;
    l.dir = Double3{dx / dis * step, dy / dis * step, dz / dis * step};
    l.count = np + 1;
    return l;
}

/// The free surface along the line point0 + k dir, k = 0..n-1, from the SWL masses there
/// (JGaugeSwl): the first point below masslimit that follows one above it, moved back towards
/// that one by linear interpolation. No crossing: the last point when every point was above
/// the limit, point0 when none was (or the line is empty).
SEASPRING_HD inline Double3 swlSurface(const double* mass, int n, const Double3& point0, const Double3& dir,
                                       double masslimit) {
    double mpre = 0.0;
    bool above = false;
    for (int k = 0; k < n; ++k) {
        const double m = mass[k];
        if (m > masslimit) {
            mpre = m;
            above = true;
        } else if (m < masslimit && above) {
            const double f = (masslimit - mpre) / (m - mpre) - 1.0;  // in [-1, 0]
            const double s = double(k) + f;
            return Double3{point0.x + dir.x * s, point0.y + dir.y * s, point0.z + dir.z * s};
        }
    }
    const double s = above ? double(n - 1) : 0.0;
    return Double3{point0.x + dir.x * s, point0.y + dir.y * s, point0.z + dir.z * s};
}

/// One row of cells (y, z) of a maxz gauge's column: fluid cells x0..x1 are searched for the
/// highest particle within sqrt(r2) of the vertical line through (lx, ly) (2D: x only).
struct MaxzRow {
    std::uint32_t row_first_cell;  ///< linear index of cell (0, y, z)
    int x0, x1;                    ///< cell span along x
    double lx, ly, r2;
};

/// The highest z in one row (-1e300 when no fluid particle is in reach); positions `pos` and
/// PosCells `poscell` indexed as cell_start_fluid (particles removed from the run left out).
template <int kDim>
SEASPRING_HD inline double maxzRowAt(const MaxzRow& r, const std::uint32_t* cell_start_fluid, const Double3* pos,
                                     const Float4* poscell) {
    double zmax = -1e300;
    const std::uint32_t pb = cell_start_fluid[r.row_first_cell + std::uint32_t(r.x0)];
    const std::uint32_t pe = cell_start_fluid[r.row_first_cell + std::uint32_t(r.x1) + 1u];
    for (std::uint32_t j = pb; j < pe; ++j) {
        if (removedFromRun(poscell[j])) continue;
        const Double3 p = pos[j];
        const double dx = r.lx - p.x;
        const double dy = kDim == 3 ? r.ly - p.y : 0.0;
        if (dx * dx + dy * dy <= r.r2 && p.z > zmax) zmax = p.z;
    }
    return zmax;
}

/// A plane section: the plane through `o` with unit normal `n`, limited to the crossing points
/// inside the box [lo, hi] (infinite bounds: the whole plane).
struct PlaneSection {
    Double3 o, n, lo, hi;
};

/// Signed distance of p from the section's plane, along n.
SEASPRING_HD inline double planeDistance(const PlaneSection& s, const Double3& p) {
    return (p.x - s.o.x) * s.n.x + (p.y - s.o.y) * s.n.y + (p.z - s.o.z) * s.n.z;
}

/// How a particle that moved (in a straight line) from p0 to p1 crossed the section: +1 from
/// the negative side (distance < 0) to the other (>= 0), -1 back, 0 not at all or outside the
/// box. The crossing point is p0 + (p1 - p0) d0 / (d0 - d1). A particle on the plane counts on
/// the positive side, so one that stops on it has crossed once.
SEASPRING_HD inline int sectionCrossing(const PlaneSection& s, const Double3& p0, const Double3& p1) {
    const double d0 = planeDistance(s, p0), d1 = planeDistance(s, p1);
    const int dir = d0 < 0.0 && d1 >= 0.0 ? 1 : d0 >= 0.0 && d1 < 0.0 ? -1 : 0;
    if (dir == 0) return 0;
    const double f = d0 / (d0 - d1);
    const double x = p0.x + (p1.x - p0.x) * f, y = p0.y + (p1.y - p0.y) * f, z = p0.z + (p1.z - p0.z) * f;
    const bool inside = x >= s.lo.x && x <= s.hi.x && y >= s.lo.y && y <= s.hi.y && z >= s.lo.z && z <= s.hi.z;
    return inside ? dir : 0;
}

/// Marks boundary ids that no gauge asks for (slot_of_id).
constexpr std::uint32_t kNoGaugeSlot = 0xFFFFFFFFu;

/// Boundary particle i (sorted order) gives its position to the gauge slot of its id, if any.
SEASPRING_HD inline void gaugePositionAt(std::uint32_t i, const std::uint32_t* id, const Double3* pos,
                                         const std::uint32_t* slot_of_id, Double3* out) {
    const std::uint32_t k = slot_of_id[id[i]];
    if (k != kNoGaugeSlot) out[k] = pos[i];
}

}  // namespace seaspring::physics
