// SeaSpring — MIT licence.
/// \file simulation_checkpoint.cpp
/// \brief Restart files of a run (Simulation::saveCheckpoint, Simulation::resume): the loop's
///        state, the time scheme's, the counters, the gauges' timing and file lengths, the
///        ledger's length, the output series and the backend's whole state (Backend::saveState).
///        A run continued from one gives the same bits as the run that was not interrupted.
#include <cmath>
#include <filesystem>
#include <ostream>

#include "core/error.h"
#include "io/checkpoint_file.h"
#include "io/xdmf_series.h"
#include "solver/coupling_ledger.h"
#include "solver/gauge_system.h"
#include "solver/simulation.h"
#include "solver/simulation_parts.h"
#include "solver/step_context.h"
#include "solver/time_steppers.h"

namespace seaspring::solver {

namespace fs = std::filesystem;

namespace {

constexpr const char* kRestartName = "restart.h5";

std::string canonical(const std::string& p) {
    std::error_code ec;
    const fs::path c = fs::weakly_canonical(fs::absolute(p), ec);
    return ec ? p : c.string();
}

/// The -cellmode name of an option line's "cells of X" (describePhysics), or "" without one.
std::string cellModeOf(const std::string& options) {
    const std::string key = "cells of ";
    const std::size_t at = options.find(key);
    if (at == std::string::npos) return "";
    const std::size_t b = at + key.size(), e = options.find_first_of(" ,", b);
    const std::string label = options.substr(b, e == std::string::npos ? std::string::npos : e - b);
    for (int d = 1; d < kCellModes; ++d)
        if (label == cellSizeLabel(d)) return cellModeName(d);
    return "";
}

/// The word after `key` in an option line (describePhysics), "0" without it: the -skin of
/// "with a skin of F cell", the -cellswitch of "(h once F of the fluid shares them)".
std::string valueAfter(const std::string& options, const std::string& key) {
    const std::size_t at = options.find(key);
    if (at == std::string::npos) return "0";
    const std::size_t b = at + key.size(), e = options.find(' ', b);
    return options.substr(b, e == std::string::npos ? std::string::npos : e - b);
}
std::string skinOf(const std::string& options) { return valueAfter(options, "with a skin of "); }
std::string cellSwitchOf(const std::string& options) { return valueAfter(options, "(h once "); }

}  // namespace

bool restartContinuesIn(const std::string& restart_file, const std::string& outdir) {
    return fs::path(canonical(restart_file)).parent_path() == fs::path(canonical(outdir));
}

double Simulation::nextCheckpoint(double t) const {
    const double dt = opt_.checkpoint_interval;
    if (!(dt > 0)) return HUGE_VAL;
    double n = dt * std::floor(t / dt);
    if (n <= t + 1e-9 * dt) n = dt * (std::floor(t / dt) + 1.0);
    return n;
}

bool Simulation::terminateRequested() const {
    std::error_code ec;
    return fs::exists(fs::path(opt_.outdir) / "TERMINATE", ec);
}

void Simulation::saveCheckpoint(const LoopState& loop, const TimeStepper& stepper, const StepContext& ctx) {
    if (out_) out_->parts.wait();  // HDF5 from one thread at a time (io/part_writer.h)
    CheckpointData d;
    d.texts["loop/case"] = case_.name;
    d.texts["loop/options"] = sum_.options;
    d.texts["loop/outdir"] = canonical(opt_.outdir);
    d.reals["loop/t"] = loop.t;
    d.reals["loop/next_out"] = loop.next_out;
    d.reals["loop/next_checkpoint"] = loop.next_checkpoint;
    d.reals["loop/dt_last"] = sum_.dt_last;
    d.reals["loop/time_max"] = case_.params.time_max;
    d.ints["loop/step"] = loop.step;
    d.ints["loop/warned_out"] = loop.warned_out ? 1 : 0;
    d.ints["loop/out_index"] = out_index_;
    d.ints["loop/outputs"] = sum_.outputs;
    d.ints["loop/save_h5"] = out_ ? 1 : 0;
    if (out_) {
        const std::vector<std::string>& frames = out_->xdmf.frames();
        d.ints["xdmf/frames"] = (long long)frames.size();
        for (std::size_t k = 0; k < frames.size(); ++k) d.texts["xdmf/" + std::to_string(k)] = frames[k];
    }
    d.reals["health/written_time"] = health_->written_time;
    d.texts["health/written_file"] = health_->written_file;
    stepper.save(d);
    ctx.saveCounters(d);
    if (gauges_) gauges_->save(d);
    if (ledger_) d.ints["ledger/offset"] = ledger_->file.offset();
    backend_->saveState(d);
    const std::string path = (fs::path(opt_.outdir) / kRestartName).string();
    io::writeCheckpointFile(path, d);
    ++sum_.checkpoints;
    sum_.last_checkpoint = path;
    log_ << "  checkpoint t=" << loop.t << " s, step " << loop.step << ": " << path << "\n";
}

Simulation::LoopState Simulation::resume(TimeStepper& stepper, StepContext& ctx) {
    const CheckpointData& d = *resume_;
    if (d.text("loop/case") != case_.name)
        throw Error(d.source + ": restart file of case '" + d.text("loop/case") + "', this run is case '" + case_.name +
                    "'");
    if (d.text("loop/options") != sum_.options) {
        // The cell mode, the skin and the cells' switch are what an option line may differ in
        // without any option given: their defaults changed (cells of dp where 1.5 dp < h < 2 dp,
        // twenty-first session; a skin of 0.25 below 262,144 particles, thirtieth session; the
        // switch, thirty-first session).
        const std::string was = cellModeOf(d.text("loop/options")), now = cellModeOf(sum_.options);
        std::string hint = !was.empty() && was != now ? "; its cells differ: continue it with -cellmode:" + was : "";
        const std::string skin_was = skinOf(d.text("loop/options"));
        if (skin_was != skinOf(sum_.options)) hint += "; its skin differs: continue it with -skin:" + skin_was;
        // The cells' switch (cell_switch.h, thirty-first session): a file of a run without it.
        const std::string switch_was = cellSwitchOf(d.text("loop/options"));
        if (switch_was != cellSwitchOf(sum_.options))
            hint += "; its cells' switch differs: continue it with -cellswitch:" + switch_was;
        throw Error(d.source + ": restart file written with the options\n  " + d.text("loop/options") +
                    "\nthis run has\n  " + sum_.options + "\n(a restart continues the same run: give the same options" +
                    hint + ")");
    }
    LoopState loop;
    loop.t = d.real("loop/t");
    loop.step = d.integer("loop/step");
    loop.next_out = d.real("loop/next_out");
    loop.next_checkpoint = nextCheckpoint(loop.t);
    loop.warned_out = d.integer("loop/warned_out") != 0;
    sum_.dt_last = d.real("loop/dt_last");
    out_index_ = int(d.integer("loop/out_index"));
    sum_.outputs = int(d.integer("loop/outputs"));
    if (out_ && continuing_ && d.integer("loop/save_h5") != 0) {
        std::vector<std::string> frames(std::size_t(d.integer("xdmf/frames")));
        for (std::size_t k = 0; k < frames.size(); ++k) frames[k] = d.text("xdmf/" + std::to_string(k));
        out_->xdmf.restoreFrames(std::move(frames));
    }
    health_->written_time = d.real("health/written_time");
    health_->written_file = d.text("health/written_file");
    stepper.load(d);
    ctx.loadCounters(d);
    backend_->loadState(d);
    log_ << "  restarted from " << d.source << " at t=" << loop.t << " s, step " << loop.step
         << (continuing_ ? " (continuing the outputs in OUTDIR)" : " (outputs start afresh in OUTDIR)") << "\n";
    return loop;
}

}  // namespace seaspring::solver
