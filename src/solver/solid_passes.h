// SeaSpring — MIT licence.
/// \file solid_passes.h
/// \brief The passes of the VCPM solids, one functor each over one function of physics/vcpm.h
///        or physics/solid_coupling.h, and the sub-cycle as one sequence of passes.
///
/// A sub-step is four passes (sums at r^m, predictor, sums at r^{m+1/2}, corrector; the sums
/// pass also takes the clamp nodes' sums and, with contact, the contact force), each needing
/// the previous one complete. On the GPU a particle's bond slots are spread over several
/// threads ("bond lanes", physics/vcpm_substep.h: the same bits). SolidSubCycle writes that sequence
/// once; the execution policy's `sequence` runs it with a runner `run(n, pass)` that runs the
/// pass for indices [0, n) and returns when all are done: an `omp for` inside one parallel
/// region (CPU), one grid-wide launch per pass (GPU, large solids), or a block-stride loop and
/// a barrier inside ONE single-block kernel (GPU, small solids: one launch per sub-cycle
/// instead of 1 + 4 n). Every pass writes only its own index's entries, so each runner gives
/// the same bits (a clamp node reads a breakage flag that the bond's solid end may set in the
/// same pass; physics::clampSumAt gets the same result from the old and the new flag).
#pragma once

#include <cstdint>

#include "physics/solid_contact.h"
#include "physics/solid_coupling.h"
#include "physics/vcpm.h"
#include "physics/vcpm_substep.h"

