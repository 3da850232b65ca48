// SeaSpring — MIT licence.
/// \file solid_contact.h
/// \brief Contact of the VCPM solids (issue 13): solid particles that are not bonded to each
///        other (fragments of a broken body, two bodies, a plate folding onto itself) and solid
///        particles against fixed or moving boundary particles they are not clamped to repel
///        each other with a linear normal penalty, a normal dashpot and optional regularised
///        Coulomb friction, inside the solid sub-step. One source for both backends, through
///        the passes of src/solver/solid_passes.h.
///
/// Pair law for particles a, b at distance r < r_c (r_c = dp, the lattice spacing: unbonded
/// particles of an intact lattice are sqrt(3) dp (3D) or 2 dp (2D) apart or more, so contact
/// never acts inside a body that is whole), n = (r_a - r_b)/r, v = v_a - v_b, v_n = v . n:
///   F_n = max(0, k (r_c - r) - c v_n),  c = 2 zeta sqrt(m_eff k),
///   F_t = -min(mu F_n, c |v_t|) v_t/|v_t|,  v_t = v - v_n n,
///   F_a = F_n n + F_t = -F_b.
/// k = VcpmContactStiffness x the first-neighbour bond stiffness k_1 (harmonic mean of the two
/// bodies' values for solid pairs), m_eff = m_a m_b/(m_a + m_b) (m_a against a wall). Both ends
/// evaluate the same expression with every vector negated exactly, so F_b = -F_a bit for bit
/// (Newton's third law without atomics: each particle gathers its own sum).
///
/// Candidates: once per fluid step (per sub-cycle), each solid particle lists the boundary
/// particles (walls, moving boundaries, other solid particles) within r_c + margin of it that
/// it has no intact bond to, from the cell-sorted boundary block, in cell-then-id order (the
/// same order on every backend). The margin (half a dp) covers the relative motion in one
/// step; a pair that closes faster is caught by the blow-up bounds (a speed of dp/2 per fluid
/// step is far above c0 / 10).
#pragma once

#include <cmath>
#include <cstdint>

#include "core/host_device.h"
#include "physics/cell_grid.h"
#include "physics/vcpm.h"

