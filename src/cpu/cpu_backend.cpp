// SeaSpring — MIT licence.
/// \file cpu_backend.cpp
/// \brief OpenMP backend: sorting, cell ranges, motion, integration (loops over the shared
///        per-particle functions) and the force dispatch.
#include "cpu/cpu_backend.h"

#include <omp.h>

#include <algorithm>
#include <fstream>
#include <numeric>
#include <string>
#include <utility>

#include "core/error.h"
#include "cpu/cpu_gauges.h"
#include "cpu/cpu_solid.h"
#include "physics/fluid_interaction.h"

namespace seaspring::cpu {

physics::DtMaxima cpuForces_wendland(const solver::PhysicsChoice&, CpuArrays&, std::uint32_t,
                                     std::uint32_t, const physics::FluidConstants&,
                                     const physics::CellGrid&);
physics::DtMaxima cpuForces_cubic(const solver::PhysicsChoice&, CpuArrays&, std::uint32_t,
                                  std::uint32_t, const physics::FluidConstants&,
                                  const physics::CellGrid&);

void cpuHydroForces_wendland(const solver::PhysicsChoice&, CpuArrays&, const std::uint32_t*, std::uint32_t,
                            physics::Double3*, const physics::FluidConstants&, const physics::CellGrid&);
void cpuHydroForces_cubic(const solver::PhysicsChoice&, CpuArrays&, const std::uint32_t*, std::uint32_t,
                         physics::Double3*, const physics::FluidConstants&, const physics::CellGrid&);

physics::DtMaxima cpuComputeForces(const solver::PhysicsChoice& choice, CpuArrays& a,
                                   std::uint32_t nbound, std::uint32_t nfluid,
                                   const physics::FluidConstants& c, const physics::CellGrid& g) {
    if (choice.kernel == physics::KernelType::Wendland)
        return cpuForces_wendland(choice, a, nbound, nfluid, c, g);
    return cpuForces_cubic(choice, a, nbound, nfluid, c, g);
}

physics::ParticleView CpuArrays::view() {
    physics::ParticleView v;
    v.id = id.data();
    v.pos = pos.data();
    v.velrho = velrho.data();
    v.excl = excl.data();
    v.poscell = poscell.data();
    v.press_ovrho = press_ovrho.data();
    v.pos_pre = pos_pre.data();
    v.velrho_pre = velrho_pre.data();
    v.acear = acear.data();
    v.visc = visc.data();
    v.tau = tau.empty() ? nullptr : tau.data();
    v.gradvel = gradvel.empty() ? nullptr : gradvel.data();
    v.keys = keys.data();
    v.perm = perm.data();
    return v;
}

namespace {

std::string cpuModelName() {
    std::ifstream f("/proc/cpuinfo");
    std::string line;
    while (std::getline(f, line))
        if (line.rfind("model name", 0) == 0) {
            const auto colon = line.find(':');
            if (colon != std::string::npos) return line.substr(colon + 2);
        }
    return "unknown CPU";
}

/// Reorders v[b, e) by perm (perm holds absolute indices inside [b, e)).
template <typename T>
void gatherRange(std::vector<T>& v, std::vector<T>& scratch, const std::vector<std::uint32_t>& perm,
                 std::uint32_t b, std::uint32_t e) {
    if (v.empty()) return;
    scratch.resize(v.size());
#pragma omp parallel for schedule(static)
    for (std::int64_t i = b; i < std::int64_t(e); ++i) scratch[i] = v[perm[i]];
    std::copy(scratch.begin() + b, scratch.begin() + e, v.begin() + b);
}

class CpuBackend final : public solver::Backend {
public:
    explicit CpuBackend(int threads) : threads_(threads > 0 ? threads : omp_get_max_threads()) {
        omp_set_num_threads(threads_);
    }
    std::string name() const override { return "cpu"; }
    std::string deviceName() const override { return cpuModelName(); }
    int threads() const override { return threads_; }

