// SeaSpring — MIT licence.
/// \file cpu_solid.cpp
/// \brief OpenMP loops of the VCPM sub-step (see cpu_solid.h): each loop maps particles to
///        iterations and calls one function of physics/vcpm.h; every iteration writes only its
///        own particle's entries, so any thread count gives the same bits.
#include "cpu/cpu_solid.h"

#include <omp.h>

#include "physics/solid_coupling.h"

namespace seaspring::cpu {

void CpuSolid::init(const solver::SolidSetup& s, const physics::StepConstants& step) {
    n_ = s.nsolid;
    nclamp_ = s.nclamp;
    first_ = s.first_solid;
    step_ = step;
    count_ = s.count;
    partner_ = s.partner;
    rest_ = s.rest;
    flags_ = s.flags;
    broken_.assign(s.flags.size(), 0);
    body_ = s.body;
    materials_ = s.materials;
    pos_ = s.pos;
    pos_half_ = s.pos;
    vel_ = s.vel;
    vel0_ = s.vel;
    fluid_force_.assign(n_, physics::Double3{0, 0, 0});
    sum_.assign(n_, 0.0);
    impulse_.assign(n_, physics::Double3{0, 0, 0});
    work_.assign(n_, 0.0);
    slot_.assign(n_, 0);
    clamp_count_ = s.clamp_count;
    clamp_partner_ = s.clamp_partner;
    clamp_slot_ = s.clamp_slot;
    clamp_pos_initial_ = s.clamp_pos;
    clamp_start_ = s.clamp_pos;
    clamp_end_ = s.clamp_pos;
    clamp_object_ = s.clamp_object;
    clamp_sum_.assign(nclamp_, 0.0);
    load_force_ = s.load_force;
    load_rate_ = s.load_rate;
}

physics::SolidState CpuSolid::state() {
    physics::SolidState st;
    st.pos = pos_.data();
    st.pos_half = pos_half_.data();
    st.vel = vel_.data();
    st.vel0 = vel0_.data();
    st.sum = sum_.data();
    st.fluid_force = fluid_force_.data();
    st.body = body_.data();
    st.material = materials_.data();
    st.load_force = load_force_.empty() ? nullptr : load_force_.data();
    st.load_rate = load_rate_.empty() ? nullptr : load_rate_.data();
    st.t0 = t0_;
    st.span = span_;
    return st;
}

physics::SolidBonds CpuSolid::bonds() {
    physics::SolidBonds b;
    b.n = n_;
    b.count = count_.data();
    b.partner = partner_.data();
    b.rest = rest_.data();
    b.flags = flags_.data();
    b.broken = broken_.data();
    return b;
}

physics::ClampNodes CpuSolid::clamps() {
    physics::ClampNodes c;
    c.n = nclamp_;
    c.count = clamp_count_.data();
    c.partner = clamp_partner_.data();
    c.slot = clamp_slot_.data();
    c.pos_start = clamp_start_.data();
    c.pos_end = clamp_end_.data();
    c.sum = clamp_sum_.data();
    return c;
}

void CpuSolid::updateSlots(const std::uint32_t* id, std::uint32_t nbound) {
    std::uint32_t* slot = slot_.data();
    const std::uint32_t first = first_, n = n_;
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < std::int64_t(nbound); ++i) physics::solidSlotAt(std::uint32_t(i), id, first, n, slot);
}

void CpuSolid::evaluationSums(const physics::Double3* ep, double f) {
    const physics::SolidState st = state();
    const physics::SolidBonds b = bonds();
    const physics::ClampNodes cn = clamps();
#pragma omp for schedule(static)
    for (std::int64_t s = 0; s < std::int64_t(n_); ++s)
        st.sum[s] = physics::solidSumAt(std::uint32_t(s), ep, st, b, cn, f);
#pragma omp for schedule(static)
    for (std::int64_t c = 0; c < std::int64_t(nclamp_); ++c)
        cn.sum[c] = physics::clampSumAt(std::uint32_t(c), ep, b, cn, f);
}

void CpuSolid::steps(double t0, double dt, int n, const std::vector<physics::RigidMotionGpu>& motions) {
    if (n_ == 0 || n <= 0) return;
    t0_ = t0;
    span_ = dt * double(n);
    for (std::uint32_t c = 0; c < nclamp_; ++c)
        physics::clampMotionAt(c, clamp_pos_initial_.data(), clamp_object_.data(), motions.data(),
                               clamp_start_.data(), clamp_end_.data());
    const physics::SolidState st = state();
    const physics::SolidBonds b = bonds();
    const physics::ClampNodes cn = clamps();
    const double gx = step_.gx, gy = step_.gy, gz = step_.gz;
    const double inv_n = 1.0 / double(n);
#pragma omp parallel
    for (int m = 0; m < n; ++m) {
        const double f0 = double(m) * inv_n, fh = (double(m) + 0.5) * inv_n;
        evaluationSums(st.pos, f0);
#pragma omp for schedule(static)
        for (std::int64_t s = 0; s < std::int64_t(n_); ++s)
            physics::solidPredictorAt(std::uint32_t(s), st, b, cn, f0, dt, gx, gy, gz);
        evaluationSums(st.pos_half, fh);
#pragma omp for schedule(static)
        for (std::int64_t s = 0; s < std::int64_t(n_); ++s)
            physics::solidCorrectorAt(std::uint32_t(s), st, b, cn, fh, dt, gx, gy, gz);
    }
}

void CpuSolid::save() {
    pos_saved_ = pos_;
    vel_saved_ = vel_;
    broken_saved_ = broken_;
}

void CpuSolid::restore() {
    pos_ = pos_saved_;
    vel_ = vel_saved_;
    broken_ = broken_saved_;
}

void CpuSolid::toBoundary(double dt, bool ledger, physics::Double3* bpos, physics::Float4* bvelrho) {
    const std::uint32_t* slot = slot_.data();
    const physics::Double3 *p = pos_.data(), *v = vel_.data(), *f = fluid_force_.data();
    physics::Double3* imp = impulse_.data();
    double* work = work_.data();
#pragma omp parallel for schedule(static)
    for (std::int64_t s = 0; s < std::int64_t(n_); ++s)
        physics::solidToBoundaryAt(std::uint32_t(s), slot, p, v, f, dt, imp, work, ledger, bpos, bvelrho);
}

void CpuSolid::download(solver::HostState& out) const {
    out.solid_vel = vel_;
    out.solid_force = fluid_force_;
    out.bond_broken = broken_;
    out.solid_impulse = impulse_;
    out.solid_work = work_;
}

}  // namespace seaspring::cpu
