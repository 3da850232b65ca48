// SeaSpring — MIT licence.
/// \file solid_passes.h
/// \brief The passes of the VCPM solids, one functor each over one function of physics/vcpm.h
///        or physics/solid_coupling.h, and the sub-cycle as one sequence of passes.
///
/// A sub-step is eight passes, each needing the previous one complete: at r^m the sums' terms
/// per bond slot, the sums per particle (with the clamp nodes' sums and, with contact, the
/// contact force), the forces' terms per bond slot, the predictor (which adds up its force);
/// the same at r^{m+1/2} with the corrector. One thread per bond in the slot passes: a
/// particle's bonds are evaluated side by side (their square roots and divisions are the
/// latency of a small solid's sub-step), then added up in slot order, the bits of the
/// one-thread-per-particle sums (physics::solidSumAt, solidBondForceAt). SolidSubCycle writes that sequence
/// once; the execution policy's `sequence` runs it with a runner `run(n, pass)` that runs the
/// pass for indices [0, n) and returns when all are done: an `omp for` inside one parallel
/// region (CPU), one grid-wide launch per pass (GPU, large solids), or a block-stride loop and
/// a barrier inside ONE single-block kernel (GPU, small solids: one launch per sub-cycle
/// instead of 1 + 8 n). Every pass writes only its own index's entries, so each runner gives
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

/// The slot passes of an evaluation at positions `ep` (one index per bond slot,
/// b.rows * b.n of them): the sums' terms, then (after the sums) the forces' terms.
struct SolidSumSlotPass {
    const physics::Double3* ep;
    physics::SolidState st;
    physics::SolidBonds b;
    physics::ClampNodes cn;
    double f;
    SEASPRING_HD void operator()(std::uint32_t k) const { physics::solidSumSlotAt(k, ep, st, b, cn, f); }
};

struct SolidForceSlotPass {
    const physics::Double3* ep;
    physics::SolidState st;
    physics::SolidBonds b;
    physics::ClampNodes cn;
    double f;
    SEASPRING_HD void operator()(std::uint32_t k) const { physics::solidForceSlotAt(k, ep, st, b, cn, f); }
};

struct SolidPredictorPass {
    physics::SolidState st;
    physics::SolidBonds b;
    double f, dt, gx, gy, gz;
    SEASPRING_HD void operator()(std::uint32_t s) const { physics::solidPredictorAt(s, st, b, f, dt, gx, gy, gz); }
};

struct SolidCorrectorPass {
    physics::SolidState st;
    physics::SolidBonds b;
    double f, dt, gx, gy, gz;
    SEASPRING_HD void operator()(std::uint32_t s) const { physics::solidCorrectorAt(s, st, b, f, dt, gx, gy, gz); }
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

/// The contact views of a sub-cycle (`on` false: no contact).
struct SubCycleContact {
    bool on = false;
    physics::ContactBoundary w;
    physics::CellGrid g;
    physics::ContactParams cp;
    physics::ContactList cl;
    physics::Double3* force = nullptr;
};

/// After SolidSumSlotPass: the sums S of the solid particles (indices [0, b.n):
/// physics::solidSumGatherAt) and of the clamp nodes ([b.n, b.n + cn.n): physics::clampSumAt,
/// which reads the breakage the slot pass decided); with contact, each solid particle's contact
/// force too (it reads positions and velocities, which no part of this pass writes).
struct SolidSumsPass {
    const physics::Double3* ep;
    physics::SolidState st;
    physics::SolidBonds b;
    physics::ClampNodes cn;
    double f;
    SubCycleContact ct;
    SEASPRING_HD void operator()(std::uint32_t i) const {
        if (i < b.n) {
            st.sum[i] = physics::solidSumGatherAt(i, ep, st, b, f);
            if (ct.on) ct.force[i] = physics::contactForceAt(i, ep, st, ct.w, ct.cp, ct.cl);
        } else {
            cn.sum[i - b.n] = physics::clampSumAt(i - b.n, ep, b, cn, f);
        }
    }
};

/// The start of a sub-cycle: the clamp nodes' motion over it (indices [0, cn.n)) and, with
/// contact, the solid particles' candidate lists ([cn.n, cn.n + b.n); they read the solid
/// particles and the boundary block, not the clamp nodes' motion).
struct SubCycleStartPass {
    ClampMotion cm;
    std::uint32_t nclamp;
    physics::SolidState st;
    physics::SolidBonds b;
    SubCycleContact ct;
    SEASPRING_HD void operator()(std::uint32_t i) const {
        if (i < nclamp)
            physics::clampMotionAt(i, cm.pos_initial, cm.object, cm.motions, cm.pos_start, cm.pos_end);
        else
            physics::contactCandidatesAt(i - nclamp, st, b, ct.w, ct.g, ct.cp, ct.cl);
    }
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
/// the contact force in the sums pass of each evaluation.
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
        run(cn.n + (ct.on ? b.n : 0u), SubCycleStartPass{cm, cn.n, st, b, ct});
        const double inv_n = 1.0 / double(n);
        const std::uint32_t nsums = b.n + cn.n, nslots = b.rows * b.n;
        for (int m = 0; m < n; ++m) {
            const double f0 = double(m) * inv_n, fh = (double(m) + 0.5) * inv_n;
            run(nslots, SolidSumSlotPass{st.pos, st, b, cn, f0});
            run(nsums, SolidSumsPass{st.pos, st, b, cn, f0, ct});
            run(nslots, SolidForceSlotPass{st.pos, st, b, cn, f0});
            run(b.n, SolidPredictorPass{st, b, f0, dt, gx, gy, gz});
            run(nslots, SolidSumSlotPass{st.pos_half, st, b, cn, fh});
            run(nsums, SolidSumsPass{st.pos_half, st, b, cn, fh, ct});
            run(nslots, SolidForceSlotPass{st.pos_half, st, b, cn, fh});
            run(b.n, SolidCorrectorPass{st, b, fh, dt, gx, gy, gz});
        }
    }
};

}  // namespace seaspring::solver
