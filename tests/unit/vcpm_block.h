// SeaSpring — MIT licence.
/// \file vcpm_block.h
/// \brief Test helper: a small VCPM lattice block built from gencase's lattice offsets, in the
///        SolidBonds layout, with the force (through physics/vcpm.h's passes), an independent
///        energy, affine and random displacements. Used by test_vcpm_physics.cpp and
///        test_vcpm_surface.cpp.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "core/vec3.h"
#include "gencase/vcpm_bonds.h"
#include "physics/vcpm.h"
#include "physics/vcpm_substep.h"

namespace seaspring::test {

using physics::ClampNodes;
using physics::Double3;
using physics::kBondSecond;
using physics::SolidBonds;
using physics::SolidState;
using physics::VcpmMaterial;
using Mat3 = std::array<std::array<double, 3>, 3>;

/// A block of nx*ny*nz lattice sites (2D: ny = 1, sites in the x-z plane), centred on the origin,
/// with all its solid-solid bonds in the SolidBonds layout (slots compacted in offset order).
struct Block {
    bool two_d;
    int nx, ny, nz;
    double dp;
    VcpmMaterial mat;
    std::uint32_t n;
    std::vector<Vec3i> site;
    std::vector<Double3> ref, pos, pos_half, vel, vel0, ffluid;
    std::vector<std::uint8_t> count, flags, broken;
    std::vector<std::uint32_t> partner, mirror;  // mirror: slot of the same bond at the partner
    std::vector<double> rest, sum;
    std::vector<double> vw, vw_partner;  // volumetric weights (empty: none; physics/vcpm_surface.h)
    std::vector<std::uint16_t> body;
    /// The rows' bending (empty: none; physics/vcpm_rows.h): slots per axis and side, curvatures.
    std::vector<std::uint8_t> row_slot;
    std::vector<Double3> row_d;
    int row_axes = 0;

