// SeaSpring — MIT licence.
/// \file blowup_check.h
/// \brief Blow-up detection: decides from the state of a run (never changing it) whether the
///        run diverged, and says which particles, where, which quantity and which option is the
///        likely cause.
///
/// Two kinds of check:
/// - after every step, from what the loop already knows (no state is read): the active fluid
///   against MinFluidStop, and the number of steps in a row whose dt was raised to DtMin
///   (physics::kMaxDtMinStreak);
/// - a scan of a downloaded state (at every output before it is written, and every
///   `-blowupcheck:N` steps): non-finite positions, velocities or densities of any particle,
///   fluid excluded as not finite (physics::particleNotFinite), and the alarms of VCPM solid
///   bonds strained past physics::kMaxBondStrain and solid speeds past VcpmMaterial::max_speed
///   (physics/blowup_bounds.h). The scan also counts, per solid body, the particles outside the
///   simulation domain (SolidSetup::keep: frozen). A state that passes is kept as the last good
///   one.
/// Between outputs only every K-th periodic scan (`-blowupkeep:K`; auto: one per 2^18 particles
/// of the case, so 1 below 262,145) downloads the state. The others are quick: the backend
/// counts the particles that fail physics::particleNotFinite (an integer sum, the same in any
/// order) and only the solids' positions come to the host for the out-of-domain counts; a
/// count above zero, or a solid alarm, makes it a full scan at once, which names the particles.
/// Every check decides with the same functions on the host's id-order copy or the backend's
/// exact count, so CPU and GPU runs reach the same verdict at the same step.
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "solver/backend.h"
#include "solver/run_options.h"
#include "solver/solver_case.h"

namespace seaspring::solver {

/// Thrown by a time step whose dt is not finite (StepContext::limitDt): the forces diverged.
class NonFiniteStep : public Error {
public:
    explicit NonFiniteStep(const std::string& m) : Error(m) {}
};

/// One particle a diagnosis names.
struct BlowupParticle {
    std::uint32_t id = 0;
    physics::Double3 pos{0, 0, 0};
    double value = 0;  ///< the offending quantity (strain, speed [m/s], ...; NaN for non-finite)
};

/// Why a run was stopped as blown up (run.json's "blowup" object).
struct BlowupDiagnosis {
    std::string quantity;       ///< "non-finite state", "solid bond strain", "solid speed", "fluid loss", "dt at DtMin"
    std::string message;        ///< one line for the log
    std::string likely_option;  ///< the option to change, with its value
    double time = 0;            ///< [s] when it was detected (the end of the step)
    double onset = NAN;         ///< [s] when a solid sub-step first passed the bound (solids only)
    long long step = 0;
    double value = 0, bound = 0;    ///< the largest offending value and the bound it passed
    std::uint64_t count = 0;        ///< offending particles in all
    std::vector<BlowupParticle> particles;  ///< the first few, in id order
};

/// Particles of one VCPM solid body outside the simulation domain.
struct SolidOutside {
    int mkbound = 0;
    std::uint32_t particles = 0;  ///< of the body
    std::uint32_t outside = 0;    ///< now (at the last scan)
    std::uint32_t most = 0;       ///< the most at any scan
    double first_time = -1;       ///< [s] of the first scan that found one outside (-1: never)
};

class BlowupCheck {
public:
    BlowupCheck(const SolverCase& c, const BackendSetup& s, const RunOptions& o);

    /// The per-step checks. `dt`: the step's length; `dtmin_hits`: StepCounters::dtmin_hits so far.
    std::optional<BlowupDiagnosis> afterStep(double t, long long step, double dt, std::uint32_t active_fluid,
                                             long long dtmin_hits);
    /// The diagnosis of a step whose dt came out non-finite (`what`: NonFiniteStep's message).
    BlowupDiagnosis nonFiniteStep(double t, long long step, const std::string& what) const;
    /// Whether a scan is due after `step`: -blowupcheck steps since the last scan (solid-only
    /// runs count sub-steps, which advance in chunks).
    bool scanDue(long long step) const { return every_ > 0 && step - last_scan_ >= every_; }
    /// Whether the scan due now must download the state: K - 1 quick scans since the last full
    /// one (outputs and solid alarms always scan in full, and any full scan restarts the count).
    bool keepDue() const { return since_keep_ + 1 >= keep_every_; }
    /// Scans a state (id order); updates the per-body out-of-domain counts.
    std::optional<BlowupDiagnosis> scan(const HostState& st, double t, long long step, double dt);
    /// A quick scan that passed: the backend counted no particle failing particleNotFinite (a
    /// count above zero takes the full scan instead). `solid_pos`: the solid particles'
    /// positions (solid order) for the out-of-domain counts.
    void quickScan(const std::vector<physics::Double3>& solid_pos, double t, long long step);
    /// Adds the particles a per-step diagnosis is about (excluded fluid, which reason, where).
    void describe(BlowupDiagnosis& d, const HostState& st) const;
    /// Out-of-domain counts per body (empty without solids).
    const std::vector<SolidOutside>& solidsOutside() const { return outside_; }
    /// Warnings for bodies that were found outside the domain for the first time at the last
    /// scan (each body once).
    std::vector<std::string> takeWarnings();

private:
    void countOutside(const physics::Double3* solid_pos, double t);
    std::string solidOption(double dt) const;
    std::string fluidOption() const;

    const SolverCase& case_;
    const BackendSetup& setup_;
    RunOptions opt_;
    long long every_;
    long long streak_ = 0, last_hits_ = 0;
    long long keep_every_;
    long long last_scan_ = 0;  ///< step of the last scan
    long long since_keep_ = 0; ///< quick scans since the last full one
    std::vector<SolidOutside> outside_;
    std::vector<std::string> warnings_;
};

/// Periodic scans per kept state: `requested` (-blowupkeep:K) when above 0, else one per 2^18
/// particles of the case, at least 1.
long long resolveKeepEvery(long long requested, std::size_t particles);

/// "quantity at t = ... s (step N): message; particles ...; likely cause: ..." for the log.
std::string describeBlowup(const BlowupDiagnosis& d);

}  // namespace seaspring::solver
