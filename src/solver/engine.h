// SeaSpring — MIT licence.
/// \file engine.h
/// \brief The one implementation of Backend: the particle arrays (field table), the divide,
///        the force evaluation, the integration, the VCPM solids and the gauges, written once as
///        passes (particle_passes.h, force_passes.h, solid_passes.h) over an execution policy
///        `Exec`: cpu::HostExec (OpenMP loops, host memory) or cuda::CudaExec (kernel launches,
///        device memory). An Exec provides Buffer<T>, forEach<Launch>(b, e, pass),
///        forEachIndependent (two passes that may overlap), reduce(b, e, init, value, combine),
///        sequence(work, widest, body), the sort's steps (stayersFirst, sortPairs, mergePairs,
///        lowerBound: particle_sort.h), copy and synchronize; everything else is here, so both backends run the
///        same passes in the same order and give the same bits.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/error.h"
#include "solver/backend.h"
#include "solver/force_passes.h"
#include "solver/gauge_arrays.h"
#include "solver/launch.h"
#include "solver/particle_passes.h"
#include "solver/particle_sort.h"
#include "solver/row_extents_cache.h"
#include "solver/particle_store.h"
#include "solver/solid_arrays.h"
#include "solver/solid_cycle.h"
#include "solver/solid_passes.h"

namespace seaspring::solver {

template <class Exec>
class Engine final : public Backend {
    template <typename T>
    using Buf = typename Exec::template Buffer<T>;

public:
    explicit Engine(Exec exec) : exec_(std::move(exec)) {}
    std::string name() const override { return exec_.name(); }
    std::string deviceName() const override { return exec_.deviceName(); }
    int threads() const override { return exec_.threads(); }
    int hostThreads() const override { return exec_.hostThreads(); }
    DeviceMemoryUse deviceMemory() const override { return exec_.deviceMemory(); }

    void init(const BackendSetup& s) override {
        if (s.pair_lanes == 0 || s.pair_lanes > physics::kMaxPairLanes || (s.pair_lanes & (s.pair_lanes - 1u)) != 0)
            throw std::invalid_argument("Engine::init: " + std::to_string(s.pair_lanes) +
                                        " pair lanes (a power of two up to " +
                                        std::to_string(physics::kMaxPairLanes) + ")");
        if (std::uint64_t(s.nfluid) * s.pair_lanes > 0xffffffffull)
            throw Error(std::to_string(s.nfluid) + " fluid particles x " + std::to_string(s.pair_lanes) +
                        " pair lanes exceed 2^32 GPU threads: run with fewer -pairlanes");
        dropForcesAhead();
        setup_ = s;
        sorted_ = false;
        removed_ = 0u;
        counts_ = DivideCounts{};
        nbound_ = s.nbound;
        nfluid_ = s.nfluid;
        const std::size_t np = std::size_t(s.nbound) + s.nfluid;
        const bool sps = s.physics.visco == physics::Viscosity::LaminarSps;
        p_.forEachField([&](auto& buf, unsigned, physics::FieldNeed need) {
            using T = std::remove_pointer_t<decltype(buf.data())>;
            if (physics::fieldNeeded(need, sps)) fillZero(buf, np);
            else buf = Buf<T>();
        });
        std::vector<std::uint32_t> ids(np);
        std::iota(ids.begin(), ids.end(), 0u);
        assignFrom(p_.id, ids);
        assignFrom(p_.pos, s.pos);
        assignFrom(p_.velrho, s.velrho);
        assignFrom(p_.excl, std::vector<std::uint8_t>(np, physics::kActive));
        assignFrom(p_.velrho_pre, s.velrho);
        grid_initial_ = s.grid;
        useCells(false);
        assignFrom(moving_pos0_, s.moving_pos0);
        assignFrom(moving_object_, s.moving_object);
        motions_.resize(s.motion_objects > 0 ? s.motion_objects : 1);
        exec_.prepareSort(np);
        sort_merge_min_ = sortMergeMinFromEnv();
        if (!s.solid.empty()) solid_.init(s.solid);
        if (s.mdbc.enabled) {
            assignFrom(mdbc_normal0_, s.mdbc.normal0);
            if (s.mdbc.slip != physics::SlipMode::Vel0)
                assignFrom(mdbc_visc_vel_, std::vector<physics::Float4>(nbound_ > 0 ? nbound_ : 1, physics::Float4{0, 0, 0, 0}));
            if (solid_.n > 0) assignFrom(mdbc_solid_pos0_, s.solid.pos);
        }
        sortRange(0, nbound_, cs_bound_, true);
        nearFlags(cs_bound_, physics::kNearBound);
        updateSolidSlots();
    }