namespace seaspring::physics {

/// Contact constants of a run.
struct ContactParams {
    double range = 0;       ///< r_c [m]: contact when closer (dp)
    double list_range = 0;  ///< r_c + margin [m]: the candidates listed
    double stiffness = 0;   ///< k / k_1 of the bodies
    double damping = 0;     ///< zeta: fraction of critical damping of the normal dashpot
    double friction = 0;    ///< mu: Coulomb friction coefficient (0: frictionless)
};

/// Bit of a ContactList entry that marks a solid index (else: a sorted boundary index).
constexpr std::uint32_t kContactSolid = 0x80000000u;

/// The candidates of every solid particle, slot-major as SolidBonds (entry q of particle s at
/// q * n + s, q < min(count[s], cap)); count[s] > cap: the list overflowed (an error).
struct ContactList {
    std::uint32_t n = 0, cap = 0;
    std::uint32_t* count = nullptr;
    std::uint32_t* entry = nullptr;
    Double3* pos0 = nullptr;  ///< each particle's position when its list was made
};

/// The boundary block as the candidate search and the force read it (sorted order).
struct ContactBoundary {
    const std::uint32_t* cell_start = nullptr;  ///< boundary cell ranges of the last divide
    const std::uint32_t* id = nullptr;          ///< particle id of each sorted index
    const Double3* pos = nullptr;               ///< positions (walls; moving boundaries at the step's start)
    const Float4* velrho = nullptr;             ///< velocities of walls and moving boundaries
    std::uint32_t first_solid = 0;              ///< id of solid particle 0
    std::uint32_t nsolid = 0;                   ///< solid particles
    const std::uint32_t* clamp_id = nullptr;    ///< particle id of each clamp node
};

/// True when solid particle s has an intact bond to solid particle j (bond partner) or an
/// intact clamp bond to the boundary particle of id `pid` (j = kContactSolid then).
SEASPRING_HD inline bool bondedTo(std::uint32_t s, std::uint32_t j, std::uint32_t pid, const SolidBonds& b,
                                  const ContactBoundary& w) {
    const int nb = b.count[s];
    for (int q = 0; q < nb; ++q) {
        const std::uint32_t k = std::uint32_t(q) * b.n + s;
        if (b.broken[k]) continue;
        const bool clamp = (b.flags[k] & kBondClamp) != 0;
        if (j != kContactSolid ? (!clamp && b.partner[k] == j) : (clamp && w.clamp_id[b.partner[k]] == pid)) return true;
    }
    return false;
}

/// Lists the contact candidates of solid particle s (positions st.pos) from the boundary
/// block's cells within list_range + the grid's skin (a sorted particle may lie up to the skin
/// outside its cell), rows by z then y, x ascending, each row's particles in sorted order.
/// More than cl.cap candidates raise the particle's alarm (kSolidAlarmContactOverflow): the
/// run stops rather than lose a contact.
SEASPRING_HD inline void contactCandidatesAt(std::uint32_t s, const SolidState& st, const SolidBonds& b,
                                             const ContactBoundary& w, const CellGrid& g, const ContactParams& cp,
                                             const ContactList& cl) {
    const Double3 p = st.pos[s];
    cl.pos0[s] = p;
    const double reach = cp.list_range + double(g.skinf);
    const double rr = cp.list_range * cp.list_range;
    int x0, y0, z0, x1, y1, z1;
    cellOf(g, Double3{p.x - reach, p.y - reach, p.z - reach}, x0, y0, z0);
    cellOf(g, Double3{p.x + reach, p.y + reach, p.z + reach}, x1, y1, z1);
    std::uint32_t count = 0;
    const std::uint32_t self = w.first_solid + s;
    for (int z = z0; z <= z1; ++z)
        for (int y = y0; y <= y1; ++y) {
            const std::uint32_t pb = w.cell_start[g.linear(x0, y, z)], pe = w.cell_start[g.linear(x1, y, z) + 1u];
            for (std::uint32_t i = pb; i < pe; ++i) {
                const std::uint32_t pid = w.id[i];
                if (pid == self) continue;
                const std::uint32_t js = pid - w.first_solid;
                const bool solid = pid >= w.first_solid && js < w.nsolid;
                const Double3 q = solid ? st.pos[js] : w.pos[i];
                const double dx = p.x - q.x, dy = p.y - q.y, dz = p.z - q.z;
                if (!(dx * dx + dy * dy + dz * dz < rr)) continue;
                if (bondedTo(s, solid ? js : kContactSolid, pid, b, w)) continue;
                if (count < cl.cap) cl.entry[count * cl.n + s] = solid ? (js | kContactSolid) : i;
                ++count;
            }
        }
    cl.count[s] = count;
    if (count > cl.cap) raiseSolidAlarm(st.alarm, s, kSolidAlarmContactOverflow, double(count), st.t0);
}

/// After a sub-cycle: raises solid particle s's alarm (kSolidAlarmContactMotion) when it moved
/// more than half the list margin since its list was made: a pair could then have closed by
/// more than the margin, and a contact could be missed. Never met at physical speeds (the
/// margin is dp/2; a fluid step moves a solid far less).
SEASPRING_HD inline void contactMotionAlarmAt(std::uint32_t s, const SolidState& st, const ContactParams& cp,
                                              const ContactList& cl) {
    const Double3 p = st.pos[s], q = cl.pos0[s];
    const double dx = p.x - q.x, dy = p.y - q.y, dz = p.z - q.z;
    const double half = 0.5 * (cp.list_range - cp.range);
    const double d2 = dx * dx + dy * dy + dz * dz;
    if (d2 > half * half && !solidOutside(st.keep, p))
        raiseSolidAlarm(st.alarm, s, kSolidAlarmContactMotion, sqrt(d2), st.t0 + st.span);
}

/// Host: the contact stiffness of a body, VcpmContactStiffness x k_1.
inline double contactStiffness(const VcpmMaterial& m, double factor) { return factor * m.k_first; }

/// The contact force on a from b (file brief): `d` = r_a - r_b, `v` = v_a - v_b, `k` and `m_eff`
/// of the pair.
SEASPRING_HD inline Double3 contactPairForce(const Double3& d, const Double3& v, double k, double m_eff,
                                             const ContactParams& cp) {
    const double r = sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    const double overlap = cp.range - r;
    if (!(overlap > 0.0) || !(r > 0.0)) return Double3{0, 0, 0};
    const Double3 n{d.x / r, d.y / r, d.z / r};
    const double vn = v.x * n.x + v.y * n.y + v.z * n.z;
    const double c = 2.0 * cp.damping * sqrt(m_eff * k);
    double fn = k * overlap - c * vn;
    if (!(fn > 0.0)) return Double3{0, 0, 0};
    Double3 f{fn * n.x, fn * n.y, fn * n.z};
    if (cp.friction > 0.0) {
        const Double3 vt{v.x - vn * n.x, v.y - vn * n.y, v.z - vn * n.z};
        const double st = sqrt(vt.x * vt.x + vt.y * vt.y + vt.z * vt.z);
        if (st > 0.0) {
            const double cap = cp.friction * fn, visc = c * st;
            const double ft = (visc < cap ? visc : cap) / st;
            f = Double3{f.x - ft * vt.x, f.y - ft * vt.y, f.z - ft * vt.z};
        }
    }
    return f;
}

/// The total contact force on solid particle s at positions `ep` (st.pos or st.pos_half) and
/// velocities st.vel, over its listed candidates in list order; walls at their listed
/// positions and velocities.
SEASPRING_HD inline Double3 contactForceAt(std::uint32_t s, const Double3* ep, const SolidState& st,
                                           const ContactBoundary& w, const ContactParams& cp, const ContactList& cl) {
    const Double3 p = ep[s], v = st.vel[s];
    const VcpmMaterial& ms = st.material[st.body[s]];
    const double ks = cp.stiffness * ms.k_first, mass_s = 1.0 / ms.inv_mass;
    const std::uint32_t nc = cl.count[s] < cl.cap ? cl.count[s] : cl.cap;
    double fx = 0.0, fy = 0.0, fz = 0.0;
    for (std::uint32_t q = 0; q < nc; ++q) {
        const std::uint32_t e = cl.entry[q * cl.n + s];
        Double3 pj, vj;
        double k = ks, m_eff = mass_s;
        if (e & kContactSolid) {
            const std::uint32_t j = e & ~kContactSolid;
            pj = ep[j];
            vj = st.vel[j];
            const VcpmMaterial& mj = st.material[st.body[j]];
            const double kj = cp.stiffness * mj.k_first, mass_j = 1.0 / mj.inv_mass;
            k = 2.0 * (ks * kj) / (ks + kj);
            m_eff = (mass_s * mass_j) / (mass_s + mass_j);
        } else {
            pj = w.pos[e];
            const Float4 vr = w.velrho[e];
            vj = Double3{double(vr.x), double(vr.y), double(vr.z)};
        }
        const Double3 f = contactPairForce(Double3{p.x - pj.x, p.y - pj.y, p.z - pj.z},
                                           Double3{v.x - vj.x, v.y - vj.y, v.z - vj.z}, k, m_eff, cp);
        fx += f.x;
        fy += f.y;
        fz += f.z;
    }
    return Double3{fx, fy, fz};
}

/// Host: how many sub-steps of dt a solid-only run may take with one set of contact lists: the
/// largest K >= 1 (at most `most`) with (2 v + g K dt) K dt <= 0.4 x half the list margin, for
/// particles now at most at speed v [m/s] and accelerated by gravity g [m/s^2]. The factor 2
/// on v covers an impact's elastic rebound (a wave reflected at a free face doubles the
/// particle speed) and 0.4 the lattice's other forces; the motion alarm
/// (contactMotionAlarmAt) stops the run should a chunk still move a particle too far.
inline long long contactChunk(double v, double g, double dt, const ContactParams& cp, long long most) {
    const double d = 0.4 * 0.5 * (cp.list_range - cp.range);
    const double a = g * dt * dt, b = 2.0 * v * dt;
    double k;
    if (a > 0) k = (-b + std::sqrt(b * b + 4.0 * a * d)) / (2.0 * a);
    else k = b > 0 ? d / b : double(most);
    if (!(k >= 1.0)) return 1;
    return k >= double(most) ? most : (long long)k;
}

/// Host: the largest stable sub-step of a contact of stiffness k on a particle of mass m,
/// kContactDtCoef sqrt(m / k) (a linear spring-dashpot needs dt < 2 sqrt(m/k); the margin
/// covers several contacts at once and the particle's bonds).
constexpr double kContactDtCoef = 0.5;
inline double contactTimeStep(double mass, double k) { return kContactDtCoef * std::sqrt(mass / k); }

}  // namespace seaspring::physics
