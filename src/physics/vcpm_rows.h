// SeaSpring — MIT licence.
/// \file vcpm_rows.h
/// \brief The rows' own bending of the VCPM lattice (issue 13, `VcpmRowBending`, part 4 of the
///        surface correction; docs/vcpm.md "4. The rows' own bending").
///
/// A central-force lattice carries a bent body's moment only through the axial forces of its
/// rows of particles, lumped on the rows' centre lines: a section of N rows has the second
/// moment sum_k y_k^2 dp = N (N^2 - 1)/12 dp^3 (per unit width) where the continuum has N^3/12
/// dp^3. The missing N dp^3/12 is each row's own bending (a strip of thickness dp), -3.1% in a
/// cantilever's frequency at 4 particles through the thickness and -0.8% at 8, whatever the
/// spring factors do. Each particle I with intact first-neighbour bonds on both sides along a
/// lattice axis a (I- and I+) is the centre of a row triplet with the discrete curvature
///     d_I^a = (r_I+ - r_I) - (r_I - r_I-)
/// and the energy 1/2 k_r |d_I^a|^2. A row of spacing dp bent to curvature kappa has
/// |d| = kappa dp^2, i.e. an energy per unit length 1/2 k_r kappa^2 dp^3, the strip's
/// 1/2 E_u I_row kappa^2 when
///     k_r = E_u / 12 (2D, per unit thickness),   k_r = E_u dp / 12 (3D),
/// with E_u the lattice's uniaxial-stress modulus (2D: E/(1-nu^2) of its plane-strain
/// material, which is E for a plane-stress sheet; 3D: E). d vanishes under every uniform strain
/// and rigid motion (straight rows stay straight), so the term leaves the patch test, the
/// moduli and the other corrections untouched; it only adds the rows' bending. The force on a
/// particle is the energy's exact gradient, a fourth difference along each axis:
///     F_I = -k_r sum_a (d_I-^a - 2 d_I^a + d_I+^a)
/// (d of a neighbour that is not a triplet centre, or a clamp node, is 0). A triplet exists
/// while both of its bonds are intact; both ends of a bond decide its breakage with the same
/// bits (vcpm.h), so every particle sees the same triplets. Double precision, +, - and * only.
#pragma once

#include <cstdint>

#include "core/host_device.h"
#include "physics/sph_types.h"

namespace seaspring::physics {

/// Row slot of no bond (SolidBonds::row_slot).
constexpr std::uint8_t kNoRowSlot = 0xFF;

/// k_r of a lattice of spacing dp whose uniaxial-stress modulus is `e_uniaxial` (host).
inline double rowBendingStiffness(int dim, double e_uniaxial, double dp) {
    return dim == 3 ? e_uniaxial * dp / 12.0 : e_uniaxial / 12.0;
}

/// The uniaxial-stress modulus of the lattice's material (E', nu' in 2D plane strain; E in 3D).
inline double latticeUniaxialModulus(int dim, double young, double poisson) {
    return dim == 3 ? young : young / (1.0 - poisson * poisson);
}

/// d = (r_plus - r) - (r - r_minus): the discrete curvature of a row triplet centred at r.
SEASPRING_HD inline Double3 rowCurvature(const Double3& r_minus, const Double3& r, const Double3& r_plus) {
    return Double3{(r_plus.x - r.x) - (r.x - r_minus.x), (r_plus.y - r.y) - (r.y - r_minus.y),
                   (r_plus.z - r.z) - (r.z - r_minus.z)};
}

/// Energy of one row triplet, 1/2 k_r |d|^2.
SEASPRING_HD inline double rowBendingEnergy(double k_r, const Double3& d) {
    return 0.5 * k_r * (d.x * d.x + d.y * d.y + d.z * d.z);
}

/// Force of the row term along one axis on the particle between I- and I+:
/// -k_r (d_minus - 2 d + d_plus).
SEASPRING_HD inline Double3 rowBendingForce(double k_r, const Double3& d_minus, const Double3& d,
                                            const Double3& d_plus) {
    return Double3{-k_r * ((d_minus.x - 2.0 * d.x) + d_plus.x), -k_r * ((d_minus.y - 2.0 * d.y) + d_plus.y),
                   -k_r * ((d_minus.z - 2.0 * d.z) + d_plus.z)};
}

}  // namespace seaspring::physics