    void divide(bool keep_step_start) override {
        noForcesAhead("divide");
        ++counts_.divides;
        if (!refreshes()) {
            sortBlocks(keep_step_start, kSortFluidBlock | kSortBoundaryBlock);
            return;
        }
        const RefreshVerdict verdict =
            exec_.reduce(refreshBegin(), nbound_ + nfluid_, RefreshVerdict{}, refreshPass(), RefreshCombine{});
        removed_ = verdict.removed;
        if (verdict.sort != 0u) sortBlocks(keep_step_start, verdict.sort);
    }

    void divideThenForces(bool keep_step_start) override {
        noForcesAhead("divideThenForces");
        ++counts_.divides;
        const bool gated = refreshes();
        if (gated) {  // the verdict stays on the device: it gates the evaluation's passes
            exec_.reduceDeferred(refreshBegin(), nbound_ + nfluid_, RefreshVerdict{}, refreshPass(), RefreshCombine{},
                                 refresh_);
            exec_.gate(&refresh_.device()->sort);
        } else {
            sortBlocks(keep_step_start, kSortFluidBlock | kSortBoundaryBlock);
        }
        evaluateForces(true);
        exec_.gate(nullptr);
        ahead_ = ForcesAhead{true, gated, keep_step_start};
    }
    bool forcesAhead() const override { return ahead_.on; }

    void applyMotion(const std::vector<physics::RigidMotionGpu>& motions) override {
        noForcesAhead("applyMotion");
        if (setup_.nmoving == 0 || nbound_ == 0) return;
        assignFrom(motions_, motions);
        exec_.template forEach<LaunchDefault>(0u, nbound_,
                                              MotionPass{p_.view(), setup_.first_moving, setup_.nmoving,
                                                         moving_pos0_.data(), moving_object_.data(), motions_.data()});
    }

    physics::DtMaxima computeForces() override {
        settleDivide();  // a sort drops the evaluation launched ahead (it did nothing)
        if (ahead_.on) {
            ahead_.on = false;
            return dt_ahead_.get();
        }
        return evaluateForces(false);
    }

    void symplecticPredictor(double dt) override {
        noForcesAhead("symplecticPredictor");
        exec_.template forEach<LaunchDefault>(0u, nbound_ + nfluid_, PredictorPass{nbound_, p_.view(), dt, setup_.step});
    }
    void symplecticCorrector(double dt) override {
        noForcesAhead("symplecticCorrector");
        exec_.template forEach<LaunchDefault>(0u, nbound_ + nfluid_, CorrectorPass{nbound_, p_.view(), dt, setup_.step});
    }
    void verletStep(double dt, bool euler) override {
        noForcesAhead("verletStep");
        exec_.template forEach<LaunchDefault>(0u, nbound_ + nfluid_,
                                              VerletPass{nbound_, p_.view(), dt, euler, setup_.step});
    }

