// SeaSpring — MIT licence.
/// \file vcpm_surface.h
/// \brief Host only: surface correction of the VCPM lattice (issue 13, `VcpmSurfaceCorrection`),
///        in the manner of peridynamics' energy-based surface correction factors (Madenci &
///        Oterkus): a particle near a free surface lacks bonds, so under a uniform strain its
///        energy is below the bulk's and a body a few particles thick is too soft in bending.
///
/// For each lattice site I and each axis d, under the uniform strain of a uniaxial stress along
/// d (eps_dd = 1, eps_ee = -nu_L on the other axes of the lattice's plane or space: the state
/// of a bent plate's fibres; nu_L = nu/(1-nu) in 2D plane strain, nu in 3D) each bond has
/// dl = 1/2 L0 (n . eps . n) (docs/vcpm.md), and the site's energy is
/// W_I^d = sum_J 1/2 k_J dl_J^2 (springs) + 1/2 T (sum_J dl_J)^2 (volumetric). The factor
///     g_I^d = (W_bulk^d - V_I^d) / P_I^d     (P: spring part, V: volumetric part)
/// makes the springs of I alone give back the bulk energy density along d. A bond IJ takes
///     G_IJ = ( sum_d n_d^2 / gbar_d^2 )^(-1/2),   gbar_d = (g_I^d + g_J^d) / 2,
/// the same from both ends (the sum and the squares are symmetric), so both slots of a bond
/// carry one stiffness. A site with all its bonds has g = 1 exactly and its bonds G = 1 unless
/// a partner lacks bonds. Clamp nodes count as complete sites.
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <vector>

#include <Eigen/Dense>

#include "physics/sph_types.h"