namespace seaspring::solver {

/// The arguments of physics::clampMotionAt (ClampNodes exposes the positions read-only).
struct ClampMotion {
    const physics::Double3* pos_initial = nullptr;
    const std::int16_t* object = nullptr;
    const physics::RigidMotionGpu* motions = nullptr;
    physics::Double3* pos_start = nullptr;
    physics::Double3* pos_end = nullptr;
};

/// Bond lanes (physics/vcpm_substep.h; the GPU's sub-cycle of large solids): index k of
/// [0, n << kShift) is lane k mod 2^kShift of solid particle k >> kShift. kShift = 0 is one
/// thread per particle (the host, the GPU's single-block sub-cycle). A particle's lanes are
/// consecutive threads of one warp (every runner's indices start at 0 and its blocks are whole
/// warps). A compile-time constant, so the lanes' loops unroll (and vanish for one lane).
template <std::uint32_t kShift>
struct BondLanes {
    static constexpr std::uint32_t shift = kShift;
    SEASPRING_HD static constexpr std::uint32_t lanes() { return 1u << kShift; }
    SEASPRING_HD static constexpr std::uint32_t particle(std::uint32_t k) { return k >> kShift; }
    SEASPRING_HD static constexpr std::uint32_t lane(std::uint32_t k) { return k & (lanes() - 1u); }
};

/// The predictor (kCorrector false) or the corrector pass of a sub-step; `half_next` (corrector
/// only, when the predictor's force is unused): then the next sub-step's half step into it.
template <std::uint32_t kShift, bool kCorrector>
struct SolidStepPass {
    physics::SolidState st;
    physics::SolidBonds b;
    physics::ClampNodes cn;
    double f, dt, gx, gy, gz;
    BondLanes<kShift> bl;
    physics::Double3* half_next = nullptr;
    SEASPRING_HD void operator()(std::uint32_t k) const {
        if constexpr (kCorrector)
            physics::solidCorrectorLanes(bl.particle(k), bl.lane(k), bl.lanes(), st, b, cn, f, dt, gx, gy, gz,
                                         half_next);
        else
            physics::solidPredictorLanes(bl.particle(k), bl.lane(k), bl.lanes(), st, b, cn, f, dt, gx, gy, gz);
    }
};

struct SolidSlotPass {
    const std::uint32_t* id;
    std::uint32_t first, n;
    std::uint32_t* slot;
    SEASPRING_HD void operator()(std::uint32_t i) const { physics::solidSlotAt(i, id, first, n, slot); }
};

struct SolidToBoundaryPass {
    const std::uint32_t* slot;
    const physics::Double3 *pos, *vel, *fluid_force;
    double dt;
    physics::Double3* impulse;
    double* work;
    bool ledger;
    physics::Double3* bpos;
    physics::Float4* bvelrho;
    SEASPRING_HD void operator()(std::uint32_t s) const {
        physics::solidToBoundaryAt(s, slot, pos, vel, fluid_force, dt, impulse, work, ledger, bpos, bvelrho);
    }
};

/// The midpoint coupling's snapshot of a solid (SolidArrays::snapshotPass): positions,
/// velocities, bond states and, with contact, the contact ledger copied from the `from` arrays
/// to the `to` arrays over indices [0, max(n, slots)); on the way back (`to_boundary`), each
/// restored particle's state then goes into the boundary block in the same pass (it reads only
/// its own index). One launch where there were three copies (and a fourth launch).
struct SolidSnapshotPass {
    std::uint32_t n, slots;
    const physics::Double3 *pos_from, *vel_from;
    physics::Double3 *pos_to, *vel_to;
    const std::uint8_t* broken_from;
    std::uint8_t* broken_to;
    const physics::Double3* contact_impulse_from;  ///< null without contact
    physics::Double3* contact_impulse_to;
    const double* contact_work_from;
    double* contact_work_to;
    bool to_boundary;
    SolidToBoundaryPass boundary;  ///< reads pos_to and vel_to (the arrays restored)
    SEASPRING_HD void operator()(std::uint32_t i) const {
        if (i < slots) broken_to[i] = broken_from[i];
        if (i >= n) return;
        pos_to[i] = pos_from[i];
        vel_to[i] = vel_from[i];
        if (contact_impulse_to) {
            contact_impulse_to[i] = contact_impulse_from[i];
            contact_work_to[i] = contact_work_from[i];
        }
        if (to_boundary) boundary(i);
    }
};

/// The contact views of a sub-cycle (`on` false: no contact).
struct SubCycleContact {
    bool on = false;
    physics::ContactBoundary w;
    physics::CellGrid g;
    physics::ContactParams cp;
    physics::ContactList cl;
    physics::Double3* force = nullptr;
};

/// The first pass of a force evaluation at positions `ep`: the sums S of the solid particles
/// (indices [0, b.n << kShift), their bond lanes: physics::solidSumLanes, which decides the
/// bonds' breakage; lane 0 writes S) and of the clamp nodes (one index each after them:
/// physics::clampSumAt decides its bonds' breakage with the same bits, so it needs no pass of
/// its own); with contact, each solid particle's contact force too (lane 0; it reads positions
/// and velocities, which no part of this pass writes).
template <std::uint32_t kShift>
struct SolidSumsPass {
    const physics::Double3* ep;
    physics::SolidState st;
    physics::SolidBonds b;
    physics::ClampNodes cn;
    double f;
    SubCycleContact ct;
    BondLanes<kShift> bl;
    SEASPRING_HD void operator()(std::uint32_t k) const {
        const std::uint32_t nl = b.n << bl.shift;
        if (k < nl) {
            const std::uint32_t i = bl.particle(k), lane = bl.lane(k);
            const double sum = physics::solidSumLanes(i, lane, bl.lanes(), ep, st, b, cn, f);
            if (lane != 0u) return;
            st.sum[i] = sum;
            if (ct.on) ct.force[i] = physics::contactForceAt(i, ep, st, ct.w, ct.cp, ct.cl);
        } else {
            cn.sum[k - nl] = physics::clampSumAt(k - nl, ep, st, b, cn, f);
        }
    }
};

/// The start of a sub-cycle: the clamp nodes' motion over it (indices [0, cn.n)) and, for the
/// solid particles ([cn.n, cn.n + b.n); they read the solid particles and the boundary block,
/// not the clamp nodes' motion), with contact their candidate lists, or, when the predictor's
/// force is unused (`half_step`; never with contact), the first sub-step's half step.
struct SubCycleStartPass {
    ClampMotion cm;
    std::uint32_t nclamp;
    physics::SolidState st;
    physics::SolidBonds b;
    SubCycleContact ct;
    bool half_step;
    double dt;
    SEASPRING_HD void operator()(std::uint32_t i) const {
        if (i < nclamp)
            physics::clampMotionAt(i, cm.pos_initial, cm.object, cm.motions, cm.pos_start, cm.pos_end);
        else if (ct.on)
            physics::contactCandidatesAt(i - nclamp, st, b, ct.w, ct.g, ct.cp, ct.cl);
        else if (half_step)
            physics::solidHalfStepAt(i - nclamp, st, dt, st.pos_half);
    }
};

/// The per-step blow-up test of solid particle s at the end of a sub-cycle: with contact, its
/// motion against its contact list (physics::contactMotionAlarmAt), then its bonds at the end
/// positions (physics::solidAlarmAfterSubCycleAt); it writes only s's alarm. 1 when s's alarm
/// is raised.
SEASPRING_HD inline std::uint32_t solidEndCheckAt(std::uint32_t s, const physics::SolidState& st,
                                                  const physics::SolidBonds& b, const physics::ClampNodes& cn,
                                                  const SubCycleContact& ct) {
    if (ct.on) physics::contactMotionAlarmAt(s, st, ct.cp, ct.cl);
    return physics::solidAlarmAfterSubCycleAt(s, st, b, cn);
}

/// Value pass of the per-step blow-up test, summed with CountCombine (integers, exact in any
/// order): solidEndCheckAt, or, when the sub-cycle's last pass already ran it at these
/// positions (`checked`: SolidEndPass), only whether s's alarm is raised.
struct SolidAlarmPass {
    physics::SolidState st;
    physics::SolidBonds b;
    physics::ClampNodes cn;
    SubCycleContact ct;
    bool checked;
    SEASPRING_HD std::uint32_t operator()(std::uint32_t s) const {
        if (checked) return st.alarm[s].kind != physics::kSolidAlarmNone ? 1u : 0u;
        return solidEndCheckAt(s, st, b, cn, ct);
    }
};

/// The last pass of a sub-cycle: the solid's end state into the boundary block and, with
/// `check` (the sub-cycles the per-step test follows), the test's checks of each particle
/// (solidEndCheckAt), in the same launch. Each reads the end positions, which no pass writes
/// after the last corrector, and writes only its own index.
struct SolidEndPass {
    SolidToBoundaryPass to_boundary;
    bool check;
    physics::SolidState st;
    physics::SolidBonds b;
    physics::ClampNodes cn;
    SubCycleContact ct;
    SEASPRING_HD void operator()(std::uint32_t s) const {
        to_boundary(s);
        if (check) solidEndCheckAt(s, st, b, cn, ct);
    }
};

/// The speed of solid particle s (reduced with MaxCombine: a maximum is exact in any order).
struct SolidSpeedPass {
    const physics::Double3* vel;
    SEASPRING_HD double operator()(std::uint32_t s) const { return physics::speedOf(vel[s]); }
};

/// The larger, NaN when either is (so the result does not depend on the reduction's order).
struct MaxCombine {
    SEASPRING_HD double operator()(double a, double b) const { return a != a ? a : (b != b ? b : (a > b ? a : b)); }
};

struct CountCombine {
    SEASPRING_HD std::uint32_t operator()(std::uint32_t a, std::uint32_t b) const { return a + b; }
};

/// Clamp motion (and the contact lists), then n sub-steps of dt (fractions of the interval
/// computed with IEEE division and product, so every runner has the same bits); with contact,
/// the contact force in the sums pass of each evaluation; last, the solid's end state into the
/// boundary block (SolidToBoundaryPass, with the ledger's impulse and work over the cycle) and,
/// with check_end, the per-step blow-up test's checks (SolidEndPass). Without
/// `predictor_force` (physics::predictorForceUsed false: undamped, no contact) a sub-step is
/// the sums at r^m only where they decide breakage (`start_sums`, physics::startSumsUsed), the
/// sums at r^{m+1/2} and the corrector, which also takes the next sub-step's half step (the
/// first one's is in the start pass): the same bits as the four passes. The
/// corrector reads its neighbours' r^{m+1/2} while it writes r^{m+3/2}, so the half positions
/// alternate between st.pos_half (even m) and `pos_half_alt` (odd m).
template <std::uint32_t kShift>
struct SolidSubCycle {
    physics::SolidState st;
    physics::SolidBonds b;
    physics::ClampNodes cn;
    ClampMotion cm;
    int n;
    double dt, gx, gy, gz;
    SubCycleContact ct;
    BondLanes<kShift> bl;  ///< shift 0: one thread per particle
    SolidToBoundaryPass to_boundary;  ///< the last pass: the end state into the boundary block
    bool check_end;  ///< the last pass also runs the per-step test's checks (SolidEndPass)
    bool predictor_force = true;  ///< false: the evaluation at r^m skipped (physics::predictorForceUsed)
    physics::Double3* pos_half_alt = nullptr;  ///< the odd sub-steps' r^{m+1/2} without predictor_force
    bool start_sums = true;  ///< without predictor_force: the sums pass at r^m still runs (breakage)

#if defined(__CUDACC__)
#pragma nv_exec_check_disable
#endif
    template <class Run>
    SEASPRING_HD void operator()(Run& run) const {
        const bool half_step = !predictor_force && !ct.on && pos_half_alt != nullptr;
        run(cn.n + (ct.on || half_step ? b.n : 0u), SubCycleStartPass{cm, cn.n, st, b, ct, half_step, dt});
        const double inv_n = 1.0 / double(n);
        const std::uint32_t nl = b.n << bl.shift;
        for (int m = 0; m < n; ++m) {
            const double f0 = double(m) * inv_n, fh = (double(m) + 0.5) * inv_n;
            if (!half_step) {
                run(nl + cn.n, SolidSumsPass<kShift>{st.pos, st, b, cn, f0, ct, bl});
                run(nl, SolidStepPass<kShift, false>{st, b, cn, f0, dt, gx, gy, gz, bl});
                run(nl + cn.n, SolidSumsPass<kShift>{st.pos_half, st, b, cn, fh, ct, bl});
                run(nl, SolidStepPass<kShift, true>{st, b, cn, fh, dt, gx, gy, gz, bl});
                continue;
            }
            if (start_sums) run(nl + cn.n, SolidSumsPass<kShift>{st.pos, st, b, cn, f0, ct, bl});
            physics::SolidState sm = st;
            sm.pos_half = (m & 1) ? pos_half_alt : st.pos_half;
            physics::Double3* next = (m & 1) ? st.pos_half : pos_half_alt;
            run(nl + cn.n, SolidSumsPass<kShift>{sm.pos_half, sm, b, cn, fh, ct, bl});
            run(nl, SolidStepPass<kShift, true>{sm, b, cn, fh, dt, gx, gy, gz, bl, next});
        }
        run(b.n, SolidEndPass{to_boundary, check_end, st, b, cn, ct});  // in the sub-steps' launch in one block
    }
};

}  // namespace seaspring::solver
