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

#include <cmath>
#include <vector>

#include "physics/sph_types.h"

namespace seaspring::physics {

/// Spring and volumetric energy of a site under the uniaxial-stress strain along axis d
/// (lateral strain -nu_l on the other axes; `dim` 2: the lattice's x-z plane) of bonds with
/// rest vectors `r` (to each partner) and stiffnesses `k`; `t_half` = T/2.
inline void uniformStrainEnergy(const std::vector<Double3>& r, const std::vector<double>& k, double t_half, int d,
                                double nu_l, int dim, double& spring, double& volumetric) {
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
        sum += dl;
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

}  // namespace seaspring::physics
