// SeaSpring — MIT licence.
/// \file simulation.h
/// \brief A run: the time loop (steps of the case's scheme, time_steppers.h), outputs at every
///        TimeOut, gauges, progress lines, stop rules, and the run summary (run.json).
#pragma once

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "solver/backend.h"
#include "solver/blowup_check.h"
#include "solver/run_options.h"
#include "solver/solver_case.h"

namespace seaspring::solver {

class GaugeSystem;
class StepContext;
class TimeStepper;
struct StepCounters;

/// What run.json reports.
struct RunSummary {
    std::string case_name, backend, device;
    int threads = 1;
    std::uint32_t np = 0, nfixed = 0, nmoving = 0, nsolid = 0, nfluid = 0;
    std::uint32_t fluid_active = 0;
    std::uint32_t excluded_position = 0, excluded_density = 0, excluded_not_finite = 0;
    long long steps = 0;            ///< the step count reached (a restarted run counts on from its file's)
    long long steps_run = 0;        ///< the steps this run made (= steps unless -restart)
    long long dtmin_hits = 0;
    unsigned long long divides = 0, sorts = 0;  ///< divides, and those that sorted (skin)
    unsigned long long boundary_sorts = 0;      ///< sorts that included the boundary block (movers)
    unsigned long long merged_sorts = 0;        ///< block sorts that merged the movers in (particle_sort.h)
    unsigned long long cell_switch_divide = 0;  ///< the divide at which the cells switched to h (0: none; cell_switch.h)
    double cell_switch_time = -1;               ///< the end of the step it switched in, when this run did [s]
    double physical_time = 0, wall_time = 0, loop_time = 0;
    double ns_per_particle_step = 0;
    double dt_last = 0;
    int outputs = 0;
    double output_time = 0;    ///< wall time of the outputs: state downloads, checks, part files [s]
    long long gauge_rows = 0;  ///< CSV rows written by the gauges
    std::string stop_reason;
    std::string state_hash;
    std::string options;  ///< physics options, one line
    // VCPM solids
    long long solid_substeps = 0;   ///< solid sub-steps done
    int omega_max = 0;              ///< most sub-steps in one fluid step
    double solid_dt = 0;            ///< the solid sub-step limit VcpmDtCoef dp / c_S [s]
    std::uint64_t bonds = 0, clamp_bonds = 0, broken_bonds = 0;  ///< bonds counted once
    std::vector<SolidOutside> solids_outside;  ///< per body: particles outside the domain
    // How the run ended when it did not finish (exit code != 0).
    int exit_code = 0;                       ///< 0, 1 (blow-up or error), 128 + signal
    std::optional<BlowupDiagnosis> blowup;   ///< set when a blow-up stopped the run
    // Restart files (-checkpoint, -restart).
    int checkpoints = 0;            ///< restart files written
    std::string last_checkpoint;    ///< the last one
    std::string restarted_from;     ///< -restart: the file this run continued
    double restart_time = -1;       ///< [s] it continued from
    std::string last_good_output;            ///< blow-up: the part file holding the last good state
    double last_good_time = -1;              ///< [s] of that state
    // Memory (at the summary's time): the process's host peak, and on the GPU the most its arrays
    // held (cuda/device_memory.cuh) and the device's whole memory [bytes].
    std::uint64_t host_bytes_peak = 0, gpu_bytes_peak = 0, gpu_bytes_total = 0;
};

/// Builds the backend's initial data from the case (particles in id order); cells of
/// mode cell_div (resolveCellDiv; physics::cellSizeOfMode) with a skin of `skin` cells (cell_grid.h).
/// `pair_lanes`: as RunOptions::pair_lanes (0: resolvePairLanes's choice).
/// `cell_switch`: RunOptions::cell_switch (resolveCellSwitch; 0: no switch).
BackendSetup makeBackendSetup(const SolverCase& c, int cell_div, double skin, int pair_lanes = 0,
                              double cell_switch = 0.0);
/// Fluid particles from which one pair lane suffices (resolvePairLanes).
constexpr std::uint32_t kPairLaneThreads = 98304;
/// The most pair lanes resolvePairLanes chooses.
constexpr std::uint32_t kAutoPairLanesMax = 4;
/// The pair lanes a run uses: `pair_lanes` (RunOptions), or for 0 the fewest (a power of two,
/// at most kAutoPairLanesMax) that give the case's fluid particles at least kPairLaneThreads
/// lanes (4 below 49,152 fluid particles, 2 below 98,304, then 1): small cases get more GPU
/// threads in their fluid loop. Measured on an NVIDIA H100 (tools/device_lanes.sh,
/// docs/performance-small.md): 4 lanes were the fastest or within 1.5% of it from 13,860 to 39,312
/// fluid particles; at 115,920 two lanes were 2% slower than one, at 652,212 12% slower.
std::uint32_t resolvePairLanes(const SolverCase& c, int pair_lanes);
/// Particles below which a run's default skin is kSmallRunSkinFraction (resolveSkin).
constexpr std::uint64_t kSmallRunParticles = 262144;
/// The default skin of runs of fewer than kSmallRunParticles particles.
constexpr double kSmallRunSkinFraction = 0.25;
/// The skin a run uses: -skin, else kSmallRunSkinFraction for a case of fewer than
/// kSmallRunParticles particles, else physics::kDefaultSkinFraction. A small run's step is
/// bound by launch latency, and a sort is a dozen launches and a wait, while the candidates
/// that a wider skin adds cost little there; a large run's pair loop pays for every candidate.
/// NVIDIA H200, first 0.1 s (0.3 s, 0.5 s), skin 0.25 against 0.05: the Antoci gate 2D
/// (17,384 particles) 0.855, FlexStruc Liao 2D (27,956) 0.840, DualSPHysics' 2D and 3D dam
/// breaks as shipped 0.738 and 0.899 (171 k); larger runs lost with it (the 3D sluice gate at
/// dp 4 mm, 342 k, 1.04 over 1 s; FlexStruc Liao 3D, 2.6 M, 1.03 at 0.2;
/// docs/performance-large.md, twenty-ninth and thirtieth sessions). The CPU (2 threads): the
/// 2D cases within their spread, Spheric2Dam_100K (3D, 116,658) 1.02 over its first 0.1 s (its
/// pair loop pays for the candidates; the skin must not depend on the backend, whose runs
/// would then differ in their bits).
double resolveSkin(const SolverCase& c, const RunOptions& o);
/// The cell division a run uses: `cell_div` (RunOptions), or for 0 (-cellmode:auto) in 3D 4
/// where h >= 2 dp (cells of h/2 at least dp wide; on an H100, SPHERIC Test 2 at 4.4 M
/// particles, h = 2 dp, runs 13% faster than with cells of h), physics::kCellDivSpacing (cells
/// of dp) where 1.5 dp < h < 2 dp (DualSPHysics' default coefh 1 gives h = 1.73 dp: cells of dp
/// are a whole number of spacings, so the grid can be centred on the fluid's lattice, which
/// neither h/2 nor 2h/3 allows), else 3 (2h/3: the 3D sluice gate, h = 1.5 dp, 10% faster than
/// with cells of h/2, whose cells would hold fewer than one particle), and 2 in 2D, each the
/// finest whose grid fits 32-bit packed cells and at most 16 cells per particle + 2^20 (else the
/// next coarser: 3, then 2; 1 at the coarsest).
int resolveCellDiv(const SolverCase& c, int cell_div);

class Simulation {
public:
    Simulation(const SolverCase& c, const RunOptions& o, std::unique_ptr<Backend> backend,
               std::ostream& log);
    /// Runs to TimeMax (or -nsteps), writing outputs; returns the summary (also run.json).
    RunSummary run();
    /// The summary so far (after run() threw: what the run had reached), its memory figures
    /// read now.
    RunSummary summary() const;
    /// The state at the end of run() (id order).
    const HostState& finalState() const { return final_; }
    /// Called at every output time (t = 0, each TimeOut, the end) with the state in id order,
    /// whatever -sv says: for in-process post-processing (tests, gauges).
    using OutputObserver = std::function<void(double time, long long step, const HostState& state)>;
    void onOutput(OutputObserver f) { observer_ = std::move(f); }

private:
    /// Downloads the state, scans it for a blow-up (blowup_check.h) and, when it is good,
    /// writes it as the next output; returns false (nothing written, sum_.blowup set) when not.
    /// When nothing reads the state at an output (outputNeedsState), the backend's count of
    /// non-finite particles is the check, as between outputs, and only a count above zero
    /// brings the state to the host (to name the particles).
    bool output(double time, long long step);
    /// Whether an output reads the state: part files (-sv h5 or vtk), an output observer, or
    /// the solids' ledger. Without them (-sv:none on a fluid-only case, as the benchmarks and
    /// gauge-only runs) an output is the gauges' flush and the count of outputs.
    bool outputNeedsState() const;
    /// Writes `st` as the next output (part files, ledger row when `ledger`, gauges flushed).
    void writeOutput(const HostState& st, double time, long long step, bool ledger);
    /// The particle files of an output (-sv h5, vtk).
    void writeParticleFiles(const HostState& st, double time, long long step);
    /// Counts an output at `time` and flushes the gauge files.
    void noteOutput(double time);
    /// The blow-up scan of a downloaded state; a good state becomes the last good one (swapped
    /// with it: `st` is left holding the previous one).
    bool healthy(HostState& st, double time, long long step);
    /// The blow-up checks after a step (blowup_check.h): the per-step ones, then a scan of the
    /// state every -blowupcheck steps unless an output (which scans) is due (a quick scan on the
    /// backend but at every -blowupkeep-th); they only read the state. Returns false when the
    /// run blew up.
    bool checkStep(double t, long long step, double dt, std::uint32_t active, long long dtmin_hits, bool output_due);
    /// A step whose dt was not finite (NonFiniteStep's message).
    void stepFailed(double t, long long step, const std::string& what);
    /// Time of the last output written (-1: none).
    double lastOutputTime() const;
    /// Ends a run on a blow-up: logs the diagnosis, writes the last good state when it is newer
    /// than the last output, sets the summary's stop reason and exit code.
    void blownUp(BlowupDiagnosis d);
    /// Per-particle solid fields of the part files (zero for other particles).
    void solidFields(const HostState& st, std::vector<float>& disp, std::vector<float>& strain,
                     std::vector<std::uint8_t>& broken, std::vector<float>& damage) const;
    /// Broken bonds (each solid-solid bond counted once) in `st`.
    std::uint64_t brokenBonds(const HostState& st) const;
    /// After the loop: the last output when none was written, the final state, run.json's counts.
    void finish(double t, long long steps, double loop_time, const StepCounters& counters);

