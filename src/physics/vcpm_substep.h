// SeaSpring — MIT licence.
/// \file vcpm_substep.h
/// \brief The symplectic sub-step of a VCPM solid (seed paper 000 Eqs. 20-23): a particle's
///        acceleration, predictor and corrector, one thread per particle (the host) or with the
///        particle's bond slots on several GPU threads ("bond lanes", the same bits). The lattice
///        (bonds, sums S, bond forces, breakage) is vcpm.h.
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/host_device.h"
#include "core/lane_group.h"
#include "physics/blowup_bounds.h"
#include "physics/sph_types.h"
#include "physics/vcpm.h"

namespace seaspring::physics {

/// Acceleration of a solid particle: (bond force + hydrodynamic force)/m + g - c_d v. Without
/// damping (c_d = 0) the velocity is not read: the term is absent, not 0 v (which would carry a
/// NaN velocity or flip the sign of a -0), so that the predictor's velocity v^{m+1/2}, which
/// only this term reads, is not needed (predictorForceUsed).
SEASPRING_HD inline Double3 solidAcceleration(const Double3& fbond, const Double3& ffluid, const Double3& vel,
                                              const VcpmMaterial& m, double gx, double gy, double gz) {
    const Double3 a{(fbond.x + ffluid.x) * m.inv_mass + gx, (fbond.y + ffluid.y) * m.inv_mass + gy,
                    (fbond.z + ffluid.z) * m.inv_mass + gz};
    if (m.damp_rate == 0.0) return a;
    return Double3{a.x - m.damp_rate * vel.x, a.y - m.damp_rate * vel.y, a.z - m.damp_rate * vel.z};
}

/// Whether a sub-step's force at r^m (the predictor's acceleration, for v^{m+1/2}) changes
/// anything. Of the predictor's results only r^{m+1/2} = r^m + dt/2 v^m enters the corrector's
/// force evaluation and update; v^{m+1/2} enters only the damping term (solidAcceleration) and
/// the contact dashpot (whose force at r^m also comes from the sums pass). So for undamped
/// bodies without contact the predictor's force pass is skipped (SolidSubCycle), and so is the
/// sums pass at r^m unless it decides breakage (startSumsUsed): the same bits in two or three
/// passes of four. Alarms at r^m are then raised at r^{m+1/2} or by the end-of-cycle check.
inline bool predictorForceUsed(const VcpmMaterial* m, std::size_t nbodies, bool contact) {
    if (contact) return true;
    for (std::size_t b = 0; b < nbodies; ++b)
        if (m[b].damp_rate != 0.0) return true;
    return false;
}

/// Whether the sums pass at r^m is needed without the predictor's force (predictorForceUsed
/// false): it decides the breakage of bonds strained past their critical stretch at r^m.
inline bool startSumsUsed(const VcpmMaterial* m, std::size_t nbodies) {
    for (std::size_t b = 0; b < nbodies; ++b)
        if (m[b].crit_stretch > 0.0) return true;
    return false;
}

/// The force on solid particle s other than the fluid's: its bond force `fi`, plus its point
/// load at time fraction f, plus (with contact) its contact force, added in that order.
SEASPRING_HD inline Double3 solidNonFluidForce(std::uint32_t s, const SolidState& st, double f, const Double3& fi) {
    const Double3 fl = pointLoadAt(st, s, f);
    Double3 fb{fi.x + fl.x, fi.y + fl.y, fi.z + fl.z};
    if (st.contact_force) {
        const Double3 fc = st.contact_force[s];
        fb = Double3{fb.x + fc.x, fb.y + fc.y, fb.z + fc.z};
    }
    return fb;
}

// ---- Bond lanes: one particle's bonds on several GPU threads, the same bits -------------------
//
// The sub-cycle of a small solid is latency-bound: one thread per particle walks its 8 (2D) or
// 18 (3D) bond slots one after another, each a chain of dependent loads and double square
// roots. With `lanes` threads per particle (consecutive, aligned in a warp; lanes a power of two
// <= 32), lane l evaluates the slots l, l + lanes, l + 2 lanes, ... in lockstep; after each
// round lane 0 takes the other lanes' terms (valueOfLane) and folds every term in slot order,
// raising alarms in that order: the same operations in the same order as one thread folding
// slot after slot, so the same bits on every backend. Every lane of a group calls these; only
// lane 0's result is meaningful, and only lane 0 writes the particle's own fields. With
// lanes = 1 they are the one-thread functions (solidSumAt, solidBondForceAt: the host, the
// GPU's small solids).

/// Pass 1 of a force evaluation at positions `ep`, for solid particle s over `lanes` lanes
/// (lane 0 returns S_s): decides the breakage of s's bonds (solidSumSlot) and returns
/// S_s = sum of (w) dl over its intact bonds in slot order; with the rows' bending, writes s's row curvatures (solidRowCurvaturesAt). `f`: time
/// fraction for the clamp nodes. Raises s's alarm for a position that is not finite or an
/// intact bond strained past kMaxBondStrain.
SEASPRING_HD inline double solidSumLanes(std::uint32_t s, std::uint32_t lane, std::uint32_t lanes, const Double3* ep,
                                         const SolidState& st, const SolidBonds& b, const ClampNodes& cn, double f) {
    const Double3 p = ep[s];
    const double crit = st.material[st.body[s]].crit_stretch;
    const bool out_s = solidOutside(st.keep, p);
    const double t = st.t0 + f * st.span;
    if (lane == 0 && (notFinite(p.x) || notFinite(p.y) || notFinite(p.z)))
        raiseSolidAlarm(st.alarm, s, kSolidAlarmNotFinite, p.x + p.y + p.z, t);
    const int nb = b.count[s];
    double sum = 0.0;
    for (int q0 = 0; q0 < nb; q0 += int(lanes)) {
        const int q = q0 + int(lane);
        SolidSumTerm u{0.0, 0.0, 0u, 0u};
        if (q < nb) u = solidSumSlot(s, q, p, out_s, crit, ep, st, b, cn, f);
        if (lane == 0) addSumTerm(u, s, st, t, sum);  // q0 < nb
        for (std::uint32_t l = 1; l < lanes; ++l) {  // every lane takes part in the exchange
            const SolidSumTerm v = valueOfLane(u, l, lanes);
            if (lane == 0 && q0 + int(l) < nb) addSumTerm(v, s, st, t, sum);
        }
    }
    if (b.row_d) {
        syncLanes(lanes);  // the other lanes' breakage decisions, which the row triplets read
        if (lane == 0) solidRowCurvaturesAt(s, ep, b, cn, f);
    }
    return sum;
}

/// Pass 2: the total bond force on solid particle s at positions `ep` (Eq. 12) over `lanes`
/// lanes (lane 0 returns it), from the sums of pass 1 (solidBondForceSlot in slot order), plus
/// the rows' bending force from its row curvatures (vcpm_rows.h).
SEASPRING_HD inline Double3 solidBondForceLanes(std::uint32_t s, std::uint32_t lane, std::uint32_t lanes,
                                                const Double3* ep, const SolidState& st, const SolidBonds& b,
                                                const ClampNodes& cn, double f) {
    const Double3 p = ep[s];
    const VcpmMaterial& m = st.material[st.body[s]];
    const double sum_s = st.sum[s];
    const int nb = b.count[s];
    double fx = 0.0, fy = 0.0, fz = 0.0;
    for (int q0 = 0; q0 < nb; q0 += int(lanes)) {
        const int q = q0 + int(lane);
        SolidForceTerm u{0.0, 0.0, 0.0, 0u, 0u};
        if (q < nb) u = solidBondForceSlot(s, q, p, m, sum_s, ep, st, b, cn, f);
        if (lane == 0) addForceTerm(u, fx, fy, fz);  // q0 < nb
        for (std::uint32_t l = 1; l < lanes; ++l) {  // every lane takes part in the exchange
            const SolidForceTerm v = valueOfLane(u, l, lanes);
            if (lane == 0 && q0 + int(l) < nb) addForceTerm(v, fx, fy, fz);
        }
    }
    return lane == 0 ? withRowForce(s, b, m, fx, fy, fz) : Double3{fx, fy, fz};
}

/// Pass 1 for one thread per particle (solidSumLanes with one lane).
SEASPRING_HD inline double solidSumAt(std::uint32_t s, const Double3* ep, const SolidState& st, const SolidBonds& b,
                                      const ClampNodes& cn, double f) {
    return solidSumLanes(s, 0u, 1u, ep, st, b, cn, f);
}

/// Pass 2 for one thread per particle (solidBondForceLanes with one lane).
SEASPRING_HD inline Double3 solidBondForceAt(std::uint32_t s, const Double3* ep, const SolidState& st,
                                             const SolidBonds& b, const ClampNodes& cn, double f) {
    return solidBondForceLanes(s, 0u, 1u, ep, st, b, cn, f);
}

/// r^{m+1/2} = r^m + dt/2 v^m (Eq. 21), dth = dt/2.
SEASPRING_HD inline Double3 solidHalfPosition(const Double3& p, const Double3& v, double dth) {
    return Double3{p.x + dth * v.x, p.y + dth * v.y, p.z + dth * v.z};
}

/// Predictor of a sub-step (Eqs. 20-21) for particle s, given its bond force `fi` at r^m
/// (solidBondForceAt): a^m, then v^{m+1/2} = v^m + dt/2 a^m and r^{m+1/2} = r^m + dt/2 v^m.
SEASPRING_HD inline void solidPredictorWith(std::uint32_t s, const SolidState& st, double f, double dt, double gx,
                                            double gy, double gz, const Double3& fi) {
    const Double3 fb = solidNonFluidForce(s, st, f, fi);
    const Double3 v = st.vel[s], p = st.pos[s];
    const Double3 a = solidAcceleration(fb, st.fluid_force[s], v, st.material[st.body[s]], gx, gy, gz);
    const double dth = 0.5 * dt;
    st.vel0[s] = v;
    st.vel[s] = Double3{v.x + dth * a.x, v.y + dth * a.y, v.z + dth * a.z};
    st.pos_half[s] = solidHalfPosition(p, v, dth);
}

/// A particle outside st.keep at the predictor stays where it is, at rest, its r^{m+1/2} (into
/// `half`) its r^m (true: s is frozen, its predictor is done).
SEASPRING_HD inline bool solidFrozenAt(std::uint32_t s, const SolidState& st, Double3* half) {
    if (!solidOutside(st.keep, st.pos[s])) return false;
    const Double3 rest{0, 0, 0};
    st.vel0[s] = rest;
    st.vel[s] = rest;
    half[s] = st.pos[s];
    return true;
}

/// solidFrozenAt into st.pos_half (the four-pass sub-step's predictor).
SEASPRING_HD inline bool solidFrozenAtPredictor(std::uint32_t s, const SolidState& st) {
    return solidFrozenAt(s, st, st.pos_half);
}

/// The predictor without its force (when !predictorForceUsed), into `half` (r^{m+1/2}): v^m
/// kept (in vel0 and vel) and r^{m+1/2}, or frozen (solidFrozenAt). The same r^{m+1/2}
/// and v^m as solidPredictorWith; vel holds v^m instead of v^{m+1/2}, which nothing then reads.
SEASPRING_HD inline void solidHalfStepAt(std::uint32_t s, const SolidState& st, double dt, Double3* half) {
    if (solidFrozenAt(s, st, half)) return;
    const Double3 v = st.vel[s];
    st.vel0[s] = v;
    half[s] = solidHalfPosition(st.pos[s], v, 0.5 * dt);
}

/// Corrector (Eqs. 22-23) for particle s, given its bond force `fi` at r^{m+1/2}:
/// a^{m+1/2} (damping with v^{m+1/2}; bond, load, hydrodynamic and contact forces), then
/// v^{m+1} = v^m + dt a^{m+1/2} and r^{m+1} = r^m + dt/2 (v^m + v^{m+1}); one that r^{m+1}
/// takes outside st.keep freezes there. Raises s's alarm for a velocity that is not finite or
/// faster than the material's max_speed.
SEASPRING_HD inline void solidCorrectorWith(std::uint32_t s, const SolidState& st, double f, double dt, double gx,
                                            double gy, double gz, const Double3& fi) {
    const Double3 fb = solidNonFluidForce(s, st, f, fi);
    const Double3 a = solidAcceleration(fb, st.fluid_force[s], st.vel[s], st.material[st.body[s]], gx, gy, gz);
    const Double3 v0 = st.vel0[s], p0 = st.pos[s];
    const Double3 v{v0.x + dt * a.x, v0.y + dt * a.y, v0.z + dt * a.z};
    const double dth = 0.5 * dt;
    const Double3 p{p0.x + dth * (v0.x + v.x), p0.y + dth * (v0.y + v.y), p0.z + dth * (v0.z + v.z)};
    const double t = st.t0 + f * st.span;
    if (notFinite(v.x) || notFinite(v.y) || notFinite(v.z))
        raiseSolidAlarm(st.alarm, s, kSolidAlarmNotFinite, v.x + v.y + v.z, t);
    else if (speedPastBound(v.x, v.y, v.z, st.material[st.body[s]].max_speed))
        raiseSolidAlarm(st.alarm, s, kSolidAlarmSpeed, speedOf(v), t);
    if (st.contact_force) {  // the ledger: impulse F dt and work F . (r^{m+1} - r^m) of the contact force
        const Double3 fc = st.contact_force[s], j = st.contact_impulse[s];
        st.contact_impulse[s] = Double3{j.x + fc.x * dt, j.y + fc.y * dt, j.z + fc.z * dt};
        st.contact_work[s] += fc.x * (p.x - p0.x) + fc.y * (p.y - p0.y) + fc.z * (p.z - p0.z);
    }
    st.vel[s] = solidOutside(st.keep, p) ? Double3{0, 0, 0} : v;
    st.pos[s] = p;
}

/// Corrector without the next predictor's force (when !predictorForceUsed): solidCorrectorWith,
/// then the next sub-step's half step from the new state into `half_next` (solidHalfStepAt; the
/// values the next sub-step's first pass would compute, one pass earlier). `half_next` is not
/// st.pos_half, which the other particles of this pass read.
SEASPRING_HD inline void solidCorrectorThenHalfStep(std::uint32_t s, const SolidState& st, double f, double dt,
                                                    double gx, double gy, double gz, const Double3& fi,
                                                    Double3* half_next) {
    solidCorrectorWith(s, st, f, dt, gx, gy, gz, fi);
    solidHalfStepAt(s, st, dt, half_next);
}

/// Predictor pass of a sub-step for particle s over `lanes` lanes (lanes = 1: one thread).
SEASPRING_HD inline void solidPredictorLanes(std::uint32_t s, std::uint32_t lane, std::uint32_t lanes,
                                             const SolidState& st, const SolidBonds& b, const ClampNodes& cn,
                                             double f, double dt, double gx, double gy, double gz) {
    if (solidOutside(st.keep, st.pos[s])) {  // the same verdict on every lane of s
        if (lane == 0) solidFrozenAtPredictor(s, st);
        return;
    }
    const Double3 fi = solidBondForceLanes(s, lane, lanes, st.pos, st, b, cn, f);
    if (lane == 0) solidPredictorWith(s, st, f, dt, gx, gy, gz, fi);
}

/// Corrector pass for particle s over `lanes` lanes (lanes = 1: one thread); a particle frozen
/// at the predictor (outside st.keep) stays. `half_next` (not null): then the next sub-step's
/// half step into it (solidCorrectorThenHalfStep; a frozen particle stays frozen there).
SEASPRING_HD inline void solidCorrectorLanes(std::uint32_t s, std::uint32_t lane, std::uint32_t lanes,
                                             const SolidState& st, const SolidBonds& b, const ClampNodes& cn,
                                             double f, double dt, double gx, double gy, double gz,
                                             Double3* half_next = nullptr) {
    if (solidOutside(st.keep, st.pos[s])) {
        if (half_next && lane == 0) half_next[s] = st.pos_half[s];  // r^m: frozen at the predictor
        return;
    }
    const Double3 fi = solidBondForceLanes(s, lane, lanes, st.pos_half, st, b, cn, f);
    if (lane != 0) return;
    if (half_next)
        solidCorrectorThenHalfStep(s, st, f, dt, gx, gy, gz, fi, half_next);
    else
        solidCorrectorWith(s, st, f, dt, gx, gy, gz, fi);
}

/// The predictor and corrector passes for one thread per particle.
SEASPRING_HD inline void solidPredictorAt(std::uint32_t s, const SolidState& st, const SolidBonds& b,
                                          const ClampNodes& cn, double f, double dt, double gx, double gy,
                                          double gz) {
    solidPredictorLanes(s, 0u, 1u, st, b, cn, f, dt, gx, gy, gz);
}
SEASPRING_HD inline void solidCorrectorAt(std::uint32_t s, const SolidState& st, const SolidBonds& b,
                                          const ClampNodes& cn, double f, double dt, double gx, double gy,
                                          double gz) {
    solidCorrectorLanes(s, 0u, 1u, st, b, cn, f, dt, gx, gy, gz);
}

}  // namespace seaspring::physics