    void solidSteps(double t0, double dt, int n, const std::vector<physics::RigidMotionGpu>& motions,
                    bool ledger) override {
        noForcesAhead("solidSteps");
        if (solid_.n == 0) return;
        if (n > 0)  // it ends with solidToBoundary's pass (and, with the ledger, the end checks)
            runSolidSubCycle(exec_, solid_, solid_motions_, solidViews(), t0, dt, n, motions, ledger);
        else solidToBoundary(0.0, ledger);
        solid_end_checked_ = n > 0 && ledger;
    }
    std::uint32_t solidsPastBounds() override {
        if (solid_.n == 0) return 0;
        if (!solid_check_started_) startSolidsCheck();
        solid_check_started_ = false;
        return solid_check_.get();
    }
    void startSolidsCheck() override {
        if (solid_.n == 0) return;
        exec_.reduceDeferred(0u, solid_.n, 0u,
                             SolidAlarmPass{solid_.state(), solid_.bonds(), solid_.clamps(),
                                            solidContactViews(solid_, solidViews()), solid_end_checked_},
                             CountCombine{}, solid_check_);
        solid_check_started_ = true;
        solid_end_checked_ = false;
    }
    double solidMaxSpeed() override {
        if (solid_.n == 0) return 0.0;
        return exec_.reduce(0u, solid_.n, 0.0, SolidSpeedPass{solid_.vel.data()}, MaxCombine{});
    }
    void solidSave() override {
        noForcesAhead("solidSave");
        if (solid_.n == 0) return;
        exec_.template forEach<LaunchDefault>(0u, solid_.snapshotRange(), solid_.savePass());
    }
    void solidRestore() override {  // the saved state, and on into the boundary block, in one pass
        noForcesAhead("solidRestore");
        if (solid_.n == 0) return;
        const SolidToBoundaryPass boundary = solidToBoundaryPass(solid_, solidViews(), 0.0, false);
        exec_.template forEach<LaunchDefault>(0u, solid_.snapshotRange(), solid_.restorePass(boundary));
        solid_end_checked_ = false;  // other positions: the check, when asked, runs in full
    }

    void boundaryForces(std::vector<physics::Double3>& out) override {
        settleDivide();
        out.assign(nbound_, physics::Double3{0, 0, 0});
        if (nbound_ == 0) return;
        // With mDBC the boundary particles take their ghost nodes' values for this, as in a force
        // evaluation, and get their state back afterwards: an output does not change the run.
        Buf<physics::Float4> saved;
        if (setup_.mdbc.enabled) {
            saved.resize(nbound_);
            exec_.copy(saved.data(), p_.velrho.data(), nbound_);
        }
        pressures(forceArgs());
        Buf<physics::Double3> force;  // output times only
        force.resize(nbound_);
        hydroForces(nullptr, nbound_, force.data());
        if (setup_.mdbc.enabled) exec_.copy(p_.velrho.data(), saved.data(), nbound_);
        std::vector<physics::Double3> sorted;
        std::vector<std::uint32_t> ids;
        copyToHost(force, sorted);
        copyToHost(p_.id, ids);
        for (std::uint32_t i = 0; i < nbound_; ++i) out[ids[i]] = sorted[i];
    }

    void setGauges(const GaugeQueries& q) override { gauges_.set(q, nbound_, setup_.grid, setup_.physics.dim); }
    void gauges(GaugeResults& out) override {
        settleDivide();
        gauges_.answer(exec_, setup_, cs_fluid_.data(), p_.view(), nbound_, out);
    }

    DivideCounts divideCounts() const override { return counts_; }
    std::uint32_t activeFluid() override {
        settleDivide();
        return nfluid_ - removed_;  // less those removed in their slots since the last sort
    }
    std::uint32_t notFiniteCount() override {
        noForcesAhead("notFiniteCount");
        const std::uint32_t n = std::uint32_t(p_.pos.size());
        if (n == 0) return 0;
        return exec_.reduce(0u, n, 0u, NotFiniteCountPass{p_.pos.data(), p_.velrho.data(), p_.excl.data()},
                            CountCombine{});
    }
    void downloadSolidPositions(std::vector<physics::Double3>& out) override {
        noForcesAhead("downloadSolidPositions");
        out.clear();
        if (solid_.n > 0) copyToHost(solid_.pos, out);
    }
    void synchronize() override { exec_.synchronize(); }

    void download(HostState& out) override {
        downloadIdOrder(out, physics::kHost | physics::kHashed, 0u);
        if (solid_.n > 0) solid_.download(out);
    }
    void downloadFields(HostParticles& out) override { downloadIdOrder(out, ~0u, 0u); }

    /// Restart files (engine_checkpoint.h): every state array by name (forEachStateArray), the
    /// counters and the sizes they must match.
    void saveState(CheckpointData& out) override;
    void loadState(const CheckpointData& in) override;

private:
    /// Whether a divide may only refresh PosCell (a skin, and sorted once).
    bool refreshes() const { return sorted_ && setup_.grid.skinf > 0.f; }
    /// Only moving boundaries and solids move in the boundary block.
    std::uint32_t refreshBegin() const { return setup_.nmoving > 0 || solid_.n > 0 ? 0u : nbound_; }

