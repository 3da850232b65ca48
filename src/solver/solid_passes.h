// SeaSpring — MIT licence.
/// \file solid_passes.h
/// \brief The passes of the VCPM solids, one functor each over one function of physics/vcpm.h
///        or physics/solid_coupling.h, and the sub-cycle as one sequence of passes.
///
/// A sub-step is six passes (sums at r^m, clamp sums, predictor, sums at r^{m+1/2}, clamp sums,
/// corrector), eight with contact (its force before the predictor and the corrector), each
/// needing the previous one complete. SolidSubCycle writes that sequence
/// once; the execution policy's `sequence` runs it with a runner `run(n, pass)` that runs the
/// pass for indices [0, n) and returns when all are done: an `omp for` inside one parallel
/// region (CPU), one grid-wide launch per pass (GPU, large solids), or a block-stride loop and
/// a barrier inside ONE single-block kernel (GPU, small solids: one launch per sub-cycle
/// instead of 1 + 6 n). Every pass writes only its own index's entries, so each runner gives
/// the same bits.
#pragma once

#include <cstdint>

#include "physics/solid_contact.h"
#include "physics/solid_coupling.h"
#include "physics/vcpm.h"

namespace seaspring::solver {

/// The arguments of physics::clampMotionAt (ClampNodes exposes the positions read-only).
struct ClampMotion {
    const physics::Double3* pos_initial = nullptr;
    const std::int16_t* object = nullptr;
    const physics::RigidMotionGpu* motions = nullptr;
    physics::Double3* pos_start = nullptr;
    physics::Double3* pos_end = nullptr;
};

struct ClampMotionPass {
    ClampMotion cm;
    SEASPRING_HD void operator()(std::uint32_t c) const {
        physics::clampMotionAt(c, cm.pos_initial, cm.object, cm.motions, cm.pos_start, cm.pos_end);
    }
};

struct SolidSumPass {
    const physics::Double3* ep;
    physics::SolidState st;
    physics::SolidBonds b;
    physics::ClampNodes cn;
    double f;
    SEASPRING_HD void operator()(std::uint32_t s) const { st.sum[s] = physics::solidSumAt(s, ep, st, b, cn, f); }
};

struct ClampSumPass {
    const physics::Double3* ep;
    physics::SolidBonds b;
    physics::ClampNodes cn;
    double f;
    SEASPRING_HD void operator()(std::uint32_t c) const { cn.sum[c] = physics::clampSumAt(c, ep, b, cn, f); }
};

struct SolidPredictorPass {
    physics::SolidState st;
    physics::SolidBonds b;
    physics::ClampNodes cn;
    double f, dt, gx, gy, gz;
    SEASPRING_HD void operator()(std::uint32_t s) const { physics::solidPredictorAt(s, st, b, cn, f, dt, gx, gy, gz); }
};

struct SolidCorrectorPass {
    physics::SolidState st;
    physics::SolidBonds b;
    physics::ClampNodes cn;
    double f, dt, gx, gy, gz;
    SEASPRING_HD void operator()(std::uint32_t s) const { physics::solidCorrectorAt(s, st, b, cn, f, dt, gx, gy, gz); }
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

/// Contact (physics/solid_contact.h): the candidate lists at the start of a sub-cycle ...
struct ContactListPass {
    physics::SolidState st;
    physics::SolidBonds b;
    physics::ContactBoundary w;
    physics::CellGrid g;
    physics::ContactParams cp;
    physics::ContactList cl;
    SEASPRING_HD void operator()(std::uint32_t s) const { physics::contactCandidatesAt(s, st, b, w, g, cp, cl); }
};

/// ... and the contact force of an evaluation at positions `ep` (into st.contact_force).
struct ContactForcePass {
    const physics::Double3* ep;
    physics::SolidState st;
    physics::ContactBoundary w;
    physics::ContactParams cp;
    physics::ContactList cl;
    physics::Double3* out;
    SEASPRING_HD void operator()(std::uint32_t s) const { out[s] = physics::contactForceAt(s, ep, st, w, cp, cl); }
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

/// Value pass of the per-step blow-up test (physics::solidAlarmAfterSubCycleAt: 1 for a
/// particle whose alarm is raised; it writes only its own alarm), summed with CountCombine:
/// integers, exact in any order.
struct SolidAlarmPass {
    physics::SolidState st;
    physics::SolidBonds b;
    physics::ClampNodes cn;
    SubCycleContact ct;
    SEASPRING_HD std::uint32_t operator()(std::uint32_t s) const {
        if (ct.on) physics::contactMotionAlarmAt(s, st, ct.cp, ct.cl);
        return physics::solidAlarmAfterSubCycleAt(s, st, b, cn);
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
/// the contact force after the sums of each evaluation.
struct SolidSubCycle {
    physics::SolidState st;
    physics::SolidBonds b;
    physics::ClampNodes cn;
    ClampMotion cm;
    int n;
    double dt, gx, gy, gz;
    SubCycleContact ct;

#if defined(__CUDACC__)
#pragma nv_exec_check_disable
#endif
    template <class Run>
    SEASPRING_HD void operator()(Run& run) const {
        run(cn.n, ClampMotionPass{cm});
        if (ct.on) run(b.n, ContactListPass{st, b, ct.w, ct.g, ct.cp, ct.cl});
        const double inv_n = 1.0 / double(n);
        for (int m = 0; m < n; ++m) {
            const double f0 = double(m) * inv_n, fh = (double(m) + 0.5) * inv_n;
            run(b.n, SolidSumPass{st.pos, st, b, cn, f0});
            run(cn.n, ClampSumPass{st.pos, b, cn, f0});
            if (ct.on) run(b.n, ContactForcePass{st.pos, st, ct.w, ct.cp, ct.cl, ct.force});
            run(b.n, SolidPredictorPass{st, b, cn, f0, dt, gx, gy, gz});
            run(b.n, SolidSumPass{st.pos_half, st, b, cn, fh});
            run(cn.n, ClampSumPass{st.pos_half, b, cn, fh});
            if (ct.on) run(b.n, ContactForcePass{st.pos_half, st, ct.w, ct.cp, ct.cl, ct.force});
            run(b.n, SolidCorrectorPass{st, b, cn, fh, dt, gx, gy, gz});
        }
    }
};

}  // namespace seaspring::solver