    /// The time loop's own state, saved in restart files (simulation_checkpoint.cpp).
    struct LoopState {
        double t = 0, next_out = 0, next_checkpoint = 0;
        long long step = 0;
        bool warned_out = false;
    };
    /// Writes OUTDIR/restart.h5 (atomically) with everything the run needs to continue.
    void saveCheckpoint(const LoopState& loop, const TimeStepper& stepper, const StepContext& ctx);
    /// After Backend::init: the state of the restart file (resume_) in place of the start.
    LoopState resume(TimeStepper& stepper, StepContext& ctx);
    /// The next checkpoint time after `t` (-checkpoint; a huge number without one).
    double nextCheckpoint(double t) const;
    /// StepWindow::ahead_before: the step end times below which the loop neither writes out,
    /// measures nor saves the state, and the run does not end (the outputs', gauges',
    /// checkpoints' and TimeMax's own tests, each just failed).
    double aheadBefore(double next_out, double next_checkpoint) const;
    /// A file named TERMINATE in OUTDIR (DualSPHysics' way to end a run cleanly).
    bool terminateRequested() const;

    const SolverCase& case_;
    RunOptions opt_;
    std::unique_ptr<Backend> backend_;
    std::ostream& log_;
    BackendSetup setup_;
    RunSummary sum_;
    HostState final_;
    int out_index_ = 0;
    struct Output;
    std::shared_ptr<Output> out_;
    struct Ledger;
    std::shared_ptr<Ledger> ledger_;
    std::shared_ptr<GaugeSystem> gauges_;  ///< null when the case has no gauges
    struct Health;
    std::shared_ptr<Health> health_;  ///< the blow-up check and the last good state
    OutputObserver observer_;
    std::shared_ptr<const CheckpointData> resume_;  ///< -restart: the restart file's data
    bool continuing_ = false;  ///< -restart with the restart file in OUTDIR: its files are continued
};

/// Whether a restart continues in OUTDIR (part files, gauges, ledger, Run.out continued): the
/// restart file lies in OUTDIR, as OUTDIR/restart.h5 written by -checkpoint does.
bool restartContinuesIn(const std::string& restart_file, const std::string& outdir);

/// One-line description of the physics options ("symplectic, Wendland, artificial 0.1, ...").
/// `cell_switch`: the fraction of the run's cells' switch (resolveCellSwitch; 0: none).
std::string describePhysics(const SolverParameters& p, int dim, int cell_div, double skin,
                            std::uint32_t pair_lanes = 1, double cell_switch = 0.0);

}  // namespace seaspring::solver