    void init(const solver::BackendSetup& s) override {
        setup_ = s;
        nbound_ = s.nbound;
        nfluid_ = s.nfluid;
        const std::size_t np = std::size_t(s.nbound) + s.nfluid;
        a_.id.resize(np);
        std::iota(a_.id.begin(), a_.id.end(), 0u);
        a_.pos = s.pos;
        a_.velrho = s.velrho;
        a_.excl.assign(np, physics::kActive);
        a_.poscell.resize(np);
        a_.press_ovrho.resize(np);
        a_.pos_pre = a_.pos;
        a_.velrho_pre = a_.velrho;
        a_.acear.assign(np, physics::Float4{0, 0, 0, 0});
        a_.visc.assign(np, 0.f);
        if (s.physics.visco == physics::Viscosity::LaminarSps) {
            a_.tau.assign(np, physics::SymTensor{0, 0, 0, 0, 0, 0});
            a_.gradvel.assign(np, physics::SymTensor{0, 0, 0, 0, 0, 0});
        }
        a_.keys.resize(np);
        a_.perm.resize(np);
        const std::size_t nc = std::size_t(s.grid.cellCount()) + 1;
        a_.cell_start_bound.assign(nc, 0);
        a_.cell_start_fluid.assign(nc, 0);
        moving_pos0_ = s.moving_pos0;
        moving_object_ = s.moving_object;
        if (!s.solid.empty()) solid_.init(s.solid, s.step);
        sortRange(0, nbound_, a_.cell_start_bound, true);
        boundNear();
        solid_.updateSlots(a_.id.data(), nbound_);
        bound_sorted_ = true;
    }

    void divide(bool keep_step_start) override {
        const bool pre = !setup_.symplectic || keep_step_start;
        if (setup_.nmoving > 0 || !solid_.empty() || !bound_sorted_) {
            sortRange(0, nbound_, a_.cell_start_bound, pre);
            boundNear();
            solid_.updateSlots(a_.id.data(), nbound_);
        }
        nfluid_ = sortRange(nbound_, nbound_ + nfluid_, a_.cell_start_fluid, pre) - nbound_;
        physics::ParticleView v = a_.view();
        const std::int64_t n = std::int64_t(nbound_) + nfluid_;
#pragma omp parallel for schedule(static)
        for (std::int64_t i = 0; i < n; ++i) physics::posCellAt(std::uint32_t(i), v, setup_.grid);
    }

    void applyMotion(const std::vector<physics::RigidMotionGpu>& motions) override {
        if (setup_.nmoving == 0) return;
        physics::ParticleView v = a_.view();
#pragma omp parallel for schedule(static)
        for (std::int64_t i = 0; i < std::int64_t(nbound_); ++i)
            physics::motionAt(std::uint32_t(i), v, setup_.first_moving, setup_.nmoving,
                              moving_pos0_.data(), moving_object_.data(), motions.data());
    }

    physics::DtMaxima computeForces() override {
        return cpuComputeForces(setup_.physics, a_, nbound_, nfluid_, setup_.fluid, setup_.grid);
    }

    void symplecticPredictor(double dt) override {
        physics::ParticleView v = a_.view();
        const std::int64_t n = std::int64_t(nbound_) + nfluid_;
#pragma omp parallel for schedule(static)
        for (std::int64_t i = 0; i < n; ++i)
            physics::symplecticPredictorAt(std::uint32_t(i), nbound_, v, dt, setup_.step);
    }
    void symplecticCorrector(double dt) override {
        physics::ParticleView v = a_.view();
        const std::int64_t n = std::int64_t(nbound_) + nfluid_;
#pragma omp parallel for schedule(static)
        for (std::int64_t i = 0; i < n; ++i)
            physics::symplecticCorrectorAt(std::uint32_t(i), nbound_, v, dt, setup_.step);
    }
    void verletStep(double dt, bool euler) override {
        physics::ParticleView v = a_.view();
        const std::int64_t n = std::int64_t(nbound_) + nfluid_;
#pragma omp parallel for schedule(static)
        for (std::int64_t i = 0; i < n; ++i)
            physics::verletAt(std::uint32_t(i), nbound_, v, dt, euler, setup_.step);
    }

