// SeaSpring — MIT licence.
/// \file shapes.cpp
#include "gencase/shapes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/error.h"

namespace seaspring::gencase {

// ---- Affine ---------------------------------------------------------------------------
Vec3d Affine::apply(Vec3d p) const {
    return {r[0][0] * p.x + r[0][1] * p.y + r[0][2] * p.z + t.x,
            r[1][0] * p.x + r[1][1] * p.y + r[1][2] * p.z + t.y,
            r[2][0] * p.x + r[2][1] * p.y + r[2][2] * p.z + t.z};
}

Affine Affine::inverse() const {
    Affine inv;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) inv.r[i][j] = r[j][i];
    const Vec3d mt = inv.apply(t);
    inv.t = {-mt.x, -mt.y, -mt.z};
    return inv;
}

Affine Affine::then(const Affine& inner) const {
    Affine out;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            out.r[i][j] = r[i][0] * inner.r[0][j] + r[i][1] * inner.r[1][j] + r[i][2] * inner.r[2][j];
    out.t = apply(inner.t);
    return out;
}

bool Affine::hasRotation() const {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (r[i][j] != (i == j ? 1.0 : 0.0)) return true;
    return false;
}

Affine Affine::translation(Vec3d d) {
    Affine a;
    a.t = d;
    return a;
}

Affine Affine::rotation(double angle_deg, Vec3d axis) {
    const double n = std::sqrt(dot(axis, axis));
    SEASPRING_CHECK(n > 0, "rotation axis is zero");
    const double x = axis.x / n, y = axis.y / n, z = axis.z / n;
    const double a = angle_deg * M_PI / 180.0, c = std::cos(a), s = std::sin(a), C = 1 - c;
    Affine m;
    const double rr[3][3] = {{c + x * x * C, x * y * C - z * s, x * z * C + y * s},
                             {y * x * C + z * s, c + y * y * C, y * z * C - x * s},
                             {z * x * C - y * s, z * y * C + x * s, c + z * z * C}};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m.r[i][j] = std::fabs(rr[i][j]) < 1e-15 ? 0.0 : rr[i][j];
    return m;
}

