// SeaSpring — MIT licence.
/// \file mdbc_solid.h
/// \brief mDBC on VCPM solid surfaces: the ghost vector of a solid particle follows the
///        deformation of the lattice around it.
///
/// gencase gives every solid particle near the fluid its ghost vector n0 in the undeformed
/// lattice. Now, the local deformation gradient F of particle s is the least-squares fit over
/// its intact solid-solid bonds (reference vectors dX = X_s - X_j from the initial positions,
/// current dx = x_s - x_j):
///   F A = B,  A = sum dX dX^T,  B = sum dx dX^T,
/// and a surface normal is carried by Nanson's formula, n ~ F^-T n0 = B^-T (A n0). The ghost
/// vector keeps its length: n = |n0| m / |m|, m = B^-T A n0. 2D works in the x-z plane. Where the
/// fit is singular (fewer than kDim independent intact bonds: a fragment, a broken edge) the
/// particle keeps n0 rotated by nothing, i.e. n0 itself.
/// Plain double arithmetic in a fixed order: the same bits on both backends.
#pragma once

#include <cstdint>

#include "physics/sph_types.h"
#include "physics/vcpm.h"

namespace seaspring::physics {

/// The ghost vector of solid particle s now (see the file comment). `pos`: current positions,
/// `pos0`: initial positions, both in solid-index order; `b`: the bond slots.
template <int kDim>
SEASPRING_HD inline Double3 solidGhostVector(std::uint32_t s, const Double3& n0, const Double3* pos,
                                             const Double3* pos0, const SolidBonds& b) {
    // Axes: 2D (x, z), 3D (x, y, z).
    double a[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, bm[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    const Double3 p = pos[s], p0 = pos0[s];
    const int nb = b.count[s];
    for (int q = 0; q < nb; ++q) {
        const std::uint32_t k = std::uint32_t(q) * b.n + s;
        if ((b.flags[k] & kBondClamp) || b.broken[k]) continue;
        const std::uint32_t j = b.partner[k];
        const double dX[3] = {p0.x - pos0[j].x, kDim == 3 ? p0.y - pos0[j].y : p0.z - pos0[j].z, p0.z - pos0[j].z};
        const double dx[3] = {p.x - pos[j].x, kDim == 3 ? p.y - pos[j].y : p.z - pos[j].z, p.z - pos[j].z};
        for (int r = 0; r < kDim; ++r)
            for (int c = 0; c < kDim; ++c) {
                a[r][c] += dX[r] * dX[c];
                bm[r][c] += dx[r] * dX[c];
            }
    }
    const double nv[3] = {n0.x, kDim == 3 ? n0.y : n0.z, n0.z};
    double an[3] = {0, 0, 0};  // A n0
    for (int r = 0; r < kDim; ++r)
        for (int c = 0; c < kDim; ++c) an[r] += a[r][c] * nv[c];
    // m = B^-T an: solve B^T m = an by the adjugate (2x2, 3x3).
    double m[3] = {0, 0, 0}, det;
    if (kDim == 2) {
        det = bm[0][0] * bm[1][1] - bm[0][1] * bm[1][0];
        // B^T = [[b00, b10], [b01, b11]]; its inverse = [[b11, -b10], [-b01, b00]] / det.
        m[0] = (bm[1][1] * an[0] - bm[1][0] * an[1]);
        m[1] = (-bm[0][1] * an[0] + bm[0][0] * an[1]);
    } else {
        // t = B^T; inverse(t) = adj(t) / det(t); det(B^T) = det(B).
        const double t[3][3] = {{bm[0][0], bm[1][0], bm[2][0]}, {bm[0][1], bm[1][1], bm[2][1]}, {bm[0][2], bm[1][2], bm[2][2]}};
        const double c00 = t[1][1] * t[2][2] - t[1][2] * t[2][1];
        const double c01 = t[1][2] * t[2][0] - t[1][0] * t[2][2];
        const double c02 = t[1][0] * t[2][1] - t[1][1] * t[2][0];
        det = t[0][0] * c00 + t[0][1] * c01 + t[0][2] * c02;
        const double adj[3][3] = {{c00, t[0][2] * t[2][1] - t[0][1] * t[2][2], t[0][1] * t[1][2] - t[0][2] * t[1][1]},
                                  {c01, t[0][0] * t[2][2] - t[0][2] * t[2][0], t[0][2] * t[1][0] - t[0][0] * t[1][2]},
                                  {c02, t[0][1] * t[2][0] - t[0][0] * t[2][1], t[0][0] * t[1][1] - t[0][1] * t[1][0]}};
        for (int r = 0; r < 3; ++r) m[r] = adj[r][0] * an[0] + adj[r][1] * an[1] + adj[r][2] * an[2];
    }
    // A singular fit (or a reflected one): keep n0. The adjugate solution is m * det; its
    // direction is what matters, so divide by |m det| with det's sign.
    double trace_a = 0.0;
    for (int r = 0; r < kDim; ++r) trace_a += a[r][r];
    const double scale = trace_a * trace_a * (kDim == 3 ? trace_a : 1.0);  // det's units
    if (!(det > 1e-9 * scale)) return n0;
    double len2 = 0.0;
    for (int r = 0; r < kDim; ++r) len2 += m[r] * m[r];
    const double len0 = sqrt(n0.x * n0.x + n0.y * n0.y + n0.z * n0.z);
    if (!(len2 > 0.0)) return n0;
    const double f = len0 / sqrt(len2);
    return kDim == 3 ? Double3{m[0] * f, m[1] * f, m[2] * f} : Double3{m[0] * f, 0.0, m[1] * f};
}

}  // namespace seaspring::physics