    /// The divide's skin test (refreshPosCellAt over the blocks whose particles move).
    RefreshPosCellPass refreshPass() { return RefreshPosCellPass{p_.view(), setup_.grid, nbound_}; }

    /// The sort of a divide (see Backend::divide): the blocks in `blocks` (kSortFluidBlock,
    /// kSortBoundaryBlock), those a particle has left its grown cell in. A block left unsorted
    /// keeps the cells and order of its last sort and the PosCell its skin test refreshed: its
    /// particles are all still within the skin of those cells.
    void sortBlocks(bool keep_step_start, std::uint32_t blocks) {
        ++counts_.sorts;
        sorted_ = true;
        const bool pre = !setup_.symplectic || keep_step_start;
        // Moving boundaries and solid particles move inside the boundary block: re-sort it, and
        // find the solid particles again. Fixed walls stay as init sorted them.
        const bool movers = setup_.nmoving > 0 || solid_.n > 0;
        const bool bound = (blocks & kSortBoundaryBlock) && movers;
        if (bound) {
            ++counts_.boundary_sorts;
            sortRange(0, nbound_, cs_bound_, pre);
            nearFlags(cs_bound_, physics::kNearBound);
            updateSolidSlots();
        }
        const bool fluid = (blocks & kSortFluidBlock) != 0u;
        if (fluid) {
            nfluid_ = sortRange(nbound_, nbound_ + nfluid_, cs_fluid_, pre) - nbound_;
            removed_ = 0u;  // dropped after the active end
            nearFlags(cs_fluid_, physics::kNearFluid);
        }
        // PosCell from the new cells in the sorted blocks; fixed walls get theirs again (the same
        // values); an unsorted block of moving particles keeps what its skin test refreshed.
        const std::uint32_t b = movers && !bound ? nbound_ : 0u, e = fluid ? nbound_ + nfluid_ : nbound_;
        if (e > b) exec_.template forEach<LaunchDefault>(b, e, PosCellPass{p_.view(), setup_.grid});
        if (fluid) switchCellsIfDue(pre);
    }

    /// The cells' switch (BackendSetup::cell_switch, solver/cell_switch.h): after a sort of the
    /// fluid block in the run's first cells, the fluid particles that share their cell with
    /// another are counted (an integer sum: the same on every backend); above the switch's
    /// fraction of the active fluid, both blocks are sorted into the cells of h (the fixed walls
    /// too), their PosCells, cell ranges, near flags, row extents and the gauges' cells follow.
    void switchCellsIfDue(bool pre) {
        const CellSwitch& sw = setup_.cell_switch;
        if (!sw.on || cells_switched_ || nfluid_ == 0u) return;
        const std::uint32_t shared = exec_.reduce(nbound_, nbound_ + nfluid_, 0u,
                                                  SharedCellCountPass{p_.poscell.data(), cs_fluid_.data(), setup_.grid},
                                                  CountCombine{});
        if (!(double(shared) > sw.fraction * double(nfluid_))) return;
        counts_.cell_switch_divide = counts_.divides;
        counts_.cell_switch_shared = shared;
        counts_.cell_switch_fluid = nfluid_;
        useCells(true);
        sortRange(0, nbound_, cs_bound_, pre);
        nearFlags(cs_bound_, physics::kNearBound);
        updateSolidSlots();
        nfluid_ = sortRange(nbound_, nbound_ + nfluid_, cs_fluid_, pre) - nbound_;
        removed_ = 0u;
        nearFlags(cs_fluid_, physics::kNearFluid);
        exec_.template forEach<LaunchDefault>(0u, nbound_ + nfluid_, PosCellPass{p_.view(), setup_.grid});
    }
    /// The run's first cells, or (`switched`) the switch's: the grid and the memory sized by it
    /// (cell ranges, near flags; the row extents and the gauges' cells again at their next use).
    void useCells(bool switched) {
        cells_switched_ = switched;
        setup_.grid = switched ? setup_.cell_switch.grid : grid_initial_;
        const std::size_t nc = std::size_t(setup_.grid.cellCount());
        cs_bound_.resize(nc + 1);
        cs_fluid_.resize(nc + 1);
        assignFrom(near_, std::vector<std::uint8_t>(nc, 0));
        near_tmp_.resize(nc);
        row_ext_.bound_done = false;
        gauges_.regrid(setup_.grid);
    }