namespace {

/// Lattice index range covering a world-space bounding box (clamped to the grid).
struct IndexBox { long long lo[3], hi[3]; bool empty; };

IndexBox worldRange(const LatticeGrid& g, Vec3d a, Vec3d b, double pad) {
    IndexBox r{};
    const double lo[3] = {std::min(a.x, b.x) - pad, std::min(a.y, b.y) - pad, std::min(a.z, b.z) - pad};
    const double hi[3] = {std::max(a.x, b.x) + pad, std::max(a.y, b.y) + pad, std::max(a.z, b.z) + pad};
    const long long glo[3] = {g.lo().x, g.lo().y, g.lo().z}, ghi[3] = {g.hi().x, g.hi().y, g.hi().z};
    r.empty = false;
    for (int k = 0; k < 3; ++k) {
        r.lo[k] = std::max(glo[k], g.roundIndex(lo[k], k) - 1);
        r.hi[k] = std::min(ghi[k], g.roundIndex(hi[k], k) + 1);
        r.empty = r.empty || r.hi[k] < r.lo[k];
    }
    return r;
}

/// World AABB of the local box [lo, hi] under m.
void transformedBounds(const Affine& m, Vec3d lo, Vec3d hi, Vec3d& out_lo, Vec3d& out_hi) {
    out_lo = {1e300, 1e300, 1e300};
    out_hi = {-1e300, -1e300, -1e300};
    for (int c = 0; c < 8; ++c) {
        const Vec3d p = m.apply({(c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z});
        out_lo = {std::min(out_lo.x, p.x), std::min(out_lo.y, p.y), std::min(out_lo.z, p.z)};
        out_hi = {std::max(out_hi.x, p.x), std::max(out_hi.y, p.y), std::max(out_hi.z, p.z)};
    }
}

/// Visits every lattice point of `range`, maps it to shape coordinates with `inv`, and sets
/// `value` where `inside(local)` holds. Parallel over z-planes; each point decided alone.
template <typename Inside>
std::size_t paint(LatticeGrid& g, const IndexBox& range, const Affine& inv, std::uint16_t value,
                  Inside inside) {
    if (range.empty) return 0;
    std::size_t written = 0;
#pragma omp parallel for schedule(static) reduction(+ : written)
    for (long long iz = range.lo[2]; iz <= range.hi[2]; ++iz)
        for (long long iy = range.lo[1]; iy <= range.hi[1]; ++iy)
            for (long long ix = range.lo[0]; ix <= range.hi[0]; ++ix) {
                const Vec3d local = inv.apply(g.position(int(ix), int(iy), int(iz)));
                if (!inside(local)) continue;
                g.set(int(ix), int(iy), int(iz), value);
                ++written;
            }
    return written;
}

double axisOf(Vec3d v, int k) { return k == 0 ? v.x : (k == 1 ? v.y : v.z); }

}  // namespace

std::size_t drawBox(LatticeGrid& g, const Affine& m, Vec3d p0, Vec3d size, unsigned faces,
                    std::uint16_t value) {
    const Vec3d p1 = p0 + size;
    const Vec3d lo{std::min(p0.x, p1.x), std::min(p0.y, p1.y), std::min(p0.z, p1.z)};
    const Vec3d hi{std::max(p0.x, p1.x), std::max(p0.y, p1.y), std::max(p0.z, p1.z)};
    long long ilo[3], ihi[3];
    for (int k = 0; k < 3; ++k) {
        ilo[k] = g.roundIndex(axisOf(lo, k), k);
        ihi[k] = g.roundIndex(axisOf(hi, k), k);
    }
    Vec3d wlo, whi;
    transformedBounds(m, lo, hi, wlo, whi);
    const IndexBox range = worldRange(g, wlo, whi, g.dp());
    return paint(g, range, m.inverse(), value, [&](Vec3d local) {
        long long i[3];
        for (int k = 0; k < 3; ++k) {
            i[k] = g.roundIndex(axisOf(local, k), k);
            if (i[k] < ilo[k] || i[k] > ihi[k]) return false;
        }
        if (faces & BoxSolid) return true;
        return ((faces & FaceLeft) && i[0] == ilo[0]) || ((faces & FaceRight) && i[0] == ihi[0]) ||
               ((faces & FaceFront) && i[1] == ilo[1]) || ((faces & FaceBack) && i[1] == ihi[1]) ||
               ((faces & FaceBottom) && i[2] == ilo[2]) || ((faces & FaceTop) && i[2] == ihi[2]);
    });
}

std::size_t drawCylinder(LatticeGrid& g, const Affine& m, Vec3d p1, Vec3d p2, double radius,
                         DrawMode mode, std::uint16_t value) {
    const Vec3d axis = p2 - p1;
    const double len = std::sqrt(dot(axis, axis));
    SEASPRING_CHECK(len > 0 && radius > 0, "cylinder needs distinct points and a positive radius");
    const Vec3d u = (1.0 / len) * axis;
    const double h = 0.5 * g.dp(), pad = radius + g.dp();
    const IndexBox range = worldRange(g, m.apply(p1), m.apply(p2), pad);  // axis ends, padded by R
    return paint(g, range, m.inverse(), value, [&](Vec3d local) {
        const Vec3d d = local - p1;
        const double t = dot(d, u);
        const Vec3d radial = d - t * u;
        const double rho = std::sqrt(dot(radial, radial));
        const bool full = t > -h && t <= len + h && rho < radius + h;
        const bool interior = t > h && t <= len - h && rho < radius - h;
        if (mode == DrawMode::Full) return full;
        if (mode == DrawMode::Solid) return interior;
        return full && !interior;
    });
}

std::size_t drawSphere(LatticeGrid& g, const Affine& m, Vec3d centre, double radius,
                       DrawMode mode, std::uint16_t value) {
    SEASPRING_CHECK(radius > 0, "sphere needs a positive radius");
    const double h = 0.5 * g.dp();
    const Vec3d c = m.apply(centre);
    const IndexBox range = worldRange(g, c, c, radius + g.dp());
    return paint(g, range, m.inverse(), value, [&](Vec3d local) {
        const Vec3d d = local - centre;
        const double r = std::sqrt(dot(d, d));
        if (mode == DrawMode::Full) return r < radius + h;
        if (mode == DrawMode::Solid) return r < radius - h;
        return r >= radius - h && r < radius + h;
    });
}

std::size_t fillBox(LatticeGrid& g, const Affine& m, Vec3d seed, Vec3d p0, Vec3d size,
                    unsigned mask, std::uint16_t value, std::uint16_t fluid_mk_max) {
    SEASPRING_CHECK(!m.hasRotation(), "fillbox does not support a rotated transform");
    const Vec3d w0 = m.apply(p0), w1 = m.apply(p0 + size), ws = m.apply(seed);
    long long lo[3], hi[3], s[3];
    const long long glo[3] = {g.lo().x, g.lo().y, g.lo().z}, ghi[3] = {g.hi().x, g.hi().y, g.hi().z};
    for (int k = 0; k < 3; ++k) {
        const long long a = g.roundIndex(axisOf(w0, k), k), b = g.roundIndex(axisOf(w1, k), k);
        // Without FillBorder the border planes are excluded (none for the flat axis of 2D).
        const long long shrink = ((mask & FillBorder) || (k == 1 && g.twoD())) ? 0 : 1;
        lo[k] = std::max(std::min(a, b) + shrink, glo[k]);
        hi[k] = std::min(std::max(a, b) - shrink, ghi[k]);
        s[k] = g.roundIndex(axisOf(ws, k), k);
        if (s[k] < lo[k] || s[k] > hi[k]) return 0;
    }
    auto matches = [&](std::uint16_t mk) {
        if (mk == 0) return (mask & FillVoid) != 0;
        return (mk <= fluid_mk_max) ? (mask & FillFluid) != 0 : (mask & FillBound) != 0;
    };
    const std::size_t nx = hi[0] - lo[0] + 1, ny = hi[1] - lo[1] + 1, nz = hi[2] - lo[2] + 1;
    std::vector<bool> visited(nx * ny * nz, false);
    auto local = [&](long long x, long long y, long long z) {
        return (std::size_t(z - lo[2]) * ny + std::size_t(y - lo[1])) * nx + std::size_t(x - lo[0]);
    };
    std::vector<std::array<long long, 3>> stack;
    std::size_t written = 0;
    auto push = [&](long long x, long long y, long long z) {
        if (x < lo[0] || x > hi[0] || y < lo[1] || y > hi[1] || z < lo[2] || z > hi[2]) return;
        const std::size_t l = local(x, y, z);
        if (visited[l] || !matches(g.get(int(x), int(y), int(z)))) return;
        visited[l] = true;
        stack.push_back({x, y, z});
    };
    push(s[0], s[1], s[2]);
    while (!stack.empty()) {
        const auto c = stack.back();
        stack.pop_back();
        g.set(int(c[0]), int(c[1]), int(c[2]), value);
        ++written;
        push(c[0] - 1, c[1], c[2]);
        push(c[0] + 1, c[1], c[2]);
        if (!g.twoD()) {
            push(c[0], c[1] - 1, c[2]);
            push(c[0], c[1] + 1, c[2]);
        }
        push(c[0], c[1], c[2] - 1);
        push(c[0], c[1], c[2] + 1);
    }
    return written;
}

}  // namespace seaspring::gencase
