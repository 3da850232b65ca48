// SeaSpring — MIT licence.
/// \file backend.h
/// \brief What a compute backend (OpenMP CPU, CUDA GPU) does for the time loop, and the data it
///        is set up with. Backends hold the particle arrays in cell-sorted order; the time loop
///        (simulation.h) only sees this interface.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/checkpoint_data.h"
#include "core/device_info.h"
#include "physics/cell_grid.h"
#include "physics/fluid_constants.h"
#include "physics/gauges.h"
#include "physics/blowup_bounds.h"
#include "physics/mdbc.h"
#include "physics/particle_updates.h"
#include "physics/time_integration.h"
#include "solver/particle_store.h"
#include "solver/solid_setup.h"

namespace seaspring::solver {

/// The options that select the compile-time specialisations of the pair loops (force_passes.h).
struct PhysicsChoice {
    physics::KernelType kernel = physics::KernelType::Wendland;
    physics::Viscosity visco = physics::Viscosity::Artificial;
    physics::DensityDiffusion ddt = physics::DensityDiffusion::None;
    int dim = 3;
};

/// mDBC (Boundary = 2; physics/mdbc.h).
struct MdbcSetup {
    bool enabled = false;
    physics::SlipMode slip = physics::SlipMode::Vel0;
    physics::MdbcConstants constants;
    std::vector<physics::Float4> normal0;  ///< nbound, by id: the ghost vector at t = 0 (0: DBC)
    std::uint32_t with_normal = 0;         ///< particles with a ghost vector
};

/// The switch of a 3D run's cells of one particle spacing, centred on the fluid's lattice, to
/// cells of h once its fluid has left that lattice (solver/cell_switch.h): at the first fluid
/// sort after which more than `fraction` of the active fluid shares its cell with another fluid
/// particle (physics::sharesItsCell), the engine takes `grid` and sorts both blocks into it. The rule
/// reads the state only (an integer count of the sorted PosCells), so every backend and thread
/// count switches at the same divide.
struct CellSwitch {
    bool on = false;
    double fraction = 1.0;
    physics::CellGrid grid;  ///< the cells of h (the run's skin in its cells)
};

/// What a backend keeps of its set-up: everything but the initial particle state, which
/// Backend::init uploads (40 bytes per particle of host memory no backend holds after it; the
/// engine keeps a BackendConfig, sliced from the BackendSetup it is given). Particles in id
/// order: [0, nbound) boundary (fixed, moving, then VCPM solid particles, which the fluid sees
/// as DBC boundary particles), then fluid.
struct BackendConfig {
    PhysicsChoice physics;
    physics::FluidConstants fluid;
    physics::CellGrid grid;
    bool grid_centred = false;  ///< its origin centres the fluid's lattice (solver/grid_origin.h)
    physics::StepConstants step;
    physics::SpsConstants sps;
    bool symplectic = true;
    std::uint32_t nbound = 0, nfluid = 0;
    std::uint32_t first_moving = 0, nmoving = 0;  ///< moving boundary ids
    std::vector<physics::Double3> moving_pos0;    ///< nmoving: initial positions
    std::vector<std::uint16_t> moving_object;     ///< nmoving: index into the motions array
    std::uint32_t motion_objects = 0;
    SolidSetup solid;                             ///< VCPM solids (empty when none)
    /// Pair lanes of the fluid loop (physics/fluid_interaction.h; resolvePairLanes): a power of
    /// two <= physics::kMaxPairLanes.
    std::uint32_t pair_lanes = 1;
    MdbcSetup mdbc;                               ///< mDBC (disabled: DBC)
    CellSwitch cell_switch;                       ///< cells of h once the fluid is disordered (off: never)
};

/// The initial data a backend is set up from: its configuration and the particles' initial
/// state (id order).
struct BackendSetup : BackendConfig {
    std::vector<physics::Double3> pos;            ///< np
    std::vector<physics::Float4> velrho;          ///< np
};

/// State copied back to the host, in id order: the particle fields flagged physics::kHost or
/// kHashed (particle_store.h; pos, velrho, excl), and the solids.
struct HostState : HostParticles {
    // VCPM solids (empty when the case has none), solid-index order.
    std::vector<physics::Double3> solid_vel;     ///< double-precision velocity
    std::vector<physics::Double3> solid_force;   ///< last hydrodynamic force F_F->S [N]
    std::vector<std::uint8_t> bond_broken;       ///< per bond slot (SolidSetup layout)
    std::vector<physics::Double3> solid_impulse; ///< ledger: time integral of solid_force [N s]
    std::vector<double> solid_work;              ///< ledger: work of solid_force on the solid [J]
    std::vector<physics::SolidAlarm> solid_alarm;///< blow-up bound each passed first (kind 0: none)
    std::vector<physics::Double3> contact_impulse;///< ledger: time integral of the contact force [N s] (empty without contact)
    std::vector<double> contact_work;            ///< ledger: work of the contact force on the solid [J]
};

/// The search column of a maxz gauge: the fluid cells of the box [lo, hi] (clamped to the grid,
/// grown by one cell with a skin), searched for the highest particle within sqrt(r2) of the
/// vertical line through (lx, ly) (2D: x only).
struct MaxzColumn {
    physics::Double3 lo, hi;
    double lx = 0, ly = 0, r2 = 0;
};

/// What the gauges measure (solver/gauge_system.h), set once per run: gauge points do not move.
/// Given as positions, which the backend places on its cell grid (gauge_arrays.h: again when
/// its cells change, CellSwitch).
struct GaugeQueries {
    std::vector<physics::Double3> points;      ///< kernel-sum points (2D: on the particles' plane)
    std::vector<MaxzColumn> columns;           ///< the maxz gauges' columns
    std::vector<std::uint32_t> ids;            ///< boundary or solid particles whose position is wanted
};
/// Their answers for the current state, in query order.
struct GaugeResults {
    std::vector<physics::GaugeSample> samples;
    std::vector<double> maxz;                  ///< per column
    std::vector<physics::Double3> positions;
};

/// For each boundary id [0, nbound), its index in `ids` (physics::kNoGaugeSlot when no gauge
/// asks for it): the map both backends' gaugePositionAt reads.
inline std::vector<std::uint32_t> gaugeSlotsOfIds(const std::vector<std::uint32_t>& ids, std::uint32_t nbound) {
    std::vector<std::uint32_t> slot(nbound, physics::kNoGaugeSlot);
    for (std::size_t k = 0; k < ids.size(); ++k)
        if (ids[k] < nbound) slot[ids[k]] = std::uint32_t(k);
    return slot;
}

/// The time loop's view of a backend. One implementation, solver::Engine<Exec> (engine.h), over
/// an execution policy: cpu::HostExec (OpenMP) or cuda::CudaExec.
/// Backend::divideCounts.
struct DivideCounts {
    std::uint64_t divides = 0, sorts = 0;
    /// Sorts of the boundary block (cases with moving boundaries or solids; with a skin, only the
    /// divides at which one of its particles left its grown cell).
    std::uint64_t boundary_sorts = 0;
    /// Block sorts that kept the stayers' order and merged the movers in (solver/particle_sort.h).
    std::uint64_t merged_sorts = 0;
    /// The divide at which the cells switched to CellSwitch's (0: they did not).
    std::uint64_t cell_switch_divide = 0;
    /// The fluid particles that shared their cells at the sort that switched, and the active
    /// fluid then (physics::sharesItsCell).
    std::uint64_t cell_switch_shared = 0, cell_switch_fluid = 0;
};

class Backend {
public:
    virtual ~Backend() = default;
    virtual std::string name() const = 0;        ///< "cpu" or "gpu"
    virtual std::string deviceName() const = 0;  ///< processor or GPU name
    virtual int threads() const = 0;             ///< OpenMP threads (1 for the GPU)
    /// Host threads for the bulk host work of outputs (the state into id order, the part
    /// file's arrays): the OpenMP threads on the CPU; beside a GPU, -threads or every core.
    virtual int hostThreads() const = 0;
    /// The device memory of the backend's arrays (zero on the CPU; core/device_info.h).
    virtual DeviceMemoryUse deviceMemory() const = 0;