    /// A force evaluation launched by divideThenForces, not yet taken by computeForces. `gated`:
    /// the divide's verdict (sort or not) is still on the device, and a sort makes the
    /// evaluation's passes do nothing.
    struct ForcesAhead {
        bool on = false, gated = false, keep = false;
    };

    /// Before reading the particles between two steps: a divide whose verdict is still out
    /// is completed. With no sort the forces launched ahead stand; with a sort they did
    /// nothing (gated), and computeForces evaluates them again.
    void settleDivide() {
        if (!ahead_.on || !ahead_.gated) return;
        ahead_.gated = false;
        const RefreshVerdict verdict = refresh_.get();
        removed_ = verdict.removed;
        if (verdict.sort == 0u) return;
        ahead_.on = false;
        sortBlocks(ahead_.keep, verdict.sort);
    }
    /// What changes the state cannot run between divideThenForces and computeForces (the
    /// evaluation launched ahead would be stale, and the SPS stress, mDBC's boundary values and
    /// the solids' hydrodynamic force it wrote could not be taken back).
    void noForcesAhead(const char* what) const {
        if (ahead_.on)
            throw std::logic_error(std::string("Engine::") + what +
                                   " called between divideThenForces and computeForces");
    }
    /// init, loadState: whatever was launched ahead is finished and forgotten.
    void dropForcesAhead() {
        if (ahead_.on) exec_.synchronize();
        ahead_ = ForcesAhead{};
    }

    /// The pressures, the pair loops and the dt maxima (with SPS, the stress for the next
    /// evaluation, which DualSPHysics lags by one evaluation, in the dt reduction's launch);
    /// `ahead`: the maxima go to dt_ahead_ without waiting (divideThenForces).
    physics::DtMaxima evaluateForces(bool ahead) {
        ForceArgs a = forceArgs();
        if (solid_.n > 0) {  // the hydrodynamic force on the solids, in the boundary loop's launch
            a.hydro_slot = solid_.slot.data();
            a.nhydro = solid_.n;
            a.hydro_out = solid_.fluid_force.data();
        }
        const physics::FluidConstants& c = setup_.fluid;
        const physics::RowExtents ext = row_ext_.update(exec_, setup_.grid, cs_fluid_.data(), cs_bound_.data(),
                                                        p_.poscell.data(), setup_.nmoving > 0 || solid_.n > 0);
        (Exec::kCompactPairs ? a.in.row_ext : a.in.bound_ext) = ext;  // the host's row tables; the GPU's boundary walk
        a.in.fluid_ext = row_ext_.fluidExtents(setup_.grid);  // the GPU's; filled in the pressures' launch
        pressures(a, true);
        dispatchKernelDim(setup_.physics, [&](auto kernel, auto dim) {
            ForcePasses<Exec, decltype(kernel), decltype(dim)::value>::pairs(exec_, setup_.physics, a);
        });
        auto maxima = [&](const auto& pass) {
            if (!ahead) return exec_.reduce(0u, a.np, physics::DtMaxima{}, pass, DtMaximaCombine{});
            exec_.reduceDeferred(0u, a.np, physics::DtMaxima{}, pass, DtMaximaCombine{}, dt_ahead_);
            return physics::DtMaxima{};
        };
        if (setup_.physics.visco == physics::Viscosity::LaminarSps)
            return maxima(DtMaximaPass<true>{a.nbound, a.v, c.dt_all_particles != 0, c.sps_smag, c.sps_blin});
        return maxima(DtMaximaPass<false>{a.nbound, a.v, c.dt_all_particles != 0});
    }

    /// Every array of a restart file, by name, and whether its size is the run's (the one list
    /// saveState and loadState go through).
    template <class F>
    void forEachStateArray(F&& f) {
        p_.forEachNamedField([&](const char* name, auto& buf, unsigned flags) {
            if ((flags & physics::kCheckpoint) && !buf.empty()) f(std::string("field/") + name, buf, true);
        });
        f("cell_start_bound", cs_bound_, true);
        f("cell_start_fluid", cs_fluid_, true);
        f("near", near_, true);
        f("motions", motions_, false);
        if (solid_.n > 0) {
            f("solid_motions", solid_motions_, false);
            solid_.forEachState([&](const char* name, auto& buf) { f(std::string("solid/") + name, buf, true); });
        }
    }

