// SeaSpring — MIT licence.
/// \file solid_passes.h
/// \brief The passes of the VCPM solids, one functor each over one function of physics/vcpm.h
///        or physics/solid_coupling.h, and the sub-cycle as one sequence of passes.
///
/// A sub-step is six passes (sums at r^m, clamp sums, predictor, sums at r^{m+1/2}, clamp sums,
/// corrector), each needing the previous one complete. SolidSubCycle writes that sequence
/// once; the execution policy's `sequence` runs it with a runner `run(n, pass)` that runs the
/// pass for indices [0, n) and returns when all are done: an `omp for` inside one parallel
/// region (CPU), one grid-wide launch per pass (GPU, large solids), or a block-stride loop and
/// a barrier inside ONE single-block kernel (GPU, small solids: one launch per sub-cycle
/// instead of 1 + 6 n). Every pass writes only its own index's entries, so each runner gives
/// the same bits.
#pragma once

#include <cstdint>

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

/// Clamp motion, then n sub-steps of dt (fractions of the interval computed with IEEE division
/// and product, so every runner has the same bits).
struct SolidSubCycle {
    physics::SolidState st;
    physics::SolidBonds b;
    physics::ClampNodes cn;
    ClampMotion cm;
    int n;
    double dt, gx, gy, gz;

#if defined(__CUDACC__)
#pragma nv_exec_check_disable
#endif
    template <class Run>
    SEASPRING_HD void operator()(Run& run) const {
        run(cn.n, ClampMotionPass{cm});
        const double inv_n = 1.0 / double(n);
        for (int m = 0; m < n; ++m) {
            const double f0 = double(m) * inv_n, fh = (double(m) + 0.5) * inv_n;
            run(b.n, SolidSumPass{st.pos, st, b, cn, f0});
            run(cn.n, ClampSumPass{st.pos, b, cn, f0});
            run(b.n, SolidPredictorPass{st, b, cn, f0, dt, gx, gy, gz});
            run(b.n, SolidSumPass{st.pos_half, st, b, cn, fh});
            run(cn.n, ClampSumPass{st.pos_half, b, cn, fh});
            run(b.n, SolidCorrectorPass{st, b, cn, fh, dt, gx, gy, gz});
        }
    }
};

}  // namespace seaspring::solver
