// SeaSpring — MIT licence.
/// \file cpu_solid.cpp
/// \brief OpenMP loops of the VCPM sub-cycle (see cpu_solid.h): each loop maps particles to
///        iterations and calls one function of physics/vcpm.h; every iteration writes only its
///        own particle's entries, so any thread count gives the same bits.
#include "cpu/cpu_solid.h"

#include <omp.h>

#include "physics/solid_coupling.h"

namespace seaspring::cpu {

void CpuSolid::init(const solver::SolidSetup& s, const physics::StepConstants& step) {
    step_ = step;
    a_.init(s);
}

void CpuSolid::updateSlots(const std::uint32_t* id, std::uint32_t nbound) {
    std::uint32_t* slot = a_.slot.data();
    const std::uint32_t first = a_.first, n = a_.n;
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < std::int64_t(nbound); ++i) physics::solidSlotAt(std::uint32_t(i), id, first, n, slot);
}

/// Pass 1 and 1b of an evaluation at positions `ep` (inside a parallel region).
void CpuSolid::evaluationSums(const physics::Double3* ep, double f) {
    const physics::SolidState st = a_.state();
    const physics::SolidBonds b = a_.bonds();
    const physics::ClampNodes cn = a_.clamps();
#pragma omp for schedule(static)
    for (std::int64_t s = 0; s < std::int64_t(b.n); ++s)
        st.sum[s] = physics::solidSumAt(std::uint32_t(s), ep, st, b, cn, f);
#pragma omp for schedule(static)
    for (std::int64_t c = 0; c < std::int64_t(cn.n); ++c)
        cn.sum[c] = physics::clampSumAt(std::uint32_t(c), ep, b, cn, f);
}

void CpuSolid::steps(double t0, double dt, int n, const std::vector<physics::RigidMotionGpu>& motions) {
    if (a_.n == 0 || n <= 0) return;
    a_.t0 = t0;
    a_.span = dt * double(n);
    for (std::uint32_t c = 0; c < a_.nclamp; ++c)
        physics::clampMotionAt(c, a_.clamp_pos_initial.data(), a_.clamp_object.data(), motions.data(),
                               a_.clamp_start.data(), a_.clamp_end.data());
    const physics::SolidState st = a_.state();
    const physics::SolidBonds b = a_.bonds();
    const physics::ClampNodes cn = a_.clamps();
    const double gx = step_.gx, gy = step_.gy, gz = step_.gz;
    const double inv_n = 1.0 / double(n);
#pragma omp parallel
    for (int m = 0; m < n; ++m) {
        const double f0 = double(m) * inv_n, fh = (double(m) + 0.5) * inv_n;
        evaluationSums(st.pos, f0);
#pragma omp for schedule(static)
        for (std::int64_t s = 0; s < std::int64_t(b.n); ++s)
            physics::solidPredictorAt(std::uint32_t(s), st, b, cn, f0, dt, gx, gy, gz);
        evaluationSums(st.pos_half, fh);
#pragma omp for schedule(static)
        for (std::int64_t s = 0; s < std::int64_t(b.n); ++s)
            physics::solidCorrectorAt(std::uint32_t(s), st, b, cn, fh, dt, gx, gy, gz);
    }
}

void CpuSolid::toBoundary(double dt, bool ledger, physics::Double3* bpos, physics::Float4* bvelrho) {
    const std::uint32_t* slot = a_.slot.data();
    const physics::Double3 *p = a_.pos.data(), *v = a_.vel.data(), *f = a_.fluid_force.data();
    physics::Double3* imp = a_.impulse.data();
    double* work = a_.work.data();
#pragma omp parallel for schedule(static)
    for (std::int64_t s = 0; s < std::int64_t(a_.n); ++s)
        physics::solidToBoundaryAt(std::uint32_t(s), slot, p, v, f, dt, imp, work, ledger, bpos, bvelrho);
}

}  // namespace seaspring::cpu
