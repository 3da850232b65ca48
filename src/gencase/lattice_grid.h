// SeaSpring — MIT licence.
/// \file lattice_grid.h
/// \brief The dense lattice GenCase draws on: one cell per possible particle position.
///
/// Positions are origin + k*dp (origin = `<pointref>`, default (0,0,0)). Only indices whose
/// positions lie inside [pointmin, pointmax] exist. A cell holds the global MK of the particle
/// drawn there (fluid mk+1, boundary mk+fluidcount+1) or 0 when empty. Later drawing replaces
/// earlier drawing, as in GenCase. In 2D (pointmin.y == pointmax.y) the lattice is one plane at
/// y = pointmin.y.
#pragma once

#include <cstdint>
#include <vector>

#include "core/vec3.h"

namespace seaspring::gencase {

class LatticeGrid {
public:
    LatticeGrid() = default;
    /// Throws seaspring::Error if the lattice would be empty or too large for memory.
    LatticeGrid(Vec3d origin, double dp, Vec3d pointmin, Vec3d pointmax);

    bool twoD() const { return two_d_; }
    double dp() const { return dp_; }
    Vec3d origin() const { return origin_; }
    Vec3i lo() const { return lo_; }  ///< first valid index per axis
    Vec3i hi() const { return hi_; }  ///< last valid index per axis (inclusive)
    std::size_t cellCount() const { return cells_.size(); }

    /// Lattice index nearest to a coordinate along an axis (round half up, with a small
    /// tolerance so that values computed as k*dp land on k). Axis 0,1,2 = x,y,z.
    long long roundIndex(double coord, int axis) const;
    Vec3d position(int ix, int iy, int iz) const;
    bool contains(long long ix, long long iy, long long iz) const {
        return ix >= lo_.x && ix <= hi_.x && iy >= lo_.y && iy <= hi_.y && iz >= lo_.z && iz <= hi_.z;
    }
    std::size_t linear(int ix, int iy, int iz) const {
        return (static_cast<std::size_t>(iz - lo_.z) * ny_ + static_cast<std::size_t>(iy - lo_.y)) * nx_ +
               static_cast<std::size_t>(ix - lo_.x);
    }
    std::uint16_t get(int ix, int iy, int iz) const { return cells_[linear(ix, iy, iz)]; }
    void set(int ix, int iy, int iz, std::uint16_t mk) { cells_[linear(ix, iy, iz)] = mk; }

    std::size_t nx() const { return nx_; }
    std::size_t ny() const { return ny_; }
    std::size_t nz() const { return nz_; }
    const std::vector<std::uint16_t>& cells() const { return cells_; }

private:
    Vec3d origin_{0, 0, 0};
    double dp_ = 0;
    bool two_d_ = false;
    Vec3i lo_{0, 0, 0}, hi_{-1, -1, -1};
    std::size_t nx_ = 0, ny_ = 0, nz_ = 0;
    std::vector<std::uint16_t> cells_;
};

}  // namespace seaspring::gencase
