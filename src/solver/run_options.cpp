// SeaSpring — MIT licence.
/// \file run_options.cpp
/// \brief The solver's command line (see run_options.h). DualSPHysics' `-name:value` is
///        translated to CLI11's `--name=value` (as in gencase_main.cpp); CLI11 knows the
///        options and their conflicts, the values are converted here, strictly.
#include "solver/run_options.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <vector>

#include "physics/neighbour_rows.h"

#include <CLI/CLI.hpp>

#include "core/error.h"
#include "physics/cell_grid.h"

namespace seaspring::solver {

const char* cellModeName(int cell_div) {
    static const char* const kNames[kCellModes] = {"auto", "full", "h", "third", "quarter", "dp"};
    return cell_div >= 0 && cell_div < kCellModes ? kNames[cell_div] : nullptr;
}

const char* cellSizeLabel(int cell_div) {
    static const char* const kLabels[kCellModes] = {"?", "2h", "h", "2h/3", "h/2", "dp"};
    return cell_div >= 0 && cell_div < kCellModes ? kLabels[cell_div] : nullptr;
}

namespace {

const char* kUsage = "seaspring [options] OUTDIR/NAME OUTDIR";

[[noreturn]] void usageError(const std::string& message) { throw Error(message); }

/// One option as the user wrote it.
struct Given {
    std::string arg;    ///< as written, for messages
    std::string value;  ///< after ':' or '='
    bool has_value = false;
};

/// A decimal number written completely ("0.2x", "nan", "inf", hex and blanks are refused).
double toDouble(const Given& g) {
    const std::string& t = g.value;
    if (t.empty() || t.find_first_not_of("0123456789+-.eE") != std::string::npos)
        usageError(g.arg + ": \"" + t + "\" is not a number");
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(t.c_str(), &end);
    if (end != t.c_str() + t.size()) usageError(g.arg + ": \"" + t + "\" is not a number");
    if (errno == ERANGE || !std::isfinite(v)) usageError(g.arg + ": \"" + t + "\" is out of range");
    return v;
}

/// A decimal integer in lo..hi (hi >= INT_MAX: no upper limit but the type's).
long long toInteger(const Given& g, long long lo, long long hi, const std::string& meaning = "") {
    const std::string& t = g.value;
    const std::size_t sign = !t.empty() && (t[0] == '-' || t[0] == '+') ? 1 : 0;
    if (t.size() == sign || t.find_first_not_of("0123456789", sign) != std::string::npos)
        usageError(g.arg + ": \"" + t + "\" is not an integer");
    errno = 0;
    const long long v = std::strtoll(t.c_str(), nullptr, 10);
    if (errno == ERANGE || v > hi) {
        if (hi >= INT_MAX) usageError(g.arg + ": " + t + " is too large");
        usageError(g.arg + ": " + t + " must be " + std::to_string(lo) + ".." + std::to_string(hi) +
                   meaning);
    }
    if (v < lo)
        usageError(g.arg + ": " + t + " must be " +
                   (hi >= INT_MAX ? ">= " + std::to_string(lo)
                                  : std::to_string(lo) + ".." + std::to_string(hi)) +
                   meaning);
    return v;
}

/// A number that must be > 0 (`Positive`), >= 0 (`NonNegative`) or in (0, 1] (`Fraction`).
enum class Range { Positive, NonNegative, Fraction };

double toDouble(const Given& g, Range r) {
    const double v = toDouble(g);
    const bool ok = r == Range::Positive      ? v > 0
                    : r == Range::NonNegative ? v >= 0
                                              : v > 0 && v <= 1;
    if (!ok)
        usageError(g.arg + ": " + g.value + " must be " +
                   (r == Range::Positive      ? "> 0"
                    : r == Range::NonNegative ? ">= 0"
                                              : "in (0, 1]"));
    return v;
}

/// The options CLI11 knows; their conflicts are declared here too.
void declareOptions(CLI::App& app) {
    auto value = [&](const char* name) { return app.add_option(name, "")->type_size(1); };
    auto optional = [&](const char* name) { return value(name)->expected(0, 1); };
    auto flag = [&](const char* name) { return app.add_flag(name); };
    CLI::Option* gpu = optional("--gpu");
    flag("--cpu")->excludes(gpu);
    value("--threads");
    value("--tmax");
    value("--tout");
    value("--sv");
    optional("--svres");
    optional("--svpips");
    value("--dirdataout");
    value("--nsteps");
    value("--blowupcheck");
    value("--blowupkeep");
    flag("--overwrite");
    value("--checkpoint");
    CLI::Option* restart = value("--restart");
    value("--partbegin")->excludes(restart);
    value("--cellmode");
    value("--skin");
    value("--cellswitch");
    value("--pairlanes");
    value("--vcpmsubsteps");
    value("--vcpmcoupling");
    value("--vcpmdtcoef");
    value("--progress");
    flag("--quiet");
    CLI::Option* verlet = optional("--verlet");
    flag("--symplectic")->excludes(verlet);
    CLI::Option* wendland = flag("--wendland");
    flag("--cubic")->excludes(wendland);
    CLI::Option* art = value("--viscoart");
    CLI::Option* lam = value("--viscolam")->excludes(art);
    value("--viscolamsps")->excludes(art)->excludes(lam);
    value("--viscoboundfactor");
    value("--ddt");
    value("--ddtvalue");
    value("--cfl");
    value("--dtfixed");
}

/// "-name:value" and "--name=value" become "--name=value" for CLI11; positional arguments
/// (and everything after "--") are kept apart. Unknown names, repeated options, values given to
/// flags and missing values are reported with the argument as written.
std::vector<std::string> translate(const CLI::App& app, const std::vector<std::string>& args,
                                   std::map<std::string, Given>& given,
                                   std::vector<std::string>& positional) {
    std::vector<std::string> out;
    bool only_positional = false;
    for (const std::string& a : args) {
        if (a == "--" && !only_positional) {
            only_positional = true;  // what follows is positional, even if it starts with '-'
            continue;
        }
        if (only_positional || a.size() < 2 || a[0] != '-') {
            positional.push_back(a);
            continue;
        }
        const bool gnu = a[1] == '-';
        const std::size_t start = gnu ? 2 : 1;
        const std::size_t sep = a.find(gnu ? '=' : ':', start);
        Given g{a, sep == std::string::npos ? "" : a.substr(sep + 1), sep != std::string::npos};
        const std::string name =
            a.substr(start, sep == std::string::npos ? std::string::npos : sep - start);
        const CLI::Option* opt = name.empty() ? nullptr : app.get_option_no_throw("--" + name);
        if (!opt) usageError("unknown option " + a);
        if (given.count(name))
            usageError(a + ": -" + name + " is given twice (" + given[name].arg + ")");
        if (g.has_value && opt->get_items_expected_max() == 0)
            usageError(a + ": -" + name + " takes no value");
        if (g.has_value && g.value.empty())
            usageError(a + ": the value after '" + std::string(1, a[sep]) + "' is missing");
        if (!g.has_value && opt->get_items_expected_min() > 0)
            usageError(a + ": needs a value (-" + name + ":VALUE)");
        out.push_back("--" + name + (g.has_value ? "=" + g.value : ""));
        given[name] = g;
    }
    return out;
}

/// CLI11's message with DualSPHysics-style names ("--cpu excludes --gpu" -> "-cpu ... -gpu").
std::string rewrite(std::string m) {
    for (std::size_t p; (p = m.find("--")) != std::string::npos;) m.erase(p, 1);
    const std::size_t ex = m.find(" excludes ");
    if (ex != std::string::npos) m.replace(ex, 10, " cannot be combined with ");
    return m;
}

void readOutputs(const Given& g, RunOptions& o) {
    o.save_h5 = o.save_vtk = false;
    std::set<std::string> items;
    std::string rest = g.value;
    for (std::size_t p = 0;;) {
        const std::size_t comma = rest.find(',', p);
        const std::string item =
            rest.substr(p, comma == std::string::npos ? std::string::npos : comma - p);
        if (item != "h5" && item != "vtk" && item != "none" && item != "binx" && item != "info")
            usageError(g.arg + ": unknown output \"" + item + "\" (supported: h5, vtk, none; DualSPHysics' binx and info "
                       "are taken as h5 and as run.json)");
        if (!items.insert(item).second) usageError(g.arg + ": \"" + item + "\" is listed twice");
        if (item == "binx")
            o.notes.push_back(g.arg + ": DualSPHysics' binx particle files are written as HDF5 part files "
                              "(OUTDIR/data/part_NNNN.h5, parts.xdmf)");
        if (item == "info") o.notes.push_back(g.arg + ": the run's information is in OUTDIR/run.json and Run.out");
        if (comma == std::string::npos) break;
        p = comma + 1;
    }
    if (items.count("none") && items.size() > 1)
        usageError(g.arg + ": \"none\" cannot be combined with outputs");
    if (items.count("h5") && items.count("binx")) usageError(g.arg + ": h5 and binx are the same output here");
    o.save_h5 = items.count("h5") > 0 || items.count("binx") > 0;
    o.save_vtk = items.count("vtk") > 0;
}

void readValues(const std::map<std::string, Given>& given, RunOptions& o) {
    using B = RunOptions::Backend;
    for (const auto& [name, g] : given) {
        if (name == "gpu") {
            o.backend = B::Gpu;
            if (g.has_value) o.gpu_id = int(toInteger(g, 0, INT_MAX));
        } else if (name == "cpu") {
            o.backend = B::Cpu;
        } else if (name == "threads") {
            o.threads = int(toInteger(g, 1, kMaxThreads));
        } else if (name == "tmax") {
            o.tmax = toDouble(g, Range::Positive);
        } else if (name == "tout") {
            o.tout = toDouble(g, Range::Positive);
        } else if (name == "sv") {
            readOutputs(g, o);
        } else if (name == "svres") {
            if (g.has_value) toInteger(g, 0, 1);  // accepted for DualSPHysics command lines
        } else if (name == "svpips") {
            if (g.has_value) toInteger(g, 0, 2);  // DualSPHysics: 0, 1 or 2
            o.notes.push_back(g.arg + ": performance figures (ns per particle per step, steps) are in run.json "
                                      "and the summary");
        } else if (name == "dirdataout") {
            if (g.value.empty() || g.value.find('/') != std::string::npos || g.value == "." || g.value == "..")
                usageError(g.arg + ": expected a folder name inside OUTDIR");
            if (g.value != "data")
                o.notes.push_back(g.arg + ": part files are always written to OUTDIR/data (DualSPHysics' default), "
                                          "not OUTDIR/" + g.value);
        } else if (name == "nsteps") {
            o.nsteps = toInteger(g, 0, LLONG_MAX);
        } else if (name == "blowupcheck") {
            o.blowup_check_every = toInteger(g, 0, LLONG_MAX);
        } else if (name == "blowupkeep") {
            o.blowup_keep_every = toInteger(g, 0, LLONG_MAX);
        } else if (name == "overwrite") {
            o.overwrite = true;
        } else if (name == "checkpoint") {
            o.checkpoint_interval = toDouble(g, Range::Positive);
        } else if (name == "restart" || name == "partbegin") {
            if (g.value.empty()) usageError(g.arg + ": the restart file is missing");
            o.restart_file = g.value;
        } else if (name == "cellmode") {
            o.cell_div = -1;
            for (int k = 0; k < kCellModes; ++k)
                if (g.value == cellModeName(k)) o.cell_div = k;
            if (o.cell_div < 0) {
                std::string modes;
                for (int k = 0; k < kCellModes; ++k) modes += std::string(k ? ", " : "") + cellModeName(k);
                usageError(g.arg + ": \"" + g.value + "\" is not a cell mode (supported: " + modes + ")");
            }
        } else if (name == "skin") {
            o.skin = toDouble(g, Range::NonNegative);
            if (*o.skin > physics::kMaxSkinFraction)
                usageError(g.arg + ": " + g.value + " is larger than 0.5" +
                           " (the skin is a fraction of the cell size)");
        } else if (name == "cellswitch") {
            o.cell_switch = toDouble(g, Range::NonNegative);
            if (o.cell_switch > 1.0)
                usageError(g.arg + ": " + g.value + " is larger than 1 (the share of the fluid in cells it shares; " +
                           "0: never switch)");
        } else if (name == "pairlanes") {
            o.pair_lanes = int(toInteger(g, 0, physics::kMaxPairLanes, " (pair lanes: 1, 2, 4 or 8; 0: auto)"));
            if ((o.pair_lanes & (o.pair_lanes - 1)) != 0)
                usageError(g.arg + ": " + g.value + " is not a power of two (pair lanes: 1, 2, 4 or 8; 0: auto)");
        } else if (name == "vcpmsubsteps") {
            o.solid_substeps = int(toInteger(g, 0, 1000000));
        } else if (name == "vcpmcoupling") {
            o.vcpm_coupling = int(toInteger(g, 1, 2));
        } else if (name == "vcpmdtcoef") {
            o.vcpm_dt_coef = toDouble(g, Range::Positive);
            if (*o.vcpm_dt_coef > 2) usageError(g.arg + ": " + g.value + " is larger than 2 (as the VcpmDtCoef parameter)");
        } else if (name == "progress") {
            o.progress_interval = toDouble(g, Range::NonNegative);
        } else if (name == "quiet") {
            o.quiet = true;
        } else if (name == "symplectic") {
            o.step_algorithm = 2;
        } else if (name == "verlet") {
            o.step_algorithm = 1;
            if (g.has_value) o.verlet_steps = int(toInteger(g, 1, INT_MAX));
        } else if (name == "wendland" || name == "cubic") {
            o.kernel = name == "cubic" ? 1 : 2;
        } else if (name == "viscoart" || name == "viscolamsps" || name == "viscolam") {
            o.visco = toDouble(g, Range::NonNegative);
            o.visco_treatment = name == "viscoart" ? 1 : name == "viscolamsps" ? 2 : 3;
        } else if (name == "viscoboundfactor") {
            o.visco_bound_factor = toDouble(g, Range::NonNegative);
        } else if (name == "ddt") {
            o.ddt = int(toInteger(g, 0, 3, " (0 none, 1 Molteni, 2 Fourtakas, 3 Fourtakas full)"));
        } else if (name == "ddtvalue") {
            o.ddt_value = toDouble(g, Range::NonNegative);
        } else if (name == "cfl") {
            o.cfl = toDouble(g, Range::Fraction);
        } else if (name == "dtfixed") {
            o.dt_fixed = toDouble(g, Range::Positive);
        } else {
            SEASPRING_CHECK(false, "option -", name, " is declared but not read");
        }
    }
}

}  // namespace

RunOptions parseRunOptions(int argc, const char* const* argv) {
    RunOptions o;
    const std::vector<std::string> args(argv + std::min(argc, 1), argv + std::max(argc, 0));
    for (const std::string& a : args) {
        if (a == "-h" || a == "-help" || a == "--help") {
            o.help = true;
            return o;
        }
        if (a == "-version" || a == "--version") {
            o.version = true;
            return o;
        }
    }
    CLI::App app{"seaspring"};
    app.set_help_flag();
    declareOptions(app);
    std::map<std::string, Given> given;
    std::vector<std::string> positional;
    std::vector<std::string> cli = translate(app, args, given, positional);
    std::reverse(cli.begin(), cli.end());  // CLI11's vector overload parses from the back
    try {
        app.parse(cli);
    } catch (const CLI::ParseError& e) {
        usageError(rewrite(e.what()));
    }
    readValues(given, o);
    if (positional.size() < 2)
        usageError(std::string(positional.empty() ? "OUTDIR/NAME and OUTDIR are missing"
                                                  : "OUTDIR is missing") +
                   " (usage: " + kUsage + ")");
    if (positional.size() > 2)
        usageError("unexpected argument \"" + positional[2] + "\" (usage: " + kUsage + ")");
    o.case_path = positional[0];
    o.outdir = positional[1];
    return o;
}

std::string runOptionsHelp() {
    return std::string("Usage: ") + kUsage + "\n" + R"(
Runs the case OUTDIR/NAME written by `gencase CASE_Def.xml OUTDIR/NAME` (NAME.xml and
NAME.h5; OUTDIR/NAME.xml may be given too) and writes the results to OUTDIR.
Options are written -name or -name:value (DualSPHysics style), or --name, --name=value;
arguments after "--" are taken as OUTDIR/NAME and OUTDIR even when they start with '-'.

Backend:
  -gpu[:ID]            run on CUDA device ID (default 0); an error when no GPU is usable
  -cpu                 run on the CPU (OpenMP)
  -threads:N           OpenMP threads, 1 <= N <= 1024 (default: all cores); with -gpu
                       the host threads of outputs
                       (without -gpu or -cpu: the GPU when one is usable, else the CPU)
Run control:
  -tmax:T              simulated time T > 0 [s] (overrides TimeMax)
  -tout:T              output interval T > 0 [s] (overrides TimeOut)
  -nsteps:N            stop at step N >= 0 (tests, benchmarks); after -restart the count
                       goes on from the restart file's step, as the interrupted run's did
  -overwrite           OUTDIR holds an earlier run: remove its files (Run.out, run.json,
                       parts.xdmf, data/, vtk/, gauges/, ledger.csv) and run; without it
                       such an OUTDIR is refused (the case files there are kept)
  -checkpoint:T        write OUTDIR/restart.h5 (atomically, replacing the last one) every
                       T > 0 [s] of simulated time; SIGINT/SIGTERM and a file named
                       TERMINATE in OUTDIR (as DualSPHysics) also write one, then stop
  -restart:FILE        continue the run saved in restart file FILE (alias -partbegin:FILE):
                       same case, same options; the result has the same bits as the run
                       that was not interrupted. In the OUTDIR it was written to, the part
                       files, gauge files, ledger and Run.out are continued from it
  -blowupcheck:N       scan the whole state for a blow-up every N >= 0 steps (default
                       100; 0: only at output times). Fluid loss (MinFluidStop), dt
                       stuck at DtMin and VCPM solids (non-finite, bond strain past 1,
                       speed past 10 max(c_S, c0)) are checked within every step
  -blowupkeep:K        download the state at every K-th of those scans and keep it as the
                       last good state, written if a later check fails (default 0: one
                       scan in ceil(particles / 262144)); the others count non-finite
                       particles where the state lives (no download)
  -sv:LIST             outputs, comma-separated: h5 (particle files, default), vtk (VTU
                       files in OUTDIR/vtk), none; DualSPHysics' binx is taken as h5 and
                       info as run.json (a note each)
  -svres[:0|1]         accepted for DualSPHysics command lines; run.json is always written
  -svpips[:0|1|2]      accepted for DualSPHysics command lines (a note): the figures are in
                       run.json and the summary
  -dirdataout:NAME     accepted for DualSPHysics command lines: part files go to OUTDIR/data
                       whatever NAME (a note says so when NAME is not data)
  -cellmode:auto|full|h|third|quarter|dp
                       neighbour cells of size 2h (full), h (h), 2h/3 (third), h/2
                       (quarter) or one particle spacing (dp: the search reaches the
                       cells within 2h, at most 8); finer cells mean fewer candidates
                       per neighbour and more rows of cells to visit. auto (default):
                       in 3D quarter where h >= 2 dp, dp where 1.5 dp < h < 2 dp
                       (DualSPHysics' default coefh 1 gives 1.73 dp), else third; h
                       in 2D; or the next coarser mode if the grid would exceed 16
                       cells per particle + 2^20 or a 32-bit packed cell
  -skin:F              skin of the neighbour cells, a fraction 0 <= F <= 0.5 of the cell
                       size (default 0.25 for cases of fewer than 262,144 particles,
                       else 0.05): particles keep their cell while they stay within F
                       cells of it, and the particles are sorted again only when one
                       leaves (an excluded particle leaves the run in its slot until
                       then); the search reaches F further.
                       0: sorted twice per step, as DualSPHysics. Results depend on it
                       at rounding level (the neighbour order), so hashes compare runs
                       of the same skin
  -cellswitch:F        a 3D run whose automatic cells are one particle spacing wide and
                       centred on the fluid's lattice (2h/3 where h = 1.5 dp, dp where
                       1.5 dp < h < 2 dp) switches to cells of h, once, at the first
                       sort after which more than F of the fluid shares its cell with
                       another fluid particle (none does on the lattice): the lattice's
                       cells test the fewest candidates, cells of h keep more of a
                       violent flow's pair threads busy. Default 0.3; 0: never.
                       Results depend on it at rounding level (the neighbour order)
  -pairlanes:N         pair lanes of the fluid loop, 1, 2, 4 or 8: each fluid particle's
                       candidates are split over N partial sums, added pairwise at the
                       end; the GPU runs one thread per lane, so small cases get more
                       threads. 0 (default, auto): 4 below 49,152 fluid particles, 2
                       below 98,304, else 1. Results
                       depend on it at rounding level, so hashes compare runs of the
                       same lanes
  -vcpmsubsteps:N      VCPM solids: N >= 1 solid sub-steps per fluid step instead of
                       int(dt_F/dt_S)+1 (convergence studies; 0: automatic). The solid
                       is unstable when dt_F/N exceeds its stability limit
  -progress:S          a progress line every S >= 0 seconds of wall time (default 1; 0: none)
  -quiet               no banner or progress lines (summary and errors only)
Physics (override the case's <parameters>):
  -symplectic          symplectic time integration (StepAlgorithm=2)
  -verlet[:N]          Verlet, an Euler step every N >= 1 steps (StepAlgorithm=1, VerletSteps=N)
  -wendland            Wendland C2 kernel (Kernel=2)
  -cubic               cubic spline kernel (Kernel=1)
  -viscoart:A          artificial viscosity, alpha A >= 0 (ViscoTreatment=1, Visco=A)
  -viscolam:NU         laminar viscosity NU >= 0 [m^2/s] (ViscoTreatment=3, Visco=NU)
  -viscolamsps:NU      laminar viscosity + SPS turbulence (ViscoTreatment=2, Visco=NU)
  -viscoboundfactor:F  viscosity factor F >= 0 for fluid-boundary pairs (ViscoBoundFactor)
  -ddt:K               density diffusion: 0 none, 1 Molteni, 2 Fourtakas, 3 Fourtakas full
                       (DensityDT)
  -ddtvalue:D          density diffusion coefficient delta D >= 0 (DensityDTvalue)
  -cfl:C               Courant number, 0 < C <= 1 (the case's cflnumber)
  -dtfixed:DT          constant time step DT > 0 [s] (DtFixed)
  -vcpmcoupling:K      VCPM coupling: 1 staggered as seed 000, 2 staggered midpoint
                       (VcpmCoupling, SeaSpring)
  -vcpmdtcoef:F        VCPM solid sub-step coefficient, 0 < F <= 2 (VcpmDtCoef, SeaSpring)
Other:
  -h, -help, --help    this text
  -version             the version
Each option may be given once; -gpu/-cpu, -symplectic/-verlet, -wendland/-cubic and the
three viscosity options exclude each other.

Output: OUTDIR/parts.xdmf (ParaView time series of OUTDIR/data/part_NNNN.h5),
OUTDIR/run.json (run summary, written on every exit once the run has started) and
OUTDIR/Run.out (the console).
Exit codes: 0 success; 2 bad command line or input; 1 failure during the run (a blow-up:
run.json's "blowup" says which particles, where, which quantity and the likely option; the
last good state is kept as a part file); 130 stopped by SIGINT, 143 by SIGTERM (run.json
and the last state written).
)";
}

void applyOverrides(const RunOptions& o, SolverParameters& p) {
    if (o.step_algorithm) p.step_algorithm = *o.step_algorithm;
    if (o.vcpm_coupling) p.vcpm_coupling = *o.vcpm_coupling;
    if (o.vcpm_dt_coef) p.vcpm_dt_coef = *o.vcpm_dt_coef;
    if (o.verlet_steps) p.verlet_steps = *o.verlet_steps;
    if (o.kernel) p.kernel = *o.kernel;
    if (o.visco_treatment) p.visco_treatment = *o.visco_treatment;
    if (o.visco) p.visco = *o.visco;
    if (o.visco_bound_factor) p.visco_bound_factor = *o.visco_bound_factor;
    if (o.ddt) p.density_dt = *o.ddt;
    if (o.ddt_value) p.density_dt_value = *o.ddt_value;
    if (o.cfl) p.cfl_number = *o.cfl;
    if (o.dt_fixed) p.dt_fixed = *o.dt_fixed;
    if (o.tmax) p.time_max = *o.tmax;
    if (o.tout) p.time_out = *o.tout;
}

}  // namespace seaspring::solver
