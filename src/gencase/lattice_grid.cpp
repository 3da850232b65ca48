// SeaSpring — MIT licence.
/// \file lattice_grid.cpp
#include "gencase/lattice_grid.h"

#include <cmath>
#include <string>

#include "core/error.h"
#include "core/memory_budget.h"

namespace seaspring::gencase {

namespace {
// Relative tolerance in units of dp: a coordinate computed as k*dp with round-off still maps to k.
constexpr double kIndexTolerance = 1e-6;
constexpr double kMaxCells = 4.0e9;

double component(Vec3d v, int axis) { return axis == 0 ? v.x : (axis == 1 ? v.y : v.z); }

/// A lattice index from its (already rounded) real value, clamped to +-2^61: far outside any
/// lattice (whose indices are checked against +-2e9), with room for the callers' sums, and never
/// the undefined conversion of an out-of-range double (found by fuzzing: a coordinate of 1e110
/// with dp 0.01). NaN gives the lower bound.
long long clampedIndex(double v) {
    constexpr double kBig = 2305843009213693952.0;  // 2^61
    if (!(v > -kBig)) return -(1LL << 61);
    if (v >= kBig) return 1LL << 61;
    return static_cast<long long>(v);
}
}  // namespace

LatticeGrid::LatticeGrid(Vec3d origin, double dp, Vec3d pointmin, Vec3d pointmax)
    : origin_(origin), dp_(dp) {
    SEASPRING_CHECK(dp > 0, "dp must be positive, got ", dp);
    two_d_ = pointmin.y == pointmax.y;
    if (two_d_) origin_.y = pointmin.y;  // the single plane of a 2D case
    long long lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
        const double o = component(origin_, a);
        lo[a] = clampedIndex(std::ceil((component(pointmin, a) - o) / dp - kIndexTolerance));
        hi[a] = clampedIndex(std::floor((component(pointmax, a) - o) / dp + kIndexTolerance));
        if (hi[a] < lo[a])
            throw Error(detail::concat("pointmin/pointmax give no lattice point along ", "xyz"[a],
                                       ": [", component(pointmin, a), ", ", component(pointmax, a),
                                       "] with dp=", dp));
        if (hi[a] - lo[a] > 2000000000LL)
            throw Error(detail::concat("lattice too long along ", "xyz"[a], " (",
                                       (component(pointmax, a) - component(pointmin, a)) / dp + 1.0,
                                       " points with dp=", dp, ")"));
    }
    const double total = double(hi[0] - lo[0] + 1) * double(hi[1] - lo[1] + 1) * double(hi[2] - lo[2] + 1);
    if (total > kMaxCells)
        throw Error(detail::concat("the lattice between pointmin and pointmax has ", total,
                                   " sites with dp=", dp, " (limit ", kMaxCells,
                                   "): reduce the domain or increase dp"));
    const std::string memory = memoryProblem(detail::concat("the lattice (", total, " sites with dp=", dp, ", 2 bytes each)"),
                                             2.0 * total, "reduce the domain or increase dp");
    if (!memory.empty()) throw Error(memory);
    lo_ = {int(lo[0]), int(lo[1]), int(lo[2])};
    hi_ = {int(hi[0]), int(hi[1]), int(hi[2])};
    nx_ = std::size_t(hi[0] - lo[0] + 1);
    ny_ = std::size_t(hi[1] - lo[1] + 1);
    nz_ = std::size_t(hi[2] - lo[2] + 1);
    cells_.assign(nx_ * ny_ * nz_, 0);
}

long long LatticeGrid::roundIndex(double coord, int axis) const {
    return clampedIndex(std::floor((coord - component(origin_, axis)) / dp_ + 0.5 + kIndexTolerance));
}

Vec3d LatticeGrid::position(int ix, int iy, int iz) const {
    return {origin_.x + ix * dp_, origin_.y + iy * dp_, origin_.z + iz * dp_};
}

}  // namespace seaspring::gencase