    Block(bool td, int nx_, int ny_, int nz_, double dp_, const VcpmMaterial& m)
        : two_d(td), nx(nx_), ny(td ? 1 : ny_), nz(nz_), dp(dp_), mat(m), n(std::uint32_t(nx * ny * nz)) {
        for (int k = 0; k < nz; ++k)
            for (int j = 0; j < ny; ++j)
                for (int i = 0; i < nx; ++i) {
                    site.push_back({i, j, k});
                    ref.push_back({(i - 0.5 * (nx - 1)) * dp, two_d ? 0.0 : (j - 0.5 * (ny - 1)) * dp,
                                   (k - 0.5 * (nz - 1)) * dp});
                }
        const auto& off = gencase::latticeOffsets(two_d);
        const std::size_t nfirst = gencase::firstNeighbourCount(two_d), slots = off.size() * n;
        count.assign(n, 0);
        flags = broken = std::vector<std::uint8_t>(slots, 0);
        partner = mirror = std::vector<std::uint32_t>(slots, 0);
        rest.assign(slots, 0.0);
        for (std::uint32_t s = 0; s < n; ++s)
            for (std::size_t q = 0; q < off.size(); ++q) {
                const int i = site[s].x + off[q].x, j = site[s].y + off[q].y, k = site[s].z + off[q].z;
                if (i < 0 || i >= nx || j < 0 || j >= ny || k < 0 || k >= nz) continue;
                const std::uint32_t sl = slot(s, count[s]++);
                partner[sl] = at(i, j, k);
                rest[sl] = q < nfirst ? dp : std::sqrt(2.0) * dp;
                flags[sl] = q < nfirst ? 0 : kBondSecond;
            }
        for (std::uint32_t s = 0; s < n; ++s)
            for (int q = 0; q < count[s]; ++q) {
                const std::uint32_t j = partner[slot(s, q)];
                for (int q2 = 0; q2 < count[j]; ++q2)
                    if (partner[slot(j, q2)] == s) mirror[slot(s, q)] = slot(j, q2);
            }
        pos = pos_half = ref;
        vel = vel0 = ffluid = std::vector<Double3>(n, Double3{0, 0, 0});
        sum.assign(n, 0.0);
        body.assign(n, 0);
    }
    std::uint32_t at(int i, int j, int k) const { return std::uint32_t((k * ny + j) * nx + i); }
    std::uint32_t slot(std::uint32_t s, int q) const { return std::uint32_t(q) * n + s; }
    /// True when every neighbour of s has a complete neighbourhood (>= 2 sites from each face).
    bool deep(std::uint32_t s) const {
        auto ok = [](int i, int m) { return i >= 2 && i < m - 2; };
        return ok(site[s].x, nx) && ok(site[s].z, nz) && (two_d || ok(site[s].y, ny));
    }
    /// Switches the rows' bending on with stiffness k_r: each particle's first-neighbour slots
    /// along each axis, from the lattice sites (independent of the solver's set-up).
    void setRows(double k_r) {
        mat.row_k = k_r;
        row_axes = two_d ? 2 : 3;
        row_slot.assign(std::size_t(2 * row_axes) * n, physics::kNoRowSlot);
        row_d.assign(std::size_t(row_axes) * n, Double3{0, 0, 0});
        for (std::uint32_t s = 0; s < n; ++s)
            for (int q = 0; q < count[s]; ++q) {
                const std::uint32_t j = partner[slot(s, q)];
                const int d[3] = {site[j].x - site[s].x, site[j].y - site[s].y, site[j].z - site[s].z};
                if (std::abs(d[0]) + std::abs(d[1]) + std::abs(d[2]) != 1) continue;
                for (int c = 0; c < 3; ++c)
                    if (d[c] != 0) {
                        const int a = two_d ? (c == 2 ? 1 : 0) : c;
                        row_slot[std::size_t(2 * a + (d[c] > 0 ? 1 : 0)) * n + s] = std::uint8_t(q);
                    }
            }
    }
    SolidBonds bonds() {
        SolidBonds b{n, count.data(), partner.data(), rest.data(), flags.data(), broken.data()};
        if (!vw.empty()) {
            b.vw = vw.data();
            b.vw_partner = vw_partner.data();
        }
        if (row_axes > 0) {
            b.row_slot = row_slot.data();
            b.row_d = row_d.data();
            b.row_axes = row_axes;
        }
        return b;
    }
    SolidState state() {
        SolidState st;
        st.pos = pos.data();
        st.pos_half = pos_half.data();
        st.vel = vel.data();
        st.vel0 = vel0.data();
        st.sum = sum.data();
        st.fluid_force = ffluid.data();
        st.body = body.data();
        st.material = &mat;
        return st;  // no alarms array: raiseSolidAlarm ignores a null one
    }
};

/// S (pass 1, may break bonds) then the bond force on every particle at positions x.
inline std::vector<Double3> forces(Block& b, const std::vector<Double3>& x) {
    const SolidState st = b.state();
    const SolidBonds sb = b.bonds();
    const ClampNodes cn{};
    for (std::uint32_t s = 0; s < b.n; ++s) b.sum[s] = physics::solidSumAt(s, x.data(), st, sb, cn, 0.0);
    std::vector<Double3> f(b.n);
    for (std::uint32_t s = 0; s < b.n; ++s) f[s] = physics::solidBondForceAt(s, x.data(), st, sb, cn, 0.0);
    return f;
}

inline double norm(const Double3& a) { return std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z); }
inline double& comp(Double3& a, int c) { return c == 0 ? a.x : c == 1 ? a.y : a.z; }

/// Adds a uniform random displacement in [-amp, amp] to each in-plane coordinate.
inline void perturb(std::vector<Double3>& x, double amp, bool two_d, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-amp, amp);
    for (Double3& p : x)
        for (int c = 0; c < 3; ++c)
            if (!two_d || c != 1) comp(p, c) += u(rng);
}