    /// The fields with a flag in `any` (every field for ~0u) and none in `none`, in id order
    /// (downloadInIdOrder, through the staging buffers the engine keeps).
    void downloadIdOrder(HostParticles& out, unsigned any, unsigned none) {
        exec_.synchronize();
        downloadInIdOrder(p_, ids_host_, stage_, out, any, none, exec_.hostThreads());
    }

    ForceArgs forceArgs() {
        ForceArgs a;
        a.v = p_.view();
        a.in.poscell = a.v.poscell;
        a.in.velrho = a.v.velrho;
        a.in.cell_start_bound = cs_bound_.data();
        a.in.cell_start_fluid = cs_fluid_.data();
        a.in.tau = a.v.tau;  // null without SPS
        a.in.press_ovrho = a.v.press_ovrho;
        a.in.near = near_.data();
        a.in.bound_visc_vel = mdbc_visc_vel_.empty() ? nullptr : mdbc_visc_vel_.data();
        a.c = setup_.fluid;
        a.g = setup_.grid;
        a.nbound = nbound_;
        a.np = nbound_ + nfluid_;
        a.lanes = setup_.pair_lanes;
        while ((1u << a.lane_shift) < a.lanes) ++a.lane_shift;
        return a;
    }

    /// The pressure pass; with mDBC, in the same launch, the boundary particles' densities (and
    /// velocities) from their ghost nodes first. `fluid_extents` (a force evaluation): the GPU's
    /// fluid-block row extents too (RowExtentsCache::fluidPass; without mDBC in the same launch,
    /// which spares the small cases a launch: FlexStruc Liao 2D and the Antoci gate lost 4–6%
    /// with a launch of its own).
    void pressures(const ForceArgs& a, bool fluid_extents = false) {
        const std::uint32_t ext_items = fluid_extents ? row_ext_.fluidItems(setup_.grid) : 0u;
        const RowExtentsPass ext = row_ext_.fluidPass(setup_.grid, cs_fluid_.data(), p_.poscell.data());
        if (!setup_.mdbc.enabled) {
            if constexpr (!Exec::kCompactPairs) {  // (the host has no items)
                if (ext_items > 0u) {
                    exec_.template forEachIndependent<LaunchDefault, LaunchRowLanes>(
                        0u, a.np, PressurePass{a.v, setup_.fluid}, 0u, ext_items, ext);
                    return;
                }
            }
            exec_.template forEach<LaunchDefault>(0u, a.np, PressurePass{a.v, setup_.fluid});
            return;
        }
        if (ext_items > 0u) exec_.template forEach<LaunchRowLanes>(0u, ext_items, ext);
        physics::MdbcInputs in;
        in.normal0 = mdbc_normal0_.data();
        in.visc_vel = mdbc_visc_vel_.empty() ? nullptr : mdbc_visc_vel_.data();
        in.first_moving = setup_.first_moving;
        in.nmoving = setup_.nmoving;
        in.moving_pos0 = moving_pos0_.data();
        in.moving_object = moving_object_.data();
        in.motions = motions_.data();
        in.cell_start_fluid = cs_fluid_.data();
        in.near = near_.data();
        if (solid_.n > 0) {
            in.first_solid = solid_.first;
            in.nsolid = solid_.n;
            in.solid_pos = solid_.pos.data();
            in.solid_pos0 = mdbc_solid_pos0_.data();
            in.solid_vel = solid_.vel.data();
            in.bonds = solid_.bonds();
        }
        dispatchKernelDim(setup_.physics, [&](auto kernel, auto dim) {
            ForcePasses<Exec, decltype(kernel), decltype(dim)::value>::mdbcAndPressure(exec_, setup_.mdbc.slip, a, in,
                                                                           setup_.mdbc.constants);
        });
    }

    /// The hydrodynamic force on boundary particles slot[0..n) (null: the block [0, n)).
    void hydroForces(const std::uint32_t* slot, std::uint32_t n, physics::Double3* out) {
        const ForceArgs a = forceArgs();
        dispatchKernelDim(setup_.physics, [&](auto kernel, auto dim) {
            ForcePasses<Exec, decltype(kernel), decltype(dim)::value>::hydro(exec_, setup_.physics, a, slot, n, out);
        });
    }