namespace seaspring::physics {

/// The complete lattice stencil of `dim` (6 + 12 offsets in 3D, 4 + 4 in the 2D x-z plane), in
/// units of dp, and whether each is a second neighbour (the bulk site of the surface correction
/// and of its sub-step bound).
inline void latticeStencil(int dim, std::vector<Double3>& offsets, std::vector<std::uint8_t>& second) {
    offsets.clear();
    second.clear();
    for (int i = -1; i <= 1; ++i)
        for (int j = -1; j <= 1; ++j)
            for (int k = -1; k <= 1; ++k) {
                const int nz = (i != 0) + (j != 0) + (k != 0);
                if (nz == 0 || nz == 3 || (dim == 2 && j != 0)) continue;
                offsets.push_back(Double3{double(i), double(j), double(k)});
                second.push_back(nz == 2);
            }
}

/// Spring and volumetric energy of a site under the uniaxial-stress strain along axis d
/// (lateral strain -nu_l on the other axes; `dim` 2: the lattice's x-z plane) of bonds with
/// rest vectors `r` (to each partner) and stiffnesses `k`; `t_half` = T/2.
/// `w`: the volumetric weights of the bonds (volumetricWeights; empty: all 1).
inline void uniformStrainEnergy(const std::vector<Double3>& r, const std::vector<double>& k, double t_half, int d,
                                double nu_l, int dim, double& spring, double& volumetric,
                                const std::vector<double>& w = {}) {
    spring = 0;
    double sum = 0;
    for (std::size_t j = 0; j < r.size(); ++j) {
        const double l0 = std::sqrt(r[j].x * r[j].x + r[j].y * r[j].y + r[j].z * r[j].z);
        const double n[3] = {r[j].x / l0, r[j].y / l0, r[j].z / l0};
        double e = 0;
        for (int a = 0; a < 3; ++a) {
            if (dim == 2 && a == 1) continue;
            e += (a == d ? 1.0 : -nu_l) * n[a] * n[a];
        }
        const double dl = 0.5 * l0 * e;
        spring += 0.5 * k[j] * dl * dl;
        sum += w.empty() ? dl : w[j] * dl;
    }
    volumetric = t_half * sum * sum;
}

/// g_I^d from the site's energies and the bulk's, never below 1 (1 when the site has no spring
/// along d). Near nu = 1/2 a surface site's volumetric energy under the uniaxial stress exceeds
/// the bulk's (its partial sum S misses the bonds the lateral contraction shortens): there the
/// lattice's surface is too stiff, not too soft, and weakening its springs made the beams far
/// softer (measured: docs/vcpm.md), so such sites keep their springs.
inline double surfaceFactor(double bulk_total, double spring, double volumetric) {
    if (!(spring > 0)) return 1.0;
    const double g = (bulk_total - volumetric) / spring;
    return g > 1.0 ? g : 1.0;
}

/// G_IJ of a bond of direction n (unit) between sites of factors gi and gj (per axis; 2D: the
/// y entries are 1 and n.y = 0).
inline double bondSurfaceFactor(const Double3& n, const Double3& gi, const Double3& gj) {
    const double gx = 0.5 * (gi.x + gj.x), gy = 0.5 * (gi.y + gj.y), gz = 0.5 * (gi.z + gj.z);
    if (gx == 1.0 && gy == 1.0 && gz == 1.0) return 1.0;  // exactly: n may be a rounding off unit length
    return 1.0 / std::sqrt(n.x * n.x / (gx * gx) + n.y * n.y / (gy * gy) + n.z * n.z / (gz * gz));
}

/// The volumetric weights w_J of a site's bonds (rest vectors r to its partners; `dim` 2: the
/// lattice's x-z plane; `alpha` the complete site's, below). Under a uniform strain eps each
/// bond has dl_J = 1/2 L_J n_J.eps.n_J, so the weighted sum
///     S* = sum_J w_J dl_J = 1/2 (sum_J w_J L_J n_J (x) n_J) : eps.
/// A complete site has sum_J L_J n_J (x) n_J = alpha I (alpha = (2 + 2 sqrt2) dp in 2D,
/// (2 + 4 sqrt2) dp in 3D): its S measures tr(eps) alone. A site that lacks bonds does not:
/// along a free surface its S also sees the strain along the surface, so near nu = 1/2 (T
/// large) a bent plate's surface pays volumetric energy for a deformation that keeps its
/// volume, and thin plates stiffen. The weights make the site's tensor isotropic again: the w
/// nearest to 1 (least squares) with
///     sum_J w_J L_J n_J (x) n_J = alpha_I I,
/// the minimum-norm correction w = 1 + A^T lambda of the linear constraints (one row per
/// component of the symmetric tensor), solved with Eigen's complete orthogonal decomposition.
/// alpha_I: first left free (only the deviatoric part vanishes; the solution's alpha_I is
/// 0.57 alpha on a 2D face, 0.64 on a 3D face, 0.21-0.31 on edges, 0.13 at a 3D corner). Where
/// that free alpha_I is at least alpha/2 (a face site: it lacks the bonds of one side), the
/// weights are solved again with alpha_I = alpha, so that its S* is a complete site's (its
/// weights stay within 1.03-2.1). Edges and corners keep the free solution: with alpha_I =
/// alpha their weights reach 3.6 (2D) to 7.7 (3D corner), and the 3D cantilever 4 particles
/// thick at nu = 0.49 then blew up at VcpmDtCoef 0.8 (docs/vcpm.md). A site with all its
/// bonds has w = 1. Empty when no weights satisfy the constraints (a site whose bonds cannot
/// make an isotropic tensor): the site keeps its plain sum.
inline std::vector<double> volumetricWeights(const std::vector<Double3>& r, int dim, double alpha) {
    const std::size_t nb = r.size();
    const Eigen::Index n = Eigen::Index(nb);
    // The components of r_J (x) r_J / L_J: 2D (xx, zz, xz), 3D (xx, yy, zz, xy, xz, yz).
    const int nc = dim == 2 ? 3 : 6, nd = dim == 2 ? 2 : 3;
    Eigen::MatrixXd C(nc, n);
    for (std::size_t j = 0; j < nb; ++j) {
        const Double3 v = r[j];
        const double l = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
        const Eigen::Index c = Eigen::Index(j);
        if (dim == 2) {
            C(0, c) = v.x * v.x / l;
            C(1, c) = v.z * v.z / l;
            C(2, c) = v.x * v.z / l;
        } else {
            C(0, c) = v.x * v.x / l;
            C(1, c) = v.y * v.y / l;
            C(2, c) = v.z * v.z / l;
            C(3, c) = v.x * v.y / l;
            C(4, c) = v.x * v.z / l;
            C(5, c) = v.y * v.z / l;
        }
    }
    const Eigen::VectorXd ones = Eigen::VectorXd::Ones(n);
    // w = 1 + A^T lambda with A A^T lambda = b - A 1: the w nearest to 1 with A w = b.
    auto solve = [&](const Eigen::MatrixXd& A, const Eigen::VectorXd& b) -> Eigen::VectorXd {
        const Eigen::MatrixXd g = A * A.transpose();
        const Eigen::VectorXd lambda = g.completeOrthogonalDecomposition().solve(b - A * ones);
        const Eigen::VectorXd w = ones + A.transpose() * lambda;
        if (!((A * w - b).norm() <= 1e-12 * (alpha + b.norm()))) return Eigen::VectorXd();
        return w;
    };
    // Free alpha_I: consecutive diagonal differences and the off-diagonal components vanish.
    Eigen::MatrixXd A_free(nc - 1, n);
    for (int d = 0; d + 1 < nd; ++d) A_free.row(d) = C.row(d) - C.row(d + 1);
    for (int o = nd; o < nc; ++o) A_free.row(o - 1) = C.row(o);
    Eigen::VectorXd w = solve(A_free, Eigen::VectorXd::Zero(nc - 1));
    if (w.size() == 0 || !(w.sum() > 0.5)) return {};
    const double alpha_free = (C.topRows(nd) * w).sum() / nd;
    if (alpha_free >= 0.5 * alpha) {  // a face site: the complete site's alpha
        Eigen::VectorXd b = Eigen::VectorXd::Zero(nc);
        b.head(nd).setConstant(alpha);
        const Eigen::VectorXd wf = solve(C, b);
        if (wf.size() == n) w = wf;
    }
    return std::vector<double>(w.data(), w.data() + nb);
}

/// The sub-step limit of the corrected lattice. The explicit sub-step is stable while
/// dt < 2 / omega_max, omega_max^2 = lambda_max(K) / m, K the lattice's stiffness matrix (the
/// Hessian of U in the particles' positions). Stronger springs and weighted volumetric sums at
/// the surface raise lambda_max above the plain bulk lattice's, for which VcpmDtCoef (0.8) is
/// calibrated: the 2D Antoci gate, 2 particles thick (every site a face site), blew up at 0.8
/// with the correction and ran at 0.3. Linearised, with e_IJ = |r_IJ| - L0 and b_IJ the unit
/// vector u_IJ = (r_J - r_I)/|r_J - r_I| placed -u at I and +u at J (e_IJ = b_IJ . x),
///     U = sum_bonds k_IJ/4 e_IJ^2 + sum_sites t_half/4 (sum_J w_IJ e_IJ)^2.
/// The body's lambda_max comes from the solver's own force functions (solver/solid_stability.h);
/// the plain bulk lattice's is this function: with a plane wave x_I = a exp(i q.R_I) the
/// energy per site is 1/2 a^H D(q) a,
///     D(q) = sum_J k_J sin^2(q.d_J / 2) u_J u_J^T + t_half/2 g g^H,  g = sum_J u_J (exp(i q.d_J) - 1),
/// over the stencil's offsets d_J (units of dp, unit vectors u_J, stiffnesses k_J), and
/// lambda_max = max over q of D(q)'s largest eigenvalue: here on a grid of the Brillouin zone
/// (64 x 64 in 2D, 32^3 in 3D, the zone's corners and edge midpoints included, where the
/// largest lie). A grid maximum is never above the true one, so the sub-step it sets errs
/// on the short side.
inline double plainBulkLargestStiffness(int dim, double k_first, double k_second, double t_half) {
    std::vector<Double3> d;
    std::vector<std::uint8_t> second;
    latticeStencil(dim, d, second);
    const int n = dim == 2 ? 64 : 32;
    const double pi = 3.14159265358979323846;
    double best = 0.0;
    for (int a = 0; a < n; ++a)
        for (int b = 0; b < (dim == 3 ? n : 1); ++b)
            for (int c = 0; c < n; ++c) {
                const double qx = 2 * pi * a / n, qy = dim == 3 ? 2 * pi * b / n : 0.0, qz = 2 * pi * c / n;
                Eigen::Matrix3cd D = Eigen::Matrix3cd::Zero();
                Eigen::Vector3cd g = Eigen::Vector3cd::Zero();
                for (std::size_t j = 0; j < d.size(); ++j) {
                    const double len = std::sqrt(d[j].x * d[j].x + d[j].y * d[j].y + d[j].z * d[j].z);
                    const Eigen::Vector3d u(d[j].x / len, d[j].y / len, d[j].z / len);
                    const double qd = qx * d[j].x + qy * d[j].y + qz * d[j].z, sn = std::sin(0.5 * qd);
                    D += ((second[j] ? k_second : k_first) * sn * sn * (u * u.transpose())).cast<std::complex<double>>();
                    g += u.cast<std::complex<double>>() * (std::complex<double>(std::cos(qd), std::sin(qd)) - 1.0);
                }
                D += (0.5 * t_half) * (g * g.adjoint());
                best = std::max(best, Eigen::SelfAdjointEigenSolver<Eigen::Matrix3cd>(D, Eigen::EigenvaluesOnly)
                                          .eigenvalues()
                                          .maxCoeff());
            }
    return best;
}

/// Gershgorin's bound (VcpmSubStepBound 0): lambda_max <= the largest absolute row sum of K,
/// where K = sum_bonds k_IJ/2 b b^T + sum_sites t_half/2 g_I g_I^T, g_I = sum_J w_IJ b_IJ, and
/// each rank-1 term c v v^T adds |c| |v_a| ||v||_1 to row a (rigid clamp nodes carry no rows).
/// R_bulk, component c, of a complete site of the plain lattice (the stencil's unit vectors u_J
/// and stiffnesses k_J): its springs sum_J k_J |u_J,c| ||u_J||_1 (a bond's term reaches both
/// ends), its own volumetric term nothing (sum_J u_J = 0), and each neighbour's
/// t_half/2 |u_J,c| sum_J' ||u_J'||_1.
inline double plainBulkRowBound(const std::vector<Double3>& u, const std::vector<double>& k, double t_half, int c) {
    auto comp = [c](const Double3& v) { return std::fabs(c == 0 ? v.x : c == 1 ? v.y : v.z); };
    auto norm1 = [](const Double3& v) { return std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z); };
    double springs = 0, sum_norm = 0, sum_c = 0;
    for (std::size_t j = 0; j < u.size(); ++j) {
        springs += k[j] * comp(u[j]) * norm1(u[j]);
        sum_norm += norm1(u[j]);
        sum_c += comp(u[j]);
    }
    return springs + 0.5 * std::fabs(t_half) * sum_c * sum_norm;
}

/// The factor of a clamp bond's stiffness. A clamp node is a site of the rigid support: the
/// half of the bond inside its cell does not deform, so the bond's whole elongation is the
/// strain of its solid half, of half the rest length, whose stiffness is twice the bond's.
/// Without it the clamp acts half a bond further into the support than the support's face
/// (the cells' boundary between the clamp row and the first solid row), and a cantilever
/// is longer by about dp/2 (issue 13: "the clamp plane shifts the effective length by O(dp)").
constexpr double kClampBondFactor = 2.0;

}  // namespace seaspring::physics