    void solidHydroForces() override {
        if (!solid_.empty()) hydroForces(solid_.slots(), solid_.size(), solid_.fluidForce());
    }
    void solidSteps(double t0, double dt, int n, const std::vector<physics::RigidMotionGpu>& motions,
                    bool ledger) override {
        if (solid_.empty()) return;
        solid_.steps(t0, dt, n, motions);
        solid_.toBoundary(dt * n, ledger, a_.pos.data(), a_.velrho.data());
    }
    void solidSave() override { solid_.save(); }
    void solidRestore() override {
        if (solid_.empty()) return;
        solid_.restore();
        solid_.toBoundary(0.0, false, a_.pos.data(), a_.velrho.data());
    }

    void boundaryForces(std::vector<physics::Double3>& out) override {
        physics::ParticleView v = a_.view();
        const std::int64_t np = std::int64_t(nbound_) + nfluid_;
#pragma omp parallel for schedule(static)
        for (std::int64_t i = 0; i < np; ++i) physics::pressureAt(std::uint32_t(i), v, setup_.fluid);
        std::vector<physics::Double3> sorted(nbound_);
        hydroForces(nullptr, nbound_, sorted.data());
        out.resize(nbound_);
        for (std::uint32_t i = 0; i < nbound_; ++i) out[a_.id[i]] = sorted[i];
    }

    void setGauges(const solver::GaugeQueries& q) override {
        gauge_q_ = q;
        gauge_slot_ = solver::gaugeSlotsOfIds(q.ids, nbound_);
    }
    void gauges(solver::GaugeResults& out) override {
        cpuGauges(setup_.physics, a_, nbound_, gauge_q_, gauge_slot_, setup_.fluid, setup_.grid, out);
    }

    std::uint32_t activeFluid() const override { return nfluid_; }

    void download(solver::HostState& out) override {
        const std::size_t np = a_.id.size();
        out.pos.resize(np);
        out.velrho.resize(np);
        out.excl.resize(np);
        for (std::size_t i = 0; i < np; ++i) {
            const std::uint32_t id = a_.id[i];
            out.pos[id] = a_.pos[i];
            out.velrho[id] = a_.velrho[i];
            out.excl[id] = a_.excl[i];
        }
        if (!solid_.empty()) solid_.download(out);
    }

private:
    /// The hydrodynamic force on boundary particles slot[0..n) (null: the block [0, n)).
    void hydroForces(const std::uint32_t* slot, std::uint32_t n, physics::Double3* out) {
        if (setup_.physics.kernel == physics::KernelType::Wendland)
            cpuHydroForces_wendland(setup_.physics, a_, slot, n, out, setup_.fluid, setup_.grid);
        else
            cpuHydroForces_cubic(setup_.physics, a_, slot, n, out, setup_.fluid, setup_.grid);
    }

    /// The "near" flags of the block with cell ranges `cs` (physics::cellOccupiedAt and
    /// dilateCellsAt).
    void blockNear(const std::vector<std::uint32_t>& cs, std::vector<std::uint8_t>& near) {
        const std::int64_t nc = std::int64_t(setup_.grid.cellCount());
        near.resize(std::size_t(nc));
        near_tmp_.resize(std::size_t(nc));
        std::uint8_t* a = near.data();
        std::uint8_t* t = near_tmp_.data();
        const physics::CellGrid& g = setup_.grid;
#pragma omp parallel
        {
#pragma omp for schedule(static)
            for (std::int64_t c = 0; c < nc; ++c) physics::cellOccupiedAt(std::uint32_t(c), cs.data(), a);
#pragma omp for schedule(static)
            for (std::int64_t c = 0; c < nc; ++c) physics::dilateCellsAt(std::uint32_t(c), 0, g, a, t);
#pragma omp for schedule(static)
            for (std::int64_t c = 0; c < nc; ++c) physics::dilateCellsAt(std::uint32_t(c), 1, g, t, a);
#pragma omp for schedule(static)
            for (std::int64_t c = 0; c < nc; ++c) physics::dilateCellsAt(std::uint32_t(c), 2, g, a, t);
        }
        near.swap(near_tmp_);
    }
    void boundNear() { blockNear(a_.cell_start_bound, a_.bound_near); }

