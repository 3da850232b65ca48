// SeaSpring — MIT licence.
/// \file gauge_system.h
/// \brief The case's gauges during a run: when each one measures (computedt, computetime),
///        what the backend is asked (kernel sums at points, maxz columns, particle positions,
///        boundary forces) and the CSV files OUTDIR/gauges/Gauges<Kind>_<name>.csv
///        (';'-separated, one header line, DualSPHysics' column names).
///
/// Timing follows DualSPHysics: a gauge measures at t = 0 and then whenever the time passes
/// its next multiple of computedt (0: every step) inside computetime; it writes a row when
/// output is on, inside outputtime, at multiples of outputdt. Defaults: computedt = TimeOut,
/// the whole run, output off; outputdt: every measured value (DualSPHysics: TimeOut).
#pragma once

#include <cstdio>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "solver/backend.h"
#include "solver/solver_case.h"

namespace seaspring::solver {

class GaugeSystem {
public:
    /// Resolves every gauge of `c.gauges` (points, maxz columns, marker particles, force blocks);
    /// throws seaspring::Error naming the resolved case file and line for a bad target.
    /// `resume`: a restart file's data: the gauges continue its timing, and their CSV files in
    /// OUTDIR are cut back to what they held at the checkpoint and continued (new files when
    /// they are not there).
    GaugeSystem(const SolverCase& c, const std::string& outdir, std::ostream& log,
                const CheckpointData* resume = nullptr);
    ~GaugeSystem();
    GaugeSystem(const GaugeSystem&) = delete;
    GaugeSystem& operator=(const GaugeSystem&) = delete;

    /// Gives the backend the queries of the run (after Backend::init).
    void attach(Backend& b) const;
    /// The earliest time at which a gauge measures next (a huge number when none will).
    double nextTime() const;
    /// Measures the gauges due at `t` (state after divide) and writes their rows.
    void evaluate(double t, Backend& b);
    /// Flushes the CSV files.
    void flush();
    /// Rows written so far (all gauges).
    long long rows() const { return rows_; }
    /// The gauges' timing and file lengths into a restart file ("gauges/"; flushes the files).
    void save(CheckpointData& d);

    struct Item;

private:
    double massfluid_ = 0;
    int dim_ = 3;
    double domain_minz_ = 0;
    GaugeQueries q_;
    std::vector<bool> outside_;  ///< per query point: outside the domain (measures nothing)
    std::vector<std::unique_ptr<Item>> items_;
    long long rows_ = 0;
};

}  // namespace seaspring::solver