/// Lattice energy U = sum_I [1/2 sum_J k dl^2 + 1/2 T S_I^2] over intact bonds (independent code;
/// S_I weighted by b.vw when the block has volumetric weights).
inline double energy(const Block& b, const std::vector<Double3>& x) {
    double u = 0.0;
    for (std::uint32_t s = 0; s < b.n; ++s) {
        double S = 0.0;
        for (int q = 0; q < b.count[s]; ++q) {
            const std::uint32_t k = b.slot(s, q);
            if (b.broken[k]) continue;
            const Double3 a = x[s], c = x[b.partner[k]];
            const double dl = 0.5 * (norm(Double3{a.x - c.x, a.y - c.y, a.z - c.z}) - b.rest[k]);
            u += 0.5 * ((b.flags[k] & kBondSecond) ? b.mat.k_second : b.mat.k_first) * dl * dl;
            S += b.vw.empty() ? dl : b.vw[k] * dl;
        }
        u += b.mat.t_half * S * S;  // 1/2 T S^2 with T = 2 t_half
    }
    // The rows' bending: 1/2 k_r |x+ - 2 x + x-|^2 per site with intact first-neighbour bonds
    // on both sides along an axis (found from the sites, not from the row slots).
    for (std::uint32_t s = 0; b.row_axes > 0 && s < b.n; ++s)
        for (int c = 0; c < 3; ++c) {
            if (b.two_d && c == 1) continue;
            int nb[2] = {-1, -1};
            for (int q = 0; q < b.count[s]; ++q) {
                const std::uint32_t k = b.slot(s, q), j = b.partner[k];
                const int d[3] = {b.site[j].x - b.site[s].x, b.site[j].y - b.site[s].y, b.site[j].z - b.site[s].z};
                if (b.broken[k] || std::abs(d[0]) + std::abs(d[1]) + std::abs(d[2]) != 1 || d[c] == 0) continue;
                nb[d[c] > 0 ? 1 : 0] = int(j);
            }
            if (nb[0] < 0 || nb[1] < 0) continue;
            const Double3 m = x[std::uint32_t(nb[0])], p = x[std::uint32_t(nb[1])], o = x[s];
            const double dx = m.x + p.x - 2 * o.x, dy = m.y + p.y - 2 * o.y, dz = m.z + p.z - 2 * o.z;
            u += 0.5 * b.mat.row_k * (dx * dx + dy * dy + dz * dz);
        }
    return u;
}

/// x = (I + scale eps) ref; with id = 0, x = scale eps ref.
inline std::vector<Double3> affine(const Block& b, const Mat3& e, double scale, double id = 1.0) {
    std::vector<Double3> x(b.n);
    for (std::uint32_t s = 0; s < b.n; ++s) {
        Double3 r = b.ref[s], y;
        for (int i = 0; i < 3; ++i)
            comp(y, i) = id * comp(r, i) + scale * (e[i][0] * r.x + e[i][1] * r.y + e[i][2] * r.z);
        x[s] = y;
    }
    return x;
}

/// The block under a random uniform strain (components in [-strain, strain], in-plane in 2D)
/// plus a random displacement in [-amp, amp] of each particle, from a fixed seed.
inline std::vector<Double3> randomlyDeformed(const Block& b, double strain, double amp, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Mat3 eps{};
    for (int i = 0; i < 3; ++i)
        for (int l = 0; l < 3; ++l) eps[i][l] = (b.two_d && (i == 1 || l == 1)) ? 0.0 : strain * u(rng);
    std::vector<Double3> x = affine(b, eps, 1.0);
    perturb(x, amp, b.two_d, rng);
    return x;
}

/// max |F + dU/dx| / max |F| at positions x, F from the passes of vcpm.h (forces), dU/dx by
/// central differences of the independent energy (step 1e-5 dp).
inline double forceEnergyMismatch(Block& b, const std::vector<Double3>& x) {
    std::vector<Double3> f = forces(b, x);
    double fmax = 0.0, err = 0.0;
    for (Double3 v : f) fmax = std::max(fmax, norm(v));
    const double h = 1e-5 * b.dp;
    for (std::uint32_t s = 0; s < b.n; ++s)
        for (int c = 0; c < 3; ++c) {
            if (b.two_d && c == 1) continue;
            std::vector<Double3> xp = x, xm = x;
            comp(xp[s], c) += h;
            comp(xm[s], c) -= h;
            const double g = -(energy(b, xp) - energy(b, xm)) / (2 * h);
            err = std::max(err, std::fabs(comp(f[s], c) - g));
        }
    return err / fmax;
}

}  // namespace seaspring::test
