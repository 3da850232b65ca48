// SeaSpring — MIT licence.
/// \file solid_cycle.h
/// \brief How a backend runs the VCPM solids' sub-cycle (solid_passes.h's SolidSubCycle) over
///        its arrays (solid_arrays.h): the views of the boundary block it reads and writes, the
///        contact views, the copy of the end state into the boundary block, and the launch with
///        the execution policy's `sequence` and its bond lanes. Written once for every `Exec`.
#pragma once

#include <cstdint>
#include <vector>

#include "physics/cell_grid.h"
#include "physics/sph_types.h"
#include "solver/buffers.h"
#include "solver/solid_arrays.h"
#include "solver/solid_passes.h"

namespace seaspring::solver {

/// What a solid's sub-cycle needs of the particle arrays (sorted order) and the set-up.
struct SolidBlockViews {
    const std::uint32_t* cell_start_bound = nullptr;  ///< the boundary block's cell ranges
    const std::uint32_t* id = nullptr;
    physics::Double3* pos = nullptr;
    physics::Float4* velrho = nullptr;
    physics::CellGrid grid;
    double gx = 0, gy = 0, gz = 0;  ///< gravity
};

/// The contact views of the solids' sub-cycle (off without contact).
template <template <typename> class Buf>
SubCycleContact solidContactViews(SolidArrays<Buf>& s, const SolidBlockViews& w) {
    SubCycleContact ct;
    if (!s.contact_on) return ct;
    ct.on = true;
    ct.w.cell_start = w.cell_start_bound;
    ct.w.id = w.id;
    ct.w.pos = w.pos;
    ct.w.velrho = w.velrho;
    ct.w.first_solid = s.first;
    ct.w.nsolid = s.n;
    ct.w.clamp_id = s.clamp_pid.data();
    ct.g = w.grid;
    ct.cp = s.contact;
    ct.cl = s.contactList();
    ct.force = s.contact_force.data();
    return ct;
}

/// Solid positions and velocities into the boundary block after a sub-cycle of length dt;
/// `ledger`: accumulate the impulse and work of the hydrodynamic force.
template <template <typename> class Buf>
SolidToBoundaryPass solidToBoundaryPass(SolidArrays<Buf>& s, const SolidBlockViews& w, double dt, bool ledger) {
    return SolidToBoundaryPass{s.slot.data(), s.pos.data(), s.vel.data(), s.fluid_force.data(), dt,
                               s.impulse.data(), s.work.data(), ledger, w.pos, w.velrho};
}

/// n solid sub-steps of dt from t0 (clamp nodes moved by `motions` over the whole interval,
/// uploaded into `motion_buf` when a clamp moves), ending with the copy into the boundary
/// block: one SolidSubCycle run by exec.sequence with the bond lanes exec.bondLaneShift picks.
/// With `ledger` (a step's own cycle, not the midpoint's half step) its last pass also runs
/// the per-step blow-up test's checks, which Backend::startSolidsCheck then only counts.
template <class Exec, template <typename> class Buf, class MotionBuf>
void runSolidSubCycle(const Exec& exec, SolidArrays<Buf>& s, MotionBuf& motion_buf,
                      const SolidBlockViews& w, double t0, double dt, int n,
                      const std::vector<physics::RigidMotionGpu>& motions, bool ledger) {
    s.t0 = t0;
    s.span = dt * double(n);
    ClampMotion cm;
    cm.pos_initial = s.clamp_pos_initial.data();
    cm.object = s.clamp_object.data();
    cm.pos_start = s.clamp_start.data();
    cm.pos_end = s.clamp_end.data();
    if (s.clamps_move && !motions.empty()) {  // fixed clamps read no motion
        assignFrom(motion_buf, motions);
        cm.motions = motion_buf.data();
    }
    const SubCycleContact ct = solidContactViews(s, w);
    auto cycle = [&](auto bl) {
        const SolidSubCycle<decltype(bl)::shift> body{s.state(), s.bonds(), s.clamps(), cm, n, dt, w.gx, w.gy, w.gz, ct,
                                                      bl, solidToBoundaryPass(s, w, dt * n, ledger), ledger,
                                                      s.predictor_force,
                                                      s.predictor_force ? nullptr : s.pos_half_alt.data(),
                                                      s.start_sums};
        exec.sequence(std::uint64_t(s.n) + s.nclamp, (s.n << bl.shift) + s.nclamp, body);  // widest: the sums
    };
    switch (exec.bondLaneShift(std::uint64_t(s.n) + s.nclamp, s.n)) {  // 0 on the host
    case 0: cycle(BondLanes<0>{}); break;
    case 1: cycle(BondLanes<1>{}); break;
    case 2: cycle(BondLanes<2>{}); break;
    default: cycle(BondLanes<3>{}); break;
    }
}

}  // namespace seaspring::solver