    /// Sorts [b, e) by (cell, id), excluded last; rebuilds `cell_start` for the active part.
    /// `pre`: reorder the step-start state too (Backend::divide). Returns the end of the
    /// active part.
    std::uint32_t sortRange(std::uint32_t b, std::uint32_t e, std::vector<std::uint32_t>& cell_start, bool pre) {
        physics::ParticleView v = a_.view();
#pragma omp parallel for schedule(static)
        for (std::int64_t i = b; i < std::int64_t(e); ++i) {
            a_.keys[i] = physics::sortKeyAt(std::uint32_t(i), v, setup_.grid);
            a_.perm[i] = std::uint32_t(i);
        }
        std::sort(a_.perm.begin() + b, a_.perm.begin() + e,
                  [&](std::uint32_t x, std::uint32_t y) { return a_.keys[x] < a_.keys[y]; });
        gatherRange(a_.keys, scratch_u64_, a_.perm, b, e);
        gatherRange(a_.id, scratch_u32_, a_.perm, b, e);
        gatherRange(a_.pos, scratch_d3_, a_.perm, b, e);
        gatherRange(a_.velrho, scratch_f4_, a_.perm, b, e);
        gatherRange(a_.excl, scratch_u8_, a_.perm, b, e);
        if (setup_.symplectic && pre) gatherRange(a_.pos_pre, scratch_d3_, a_.perm, b, e);
        if (pre) gatherRange(a_.velrho_pre, scratch_f4_, a_.perm, b, e);
        gatherRange(a_.tau, scratch_t_, a_.perm, b, e);
        // Active part: keys below the excluded marker.
        const std::uint64_t excluded_from = physics::kExcludedCell << 32;
        const std::uint32_t active_end =
            std::uint32_t(std::lower_bound(a_.keys.begin() + b, a_.keys.begin() + e, excluded_from) -
                          a_.keys.begin());
        const std::uint64_t* keys = a_.keys.data();
        std::uint32_t* cs = cell_start.data();
        const std::int64_t nc = std::int64_t(cell_start.size());
#pragma omp parallel for schedule(static)
        for (std::int64_t c = 0; c < nc; ++c) physics::cellStartOuterAt(std::uint32_t(c), b, active_end, keys, cs);
#pragma omp parallel for schedule(static)
        for (std::int64_t k = b; k < std::int64_t(active_end); ++k)
            physics::cellStartFillAt(std::uint32_t(k), b, keys, cs);
        return active_end;
    }

    int threads_;
    solver::BackendSetup setup_;
    std::uint32_t nbound_ = 0, nfluid_ = 0;
    bool bound_sorted_ = false;
    CpuArrays a_;
    CpuSolid solid_;
    std::vector<physics::Double3> moving_pos0_;
    std::vector<std::uint16_t> moving_object_;
    std::vector<std::uint64_t> scratch_u64_;
    std::vector<std::uint32_t> scratch_u32_;
    std::vector<physics::Double3> scratch_d3_;
    std::vector<physics::Float4> scratch_f4_;
    std::vector<std::uint8_t> scratch_u8_, near_tmp_;
    std::vector<physics::SymTensor> scratch_t_;
    solver::GaugeQueries gauge_q_;
    std::vector<std::uint32_t> gauge_slot_;
};

}  // namespace

}  // namespace seaspring::cpu

namespace seaspring::solver {
std::unique_ptr<Backend> makeCpuBackend(int threads) {
    return std::make_unique<cpu::CpuBackend>(threads);
}
}  // namespace seaspring::solver
