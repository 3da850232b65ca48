// SeaSpring — MIT licence.
/// \file vcpm.h
/// \brief The VCPM lattice solid (volume-compensated particle method, Chen & Liu 2016; seed
///        paper 000 §2): material constants, bond half-elongation, the per-particle volumetric
///        sum, the bond force, breakage, and the symplectic sub-step (Eqs. 20-23). One source for
///        both backends, through the passes of src/solver/solid_passes.h.
///
/// Energy of the lattice (each bond seen from both ends, delta_l = half the elongation):
///   U = sum_I [ 1/2 sum_J k_IJ dl_IJ^2 + 1/2 T (sum_J dl_IJ)^2 ]
/// so the force on I along u_IJ = (r_I - r_J)/|r_I - r_J| is
///   f_IJ = -k_IJ dl_IJ - T/2 (S_I + S_J),   S_I = sum_Q dl_IQ   (Eq. 13).
/// With the surface correction's volumetric weights (vcpm_surface.h), S_I = sum_Q w_IQ dl_IQ
/// and f_IJ = -k_IJ dl_IJ - T/2 (w_IJ S_I + w_JI S_J); a complete site's weights are 1.
/// 3D simple cubic lattice (6 first + 12 second neighbours), R = dp/2 (Eqs. 8-9):
///   k = 2RE/(1+nu) for both shells,  T = RE(4nu-1)/((9+4 sqrt2)(1+nu)(1-2nu)).
/// 2D square lattice (4 + 4 neighbours, plane strain, per unit thickness), derived in
/// docs/vcpm.md by matching the Cauchy-Born energy to isotropic elasticity:
///   k1 = 4 mu = 2E/(1+nu),  k2 = 2 mu = E/(1+nu),
///   T = E(4nu-1) / (2 (3+2 sqrt2) (1+nu)(1-2nu)).
/// All solid arithmetic is double: elongations of stiff materials are far below float
/// resolution of the positions. Only IEEE +,-,*,/ and sqrt are used (correctly rounded on both
/// backends), so the CPU and the GPU give the same bits.
#pragma once

#include <cmath>
#include <cstdint>

#include "core/host_device.h"
#include "physics/blowup_bounds.h"
#include "physics/sph_types.h"
#include "physics/vcpm_rows.h"