    /// See solver/particle_sort.h.
    std::uint32_t sortRange(std::uint32_t b, std::uint32_t e, Buf<std::uint32_t>& cs, bool pre) {
        bool merged = false;
        const std::uint32_t end = sortBlockRange(exec_, p_, setup_.grid, b, e, cs, pre, sort_merge_min_, &merged);
        counts_.merged_sorts += merged ? 1u : 0u;
        return end;
    }
    void nearFlags(const Buf<std::uint32_t>& cs, std::uint8_t bit) {
        nearFlagsOfBlock(exec_, setup_.grid, cs, bit, near_, near_tmp_);
    }

    /// slot[s] = sorted index of solid particle s.
    void updateSolidSlots() {
        if (solid_.n == 0) return;
        exec_.template forEach<LaunchDefault>(0u, nbound_,
                                              SolidSlotPass{p_.id.data(), solid_.first, solid_.n, solid_.slot.data()});
    }

    /// The boundary block and the set-up as the solids' sub-cycle sees them (solid_cycle.h).
    SolidBlockViews solidViews() {
        return SolidBlockViews{cs_bound_.data(), p_.id.data(), p_.pos.data(), p_.velrho.data(), setup_.grid,
                               setup_.step.gx, setup_.step.gy, setup_.step.gz};
    }
    void solidToBoundary(double dt, bool ledger) {
        exec_.template forEach<LaunchDefault>(0u, solid_.n, solidToBoundaryPass(solid_, solidViews(), dt, ledger));
    }

    Exec exec_;
    typename Exec::template Deferred<std::uint32_t> solid_check_;  ///< startSolidsCheck's result
    typename Exec::template Deferred<RefreshVerdict> refresh_;     ///< divideThenForces' verdict
    std::uint32_t removed_ = 0;  ///< fluid particles removed in their slots since the last sort
    typename Exec::template Deferred<physics::DtMaxima> dt_ahead_;  ///< divideThenForces' dt maxima
    ForcesAhead ahead_;
    bool solid_check_started_ = false;
    /// The last sub-cycle ran the per-step test's checks at the current positions (SolidEndPass):
    /// startSolidsCheck then only counts the alarms.
    bool solid_end_checked_ = false;
    BackendConfig setup_;  // sliced: the initial state is uploaded, not kept
    std::uint32_t nbound_ = 0, nfluid_ = 0;
    std::uint32_t sort_merge_min_ = kMergeMinParticles;  ///< sortBlockRange merges from this block size
    bool sorted_ = false;  ///< the fluid block was sorted once (divide)
    bool cells_switched_ = false;     ///< the grid is BackendSetup::cell_switch's (useCells)
    physics::CellGrid grid_initial_;  ///< the run's first grid (init's)
    DivideCounts counts_;
    ParticleStore<Exec::template Buffer> p_;
    Buf<std::uint32_t> cs_bound_, cs_fluid_;
    Buf<std::uint8_t> near_, near_tmp_;  ///< per-cell near flags (physics::kNearBound, kNearFluid), scratch
    RowExtentsCache<Exec> row_ext_;      ///< the rows' extents (solver/row_extents_cache.h)
    std::vector<std::uint32_t> ids_host_;  ///< downloadIdOrder: the ids in sorted order
    std::vector<unsigned char> stage_;     ///< downloadIdOrder: one field in sorted order
    Buf<physics::Double3> moving_pos0_;
    Buf<physics::Float4> mdbc_normal0_;      ///< mDBC only: per boundary id
    Buf<physics::Float4> mdbc_visc_vel_;     ///< mDBC SlipMode 2/3: per boundary particle (sorted), the viscous velocity
    Buf<physics::Double3> mdbc_solid_pos0_;  ///< mDBC with solids: their initial positions
    Buf<std::uint16_t> moving_object_;
    Buf<physics::RigidMotionGpu> motions_, solid_motions_;
    SolidArrays<Exec::template Buffer> solid_;
    GaugeArrays<Exec::template Buffer> gauges_;
};

}  // namespace seaspring::solver

#include "solver/engine_checkpoint.h"