    virtual void init(const BackendSetup& setup) = 0;
    /// Sorts the active particles by cell (moving boundaries too when there are any), drops
    /// the ones flagged excluded to the tail, rebuilds cell ranges and PosCell.
    /// `keep_step_start`: the symplectic step-start state (velrho_pre) is still to be
    /// read (between predictor and corrector); otherwise it is not reordered, as the next
    /// predictor overwrites it. (Verlet's state at n-1 is always kept.)
    /// With a skin (CellGrid::skinf > 0) it only refreshes PosCell while every particle stays
    /// within the skin of the cell it was sorted into (cell_grid.h); a particle excluded since
    /// is then removed from the run in its slot (physics::removedPosCell) and dropped to the
    /// tail at the next sort.
    virtual void divide(bool keep_step_start) = 0;
    /// divide(), then the next force evaluation launched at once, without waiting for the
    /// divide's verdict (sort or not): its passes are gated on it, so a sort makes them do
    /// nothing. The host then goes on while the device works; computeForces() takes the result
    /// (sorting and evaluating again when the verdict was a sort), and activeFluid() and
    /// gauges() settle the verdict first. Until computeForces(), nothing may change the state
    /// (the methods that would, throw std::logic_error), and a download sees the evaluation's
    /// own writes (the SPS stress, mDBC's boundary values, the solids' hydrodynamic force):
    /// call it only where the state at this step's end is not saved or written out
    /// (time_steppers.h, StepWindow::ahead_before). The bits of the run are those of
    /// divide() then computeForces().
    virtual void divideThenForces(bool keep_step_start) = 0;
    /// Whether a force evaluation launched by divideThenForces waits for computeForces().
    virtual bool forcesAhead() const = 0;
    /// Divides so far and how many of them sorted.
    virtual DivideCounts divideCounts() const = 0;
    /// Places moving boundaries (pose now, velocity over the coming interval).
    virtual void applyMotion(const std::vector<physics::RigidMotionGpu>& motions) = 0;
    /// One force evaluation; returns the dt maxima. With VCPM solids it also gives the
    /// hydrodynamic force on every solid particle (Eq. 16), which the solid sub-steps hold
    /// fixed until the next evaluation.
    virtual physics::DtMaxima computeForces() = 0;
    virtual void symplecticPredictor(double dt) = 0;
    virtual void symplecticCorrector(double dt) = 0;
    virtual void verletStep(double dt, bool euler) = 0;
    /// VCPM solids: `n` sub-steps of `dt` from time t0 with the hydrodynamic force held fixed; `motions`
    /// carries each motion object's pose at the start and the end of the n sub-steps (clamp
    /// nodes on moving boundaries move linearly in between). Then copies the solid positions
    /// and velocities into the boundary block; `ledger`: add the interval to the coupling
    /// ledger (false for a sub-cycle that solidRestore will undo).
    virtual void solidSteps(double t0, double dt, int n, const std::vector<physics::RigidMotionGpu>& motions,
                            bool ledger) = 0;
    /// The solid particles whose alarm a sub-step raised (physics::SolidAlarm: not finite, too
    /// fast, an intact bond strained past its bound); one small integer reduction, run after
    /// every step, so a diverging solid stops the run at the end of the step it diverged in
    /// (0 without solids).
    virtual std::uint32_t solidsPastBounds() = 0;
    /// Starts solidsPastBounds()'s reduction now, after a step's last sub-cycle, without
    /// waiting for it: its result then comes back with the step's next readback (the
    /// division's), not in a round trip of its own. solidsPastBounds() takes it (or runs the
    /// reduction itself when none was started).
    virtual void startSolidsCheck() = 0;
    /// The largest speed of a solid particle now [m/s] (0 without solids; the solid-only
    /// stepper sizes its chunks of sub-steps with it when contact is on).
    virtual double solidMaxSpeed() = 0;
    /// Snapshot of the solid state (positions, velocities, bond states) ...
    virtual void solidSave() = 0;
    /// ... and back to it (the boundary block gets the restored positions and velocities).
    virtual void solidRestore() = 0;
    /// The hydrodynamic force on every boundary particle (fixed, moving, solid) for the current
    /// state, id order [0, nbound) (the coupling ledger's wall force, at output times; the
    /// pressures are recomputed first, nothing else changes).
    virtual void boundaryForces(std::vector<physics::Double3>& out) = 0;
    /// Gauges: the queries of this run (after init) ...
    virtual void setGauges(const GaugeQueries& q) = 0;
    /// ... answered for the current state (after divide).
    virtual void gauges(GaugeResults& out) = 0;
    /// Active fluid particles now.
    virtual std::uint32_t activeFluid() = 0;
    /// The particles (all of them, excluded ones included) that physics::particleNotFinite
    /// rejects: the blow-up scan's test, counted where the state lives (an integer sum, exact
    /// in any order), so a scan that finds none needs no download (blowup_check.h).
    virtual std::uint32_t notFiniteCount() = 0;
    /// The VCPM solid particles' positions, solid order (empty without solids): what a quick
    /// scan needs for the out-of-domain counts.
    virtual void downloadSolidPositions(std::vector<physics::Double3>& out) = 0;
    /// Waits for queued device work (phase timers only; the CPU backend has none).
    virtual void synchronize() {}
    virtual void download(HostState& out) = 0;
    /// Every allocated particle field except the sort scratch, in id order (tests compare
    /// backends field by field after each phase).
    virtual void downloadFields(HostParticles& out) = 0;
    /// The whole state a restart needs, exactly (checkpoint_data.h, names under "engine/"):
    /// the particle fields flagged kCheckpoint in their current (sorted) order, the cell
    /// ranges and near flags of the last divide, the motions of the coming step, the solids'
    /// arrays and the divide counters. Between two steps only.
    virtual void saveState(CheckpointData& out) = 0;
    /// Replaces the state set by init() with a saved one of the same case (after init(), in
    /// place of the first divide); the run then continues with the same bits.
    virtual void loadState(const CheckpointData& in) = 0;
};

std::unique_ptr<Backend> makeCpuBackend(int threads);
/// nullptr with `why` filled when the CUDA backend is not built or no device exists.
std::unique_ptr<Backend> makeCudaBackend(int device, std::string& why, int host_threads = 0);

}  // namespace seaspring::solver