namespace seaspring::physics {

/// Bond slots per particle: 18 in 3D (6 + 12), 8 in 2D (4 + 4).
constexpr int kMaxBonds3D = 18;
constexpr int kMaxBonds2D = 8;

/// Bond flags in SolidBonds::flags (the kind bits are gencase's BondKind values).
enum VcpmBondFlag : std::uint8_t {
    kBondSecond = 1,  ///< second neighbour (rest length sqrt(2) dp)
    kBondClamp = 2,   ///< the partner is a clamp node (boundary particle), not a solid particle
};

/// Constants of one solid body, as used per bond and per particle.
struct VcpmMaterial {
    double k_first = 0;   ///< normal stiffness of first-neighbour bonds [N/m] (2D: per m of thickness)
    double k_second = 0;  ///< of second-neighbour bonds
    double t_half = 0;    ///< T/2, volumetric (non-local) parameter
    double inv_mass = 0;  ///< 1 / (rho_S dp^D)
    double damp_rate = 0; ///< c_d [1/s]: damping force -m c_d v (Eq. 11; 0 = none)
    double crit_stretch = 0;  ///< a bond breaks when (|r|-L0)/L0 > this; <= 0: never
    double max_speed = 1e300; ///< blow-up bound on a particle's speed [m/s] (blowup_bounds.h)
    double row_k = 0;         ///< k_r of the rows' own bending (vcpm_rows.h; 0 without it)
};

/// Elastic and time-step properties of a material (host).
struct VcpmElastic {
    double shear = 0;     ///< G = E / (2(1+nu))
    double bulk = 0;      ///< K = E / (3(1-2nu))
    double lame = 0;      ///< lambda = E nu / ((1+nu)(1-2nu))
    double wave_speed = 0;///< P-wave speed c_S = sqrt((K + 4G/3)/rho) [m/s]
};

inline VcpmElastic vcpmElastic(double young, double poisson, double density) {
    VcpmElastic e;
    e.shear = young / (2.0 * (1.0 + poisson));
    e.bulk = young / (3.0 * (1.0 - 2.0 * poisson));
    e.lame = young * poisson / ((1.0 + poisson) * (1.0 - 2.0 * poisson));
    e.wave_speed = std::sqrt((e.bulk + 4.0 * e.shear / 3.0) / density);
    return e;
}

/// Host: a plane-stress sheet (DualSPHysics' constitmodel 2) of Young's modulus E and Poisson's
/// ratio nu as the 2D lattice's plane-strain material of E' = E (1+2nu)/(1+nu)^2 and
/// nu' = nu/(1+nu): the same shear modulus mu = E/(2(1+nu)) and the in-plane Lame constant
/// lambda' = E' nu'/((1+nu')(1-2nu')) = E nu/(1-nu^2), the plane-stress one, so every in-plane
/// response (uniaxial stress E, lateral contraction nu, P-wave speed sqrt(E/(rho(1-nu^2))))
/// is that of the sheet (docs/vcpm.md, "Plane stress").
inline void planeStressEquivalent(double young, double poisson, double& young_eq, double& poisson_eq) {
    young_eq = young * (1.0 + 2.0 * poisson) / ((1.0 + poisson) * (1.0 + poisson));
    poisson_eq = poisson / (1.0 + poisson);
}

/// Mass of a solid particle, rho_S dp^D [kg] (2D: per m of thickness).
inline double vcpmParticleMass(int dim, double density, double dp) {
    return density * dp * dp * (dim == 3 ? dp : 1.0);
}

/// The solid sub-step of a material [s]: VcpmDtCoef dp / c_S (c_S: VcpmElastic::wave_speed).
inline double vcpmTimeStep(double dt_coef, double dp, double wave_speed) { return dt_coef * dp / wave_speed; }

/// Host: the constants of a body of density rho, Young's modulus E, Poisson's ratio nu on a
/// lattice of spacing dp (dim 2 or 3); `damping` multiplies sqrt(E/(rho dp^2)).
inline VcpmMaterial vcpmMaterial(int dim, double young, double poisson, double density, double dp,
                                 double damping, double crit_stretch) {
    const double sqrt2 = std::sqrt(2.0);
    VcpmMaterial m;
    const double denom = (1.0 + poisson) * (1.0 - 2.0 * poisson);
    if (dim == 3) {
        const double r = 0.5 * dp;
        m.k_first = 2.0 * r * young / (1.0 + poisson);
        m.k_second = m.k_first;
        m.t_half = 0.5 * r * young * (4.0 * poisson - 1.0) / ((9.0 + 4.0 * sqrt2) * denom);
    } else {
        m.k_first = 2.0 * young / (1.0 + poisson);
        m.k_second = young / (1.0 + poisson);
        m.t_half = 0.5 * young * (4.0 * poisson - 1.0) / (2.0 * (3.0 + 2.0 * sqrt2) * denom);
    }
    m.inv_mass = 1.0 / vcpmParticleMass(dim, density, dp);
    m.damp_rate = damping * std::sqrt(young / (density * dp * dp));
    m.crit_stretch = crit_stretch;
    return m;
}

/// Bonds of the solid particles in a padded, slot-major layout: slot q of particle s is at
/// q * n + s (coalesced on the GPU), q < count[s], in gencase's fixed lattice-offset order.
/// `partner` is a solid index, or a clamp-node index when the slot's flags hold kBondClamp.
struct SolidBonds {
    std::uint32_t n = 0;                  ///< solid particles
    const std::uint8_t* count = nullptr;  ///< [n]
    const std::uint32_t* partner = nullptr;
    const double* rest = nullptr;         ///< rest length L0 [m]
    const std::uint8_t* flags = nullptr;  ///< VcpmBondFlag
    std::uint8_t* broken = nullptr;       ///< 1 once the bond has broken (never heals)
    const double* kfac = nullptr;         ///< surface correction of each slot's stiffness (null: none; vcpm_surface.h)
    /// Volumetric weights (null: none; vcpm_surface.h): the slot's weight in its own site's sum
    /// S*, and the mirror slot's in the partner's (1 for a clamp node).
    const double* vw = nullptr;
    const double* vw_partner = nullptr;
    /// The rows' own bending (null: none; vcpm_rows.h): for axis a and side (0: -, 1: +), the
    /// slot of the particle's first-neighbour bond at (2a + side) * n + s (kNoRowSlot: none),
    /// and the curvature d of its row triplet along a at a * n + s, written by solidSumAt
    /// (0 where the triplet does not exist).
    const std::uint8_t* row_slot = nullptr;
    Double3* row_d = nullptr;
    int row_axes = 0;  ///< 2 (x, z) in 2D, 3 in 3D
};

/// Clamp nodes: the boundary particles that clamp bonds reach. Their positions are prescribed
/// (fixed, or moving with their boundary); their volumetric sums S come from their clamp bonds,
/// so a clamp node behaves as a lattice site with a prescribed displacement. Slot layout as in
/// SolidBonds; `slot` is the index of the same bond in SolidBonds (to read its state).
struct ClampNodes {
    std::uint32_t n = 0;
    const std::uint8_t* count = nullptr;
    const std::uint32_t* partner = nullptr;  ///< solid index
    const std::uint32_t* slot = nullptr;     ///< bond slot in SolidBonds
    const Double3* pos_start = nullptr;      ///< position at the start of the solid interval
    const Double3* pos_end = nullptr;        ///< position at its end
    double* sum = nullptr;                   ///< S of each node
};

/// Position of clamp node c at fraction f in [0, 1] of the solid interval (linear in time,
/// matching the constant velocity the fluid sees over a step).
SEASPRING_HD inline Double3 clampPosAt(const ClampNodes& cn, std::uint32_t c, double f) {
    const Double3 a = cn.pos_start[c], b = cn.pos_end[c];
    return Double3{a.x + f * (b.x - a.x), a.y + f * (b.y - a.y), a.z + f * (b.z - a.z)};
}

/// r_a - r_b and its length (the same bits from either end: the difference is negated exactly).
SEASPRING_HD inline double bondVector(const Double3& a, const Double3& b, double& dx, double& dy, double& dz) {
    dx = a.x - b.x;
    dy = a.y - b.y;
    dz = a.z - b.z;
    return sqrt(dx * dx + dy * dy + dz * dz);
}

/// Half the bond elongation, dl = (|r| - L0) / 2.
SEASPRING_HD inline double halfElongation(double len, double rest) { return 0.5 * (len - rest); }

/// True once a bond of length `len` and rest length `rest` is stretched past the critical
/// stretch (never in compression; crit <= 0 disables breakage).
SEASPRING_HD inline bool bondBreaks(double len, double rest, double crit) {
    return crit > 0.0 && len - rest > crit * rest;
}

/// Normal stiffness k_IJ of a bond from its VcpmBondFlag bits.
SEASPRING_HD inline double bondStiffness(const VcpmMaterial& m, std::uint8_t flags) {
    return (flags & kBondSecond) ? m.k_second : m.k_first;
}

/// Engineering strain of a bond, (|r| - L0) / L0 (output field).
SEASPRING_HD inline double bondStrain(double len, double rest) { return (len - rest) / rest; }

/// Spring energy of an intact bond seen from one of its particles: 1/2 k dl^2 (the lattice
/// energy U of the file brief sums it from both ends). A clamp bond is seen from its solid end
/// only, so `clamp` counts both halves: k dl^2.
SEASPRING_HD inline double bondSpringEnergy(double k, double dl, bool clamp) {
    return 0.5 * k * dl * dl * (clamp ? 2.0 : 1.0);
}

/// Volumetric energy of one lattice site (solid particle or clamp node) with sum S over its
/// intact bonds: 1/2 T S^2 = t_half S^2.
SEASPRING_HD inline double siteVolumetricEnergy(double t_half, double sum) { return t_half * sum * sum; }

/// Magnitude of the force on I along u_IJ (Eq. 13).
SEASPRING_HD inline double bondForce(double k, double t_half, double dl, double sum_i, double sum_j) {
    return -k * dl - t_half * (sum_i + sum_j);
}

/// The box the solid particles live in: the simulation domain widened by `margin` (2h) on
/// every side. A solid particle that leaves it is frozen where it crossed: its velocity is
/// zero from then on, it no longer moves, and every bond it has breaks (both ends see the same
/// positions, so both slots decide alike). The margin keeps a plate that is the edge of its
/// case (a tank floor bending a little out of the default domain, the particles' bounding
/// box) alive; the fluid is excluded at the domain itself, so nothing is left near a frozen
/// particle to act on or be acted on.
struct SolidKeepBox {
    double minx = -1e300, miny = -1e300, minz = -1e300;
    double maxx = 1e300, maxy = 1e300, maxz = 1e300;
};

/// Host: the domain [lo, hi] widened by margin on every side.
inline SolidKeepBox solidKeepBox(const Double3& lo, const Double3& hi, double margin) {
    SolidKeepBox k;
    k.minx = lo.x - margin;
    k.miny = lo.y - margin;
    k.minz = lo.z - margin;
    k.maxx = hi.x + margin;
    k.maxy = hi.y + margin;
    k.maxz = hi.z + margin;
    return k;
}

/// True when p lies outside the box (a NaN position is not outside: the blow-up checks name it).
SEASPRING_HD inline bool solidOutside(const SolidKeepBox& k, const Double3& p) {
    return p.x < k.minx || p.x > k.maxx || p.y < k.miny || p.y > k.maxy || p.z < k.minz || p.z > k.maxz;
}

/// Solid state (solid-index order). A sub-step evaluates forces at `pos` (predictor) and at
/// `pos_half` (corrector); each pass reads one position array and writes another, so no
/// particle reads a position that another thread of the same pass writes.
struct SolidState {
    Double3* pos = nullptr;        ///< r^m; receives r^{m+1}
    Double3* pos_half = nullptr;   ///< r^{m+1/2}
    Double3* vel = nullptr;        ///< v^m, then v^{m+1/2}, then v^{m+1}
    Double3* vel0 = nullptr;       ///< v^m during the sub-step
    double* sum = nullptr;         ///< S of each particle (this evaluation)
    const Double3* fluid_force = nullptr;  ///< hydrodynamic force F_F->S, frozen over the sub-cycle [N]
    const std::uint16_t* body = nullptr;   ///< material index
    const VcpmMaterial* material = nullptr;
    /// Point loads (nullptr when the case has none): F(t) = load_force + load_rate t [N].
    const Double3* load_force = nullptr;
    const Double3* load_rate = nullptr;
    double t0 = 0, span = 0;  ///< the sub-cycle's start time and length: t = t0 + f span
    SolidKeepBox keep;        ///< outside it a particle is frozen (SolidKeepBox)
    SolidAlarm* alarm = nullptr;  ///< the blow-up bound each particle passed first (blowup_bounds.h)
    /// Contact (solid_contact.h; all null without it): the contact force of the evaluation
    /// (written by its own pass before the predictor and before the corrector), and its
    /// impulse and work on each particle since t = 0 (the ledger).
    const Double3* contact_force = nullptr;
    Double3* contact_impulse = nullptr;
    double* contact_work = nullptr;
};

/// The point load on solid particle s at time fraction f of the sub-cycle (0 without loads).
SEASPRING_HD inline Double3 pointLoadAt(const SolidState& st, std::uint32_t s, double f) {
    if (!st.load_force) return Double3{0, 0, 0};
    const double t = st.t0 + f * st.span;
    const Double3 a = st.load_force[s], r = st.load_rate[s];
    return Double3{a.x + r.x * t, a.y + r.y * t, a.z + r.z * t};
}

/// The position of the partner of bond slot k (slot-major index) at positions `ep` (a clamp
/// node's at time fraction f).
SEASPRING_HD inline Double3 bondPartnerPos(std::uint32_t k, const Double3* ep, const SolidBonds& b,
                                           const ClampNodes& cn, double f) {
    return (b.flags[k] & kBondClamp) ? clampPosAt(cn, b.partner[k], f) : ep[b.partner[k]];
}

/// The curvatures d of solid particle s's row triplets at positions `ep` (vcpm_rows.h), into
/// b.row_d: 0 along an axis where s lacks an intact first-neighbour bond on either side. Called
/// by solidSumAt once s's bonds' breakage is decided.
SEASPRING_HD inline void solidRowCurvaturesAt(std::uint32_t s, const Double3* ep, const SolidBonds& b,
                                              const ClampNodes& cn, double f) {
    const Double3 p = ep[s];
    for (int a = 0; a < b.row_axes; ++a) {
        const std::uint8_t qm = b.row_slot[std::uint32_t(2 * a) * b.n + s];
        const std::uint8_t qp = b.row_slot[std::uint32_t(2 * a + 1) * b.n + s];
        Double3 d{0, 0, 0};
        if (qm != kNoRowSlot && qp != kNoRowSlot) {
            const std::uint32_t km = std::uint32_t(qm) * b.n + s, kp = std::uint32_t(qp) * b.n + s;
            if (!b.broken[km] && !b.broken[kp]) d = rowCurvature(bondPartnerPos(km, ep, b, cn, f), p, bondPartnerPos(kp, ep, b, cn, f));
        }
        b.row_d[std::uint32_t(a) * b.n + s] = d;
    }
}

/// The rows' bending force on solid particle s (vcpm_rows.h) from the curvatures of pass 1:
/// along each axis, -k_r (d_minus - 2 d_s + d_plus) with the triplets centred at s's neighbours
/// on that axis (0 for a clamp node or a missing bond; a broken bond's partner has d = 0 there).
SEASPRING_HD inline Double3 solidRowForceAt(std::uint32_t s, const SolidBonds& b, double k_r) {
    double fx = 0.0, fy = 0.0, fz = 0.0;
    for (int a = 0; a < b.row_axes; ++a) {
        Double3 dn[2] = {Double3{0, 0, 0}, Double3{0, 0, 0}};
        for (int side = 0; side < 2; ++side) {
            const std::uint8_t q = b.row_slot[std::uint32_t(2 * a + side) * b.n + s];
            if (q == kNoRowSlot) continue;
            const std::uint32_t k = std::uint32_t(q) * b.n + s;
            if (!(b.flags[k] & kBondClamp)) dn[side] = b.row_d[std::uint32_t(a) * b.n + b.partner[k]];
        }
        const Double3 g = rowBendingForce(k_r, dn[0], b.row_d[std::uint32_t(a) * b.n + s], dn[1]);
        fx += g.x;
        fy += g.y;
        fz += g.z;
    }
    return Double3{fx, fy, fz};
}

/// What bond slot q of solid particle s adds to S_s in pass 1 (solidSumAt), and the slot's
/// strain alarm: the slot's breakage is decided here (the partner decides the mirror slot with
/// the same bits; a bond with an end outside st.keep breaks too). `p`, `out_s`, `crit`: s's
/// position, whether it lies outside st.keep, its material's critical stretch.
struct SolidSumTerm {
    double term;     ///< w dl of an intact bond, +0 for a broken one
    double strain;   ///< the strain of an intact bond past kMaxBondStrain (when alarm)
    std::uint32_t alarm;  ///< 1: raise s's strain alarm with `strain`
    std::uint32_t pad;
};
SEASPRING_HD inline SolidSumTerm solidSumSlot(std::uint32_t s, int q, const Double3& p, bool out_s, double crit,
                                              const Double3* ep, const SolidState& st, const SolidBonds& b,
                                              const ClampNodes& cn, double f) {
    const std::uint32_t k = std::uint32_t(q) * b.n + s;
    const std::uint32_t j = b.partner[k];
    const Double3 pj = (b.flags[k] & kBondClamp) ? clampPosAt(cn, j, f) : ep[j];
    double dx, dy, dz;
    const double len = bondVector(p, pj, dx, dy, dz);
    const double rest = b.rest[k];
    std::uint8_t br = b.broken[k];
    if (!br && (bondBreaks(len, rest, crit) || out_s || solidOutside(st.keep, pj))) {
        br = 1;
        b.broken[k] = 1;
    }
    SolidSumTerm u{0.0, 0.0, 0u, 0u};
    if (!br && bondPastBound(len, rest)) {
        u.alarm = 1u;
        u.strain = bondStrain(len, rest);
    }
    const double dl = halfElongation(len, rest);
    u.term = br ? 0.0 : (b.vw ? b.vw[k] * dl : dl);
    return u;
}

/// Folds slot q's term into S (in slot order): its strain alarm first, at time t.
SEASPRING_HD inline void addSumTerm(const SolidSumTerm& u, std::uint32_t s, const SolidState& st, double t,
                                    double& sum) {
    if (u.alarm) raiseSolidAlarm(st.alarm, s, kSolidAlarmStrain, u.strain, t);
    sum += u.term;
}

/// Pass 1b, for clamp node c: S_c over its intact bonds. It decides each bond's breakage
/// itself, with the bits solidSumAt (vcpm_substep.h) decides it with at the solid end (the
/// same length from either end, the solid particle's material and keep box), so it runs in the
/// same pass as solidSumAt: b.broken[slot] read while the solid end may set it gives the same
/// result either way (the old flag or'ed with the same test).
SEASPRING_HD inline double clampSumAt(std::uint32_t c, const Double3* ep, const SolidState& st, const SolidBonds& b,
                                      const ClampNodes& cn, double f) {
    const Double3 p = clampPosAt(cn, c, f);
    const bool out_c = solidOutside(st.keep, p);
    const int nb = cn.count[c];
    double sum = 0.0;
    for (int q = 0; q < nb; ++q) {
        const std::uint32_t k = std::uint32_t(q) * cn.n + c;
        const std::uint32_t slot = cn.slot[k], s = cn.partner[k];
        const Double3 ps = ep[s];
        double dx, dy, dz;
        const double len = bondVector(p, ps, dx, dy, dz);
        const double rest = b.rest[slot];
        if (b.broken[slot] || bondBreaks(len, rest, st.material[st.body[s]].crit_stretch) ||
            solidOutside(st.keep, ps) || out_c)
            continue;
        sum += halfElongation(len, rest);
    }
    return sum;
}

/// The force of bond slot q on solid particle s at positions `ep` (Eq. 12) from the sums of
/// pass 1; `on` false for a broken bond (nothing is added). `p`, `m`, `sum_s`: s's position,
/// material and S.
struct SolidForceTerm {
    double x, y, z;
    std::uint32_t on;
    std::uint32_t pad;
};
SEASPRING_HD inline SolidForceTerm solidBondForceSlot(std::uint32_t s, int q, const Double3& p, const VcpmMaterial& m,
                                                      double sum_s, const Double3* ep, const SolidState& st,
                                                      const SolidBonds& b, const ClampNodes& cn, double f) {
    const std::uint32_t k = std::uint32_t(q) * b.n + s;
    if (b.broken[k]) return SolidForceTerm{0.0, 0.0, 0.0, 0u, 0u};
    const std::uint32_t j = b.partner[k];
    const bool clamp = (b.flags[k] & kBondClamp) != 0;
    const Double3 pj = clamp ? clampPosAt(cn, j, f) : ep[j];
    const double sum_j = clamp ? cn.sum[j] : st.sum[j];
    double dx, dy, dz;
    const double len = bondVector(p, pj, dx, dy, dz);
    const double kb = b.kfac ? bondStiffness(m, b.flags[k]) * b.kfac[k] : bondStiffness(m, b.flags[k]);
    const double si = b.vw ? b.vw[k] * sum_s : sum_s, sj = b.vw ? b.vw_partner[k] * sum_j : sum_j;
    const double fm = bondForce(kb, m.t_half, halfElongation(len, b.rest[k]), si, sj) / len;
    return SolidForceTerm{fm * dx, fm * dy, fm * dz, 1u, 0u};
}

/// Folds slot q's force into (fx, fy, fz), in slot order.
SEASPRING_HD inline void addForceTerm(const SolidForceTerm& u, double& fx, double& fy, double& fz) {
    if (!u.on) return;
    fx += u.x;
    fy += u.y;
    fz += u.z;
}

/// The rows' bending force of s added to a bond force (vcpm_rows.h; nothing without it).
SEASPRING_HD inline Double3 withRowForce(std::uint32_t s, const SolidBonds& b, const VcpmMaterial& m, double fx,
                                         double fy, double fz) {
    if (b.row_d) {
        const Double3 fr = solidRowForceAt(s, b, m.row_k);
        fx += fr.x;
        fy += fr.y;
        fz += fr.z;
    }
    return Double3{fx, fy, fz};
}

/// After a sub-cycle, for solid particle s: raises its alarm for an intact bond strained past
/// kMaxBondStrain at the end positions (the sub-steps test the positions they start from, so
/// this covers the last one) and returns 1 when its alarm is raised, else 0.
SEASPRING_HD inline std::uint32_t solidAlarmAfterSubCycleAt(std::uint32_t s, const SolidState& st, const SolidBonds& b,
                                                            const ClampNodes& cn) {
    if (st.alarm[s].kind == kSolidAlarmNone) {
        const Double3 p = st.pos[s];
        const int nb = b.count[s];
        for (int q = 0; q < nb; ++q) {
            const std::uint32_t k = std::uint32_t(q) * b.n + s;
            if (b.broken[k]) continue;
            const std::uint32_t j = b.partner[k];
            const Double3 pj = (b.flags[k] & kBondClamp) ? clampPosAt(cn, j, 1.0) : st.pos[j];
            double dx, dy, dz;
            const double len = bondVector(p, pj, dx, dy, dz);
            if (bondPastBound(len, b.rest[k])) {
                raiseSolidAlarm(st.alarm, s, kSolidAlarmStrain, bondStrain(len, b.rest[k]), st.t0 + st.span);
                break;
            }
        }
    }
    return st.alarm[s].kind != kSolidAlarmNone ? 1u : 0u;
}

/// Number of solid sub-steps for a fluid step dt_f (Section 2.4.1): int(dt_f / dt_s) + 1.
inline int solidSubsteps(double dt_fluid, double dt_solid) {
    const double r = dt_fluid / dt_solid;
    return r >= 1e9 ? 1000000000 : int(r) + 1;
}

}  // namespace seaspring::physics
