// SeaSpring — MIT licence.
/// \file run_options.cpp
/// \brief Parsing of the DualSPHysics-style command line. Options are `-name` or
///        `-name:value`; `--help`, `-h`, `-help` print the help.
#include "solver/run_options.h"

#include <cerrno>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/error.h"

namespace seaspring::solver {

namespace {

[[noreturn]] void bad(const std::string& arg, const std::string& why) {
    throw Error("bad option " + arg + ": " + why);
}

double toNumber(const std::string& arg, const std::string& v) {
    if (v.empty()) bad(arg, "a value is required (-name:value)");
    char* end = nullptr;
    errno = 0;
    const double d = std::strtod(v.c_str(), &end);
    if (end != v.c_str() + v.size() || errno != 0 || !(d == d)) bad(arg, "\"" + v + "\" is not a number");
    return d;
}

long long toInteger(const std::string& arg, const std::string& v) {
    if (v.empty()) bad(arg, "a value is required (-name:value)");
    char* end = nullptr;
    errno = 0;
    const long long i = std::strtoll(v.c_str(), &end, 10);
    if (end != v.c_str() + v.size() || errno != 0) bad(arg, "\"" + v + "\" is not an integer");
    return i;
}

}  // namespace

std::string runOptionsHelp() {
    return R"(Usage: seaspring [options] OUTDIR/NAME OUTDIR
Runs the case OUTDIR/NAME (written by gencase) and writes the results to OUTDIR.

Backend:
  -gpu[:ID]          run on CUDA device ID (default 0); an error when no GPU is usable
  -cpu               run on the CPU (OpenMP)
  -threads:N         OpenMP threads for -cpu (default: all cores)
  (default: the GPU when one is usable, else the CPU)
Run control:
  -tmax:T            simulated time [s] (overrides TimeMax)
  -tout:T            output interval [s] (overrides TimeOut)
  -nsteps:N          stop after N time steps (tests, benchmarks)
  -sv:LIST           outputs: h5, vtk, none, comma-separated (default h5)
  -cellmode:full|h   neighbour cells of 2h or h (default h)
  -progress:S        progress line every S seconds of wall time (default 1; 0 = off)
  -quiet             no banner or progress lines (summary and errors only)
Physics (override the case's <parameters>):
  -symplectic        symplectic time integration (StepAlgorithm=2)
  -verlet[:N]        Verlet with an Euler step every N steps (StepAlgorithm=1, VerletSteps=N)
  -wendland          Wendland C2 kernel (Kernel=2)
  -cubic             cubic spline kernel (Kernel=1)
  -viscoart:A        artificial viscosity with alpha A (ViscoTreatment=1, Visco=A)
  -viscolam:NU       laminar viscosity NU [m^2/s] (ViscoTreatment=3)
  -viscolamsps:NU    laminar viscosity + SPS turbulence (ViscoTreatment=2)
  -viscoboundfactor:F  viscosity factor for fluid-boundary pairs
  -ddt:K             density diffusion 0 none, 1 Molteni, 2 Fourtakas, 3 Fourtakas full
  -ddtvalue:D        density diffusion coefficient delta
  -cfl:C             Courant number, 0 < C <= 1
  -dtfixed:DT        constant time step [s]
Other:
  -h, -help, --help  this text
  -version           the version
Output: OUTDIR/parts.xdmf (ParaView time series), OUTDIR/data/part_NNNN.h5, OUTDIR/run.json.
Exit codes: 0 success, 2 bad command line or input, 1 failure during the run.
)";
}

RunOptions parseRunOptions(int argc, const char* const* argv) {
    RunOptions o;
    std::vector<std::string> positional;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--help" || arg == "-h" || arg == "-help") {
            o.help = true;
            continue;
        }
        if (arg == "-version" || arg == "--version") {
            o.version = true;
            continue;
        }
        if (arg.size() < 2 || arg[0] != '-') {
            positional.push_back(arg);
            continue;
        }
        const auto colon = arg.find(':');
        const std::string name = arg.substr(1, colon == std::string::npos ? std::string::npos : colon - 1);
        const bool has_value = colon != std::string::npos;
        const std::string value = has_value ? arg.substr(colon + 1) : "";
        auto noValue = [&] {
            if (has_value) bad(arg, "takes no value");
        };
        if (name == "gpu") {
            o.backend = RunOptions::Backend::Gpu;
            if (has_value) {
                const long long id = toInteger(arg, value);
                if (id < 0 || id > 1024) bad(arg, "the device id must be >= 0");
                o.gpu_id = int(id);
            }
        } else if (name == "cpu") {
            noValue();
            o.backend = RunOptions::Backend::Cpu;
        } else if (name == "threads") {
            const long long n = toInteger(arg, value);
            if (n < 1 || n > 4096) bad(arg, "the thread count must be >= 1");
            o.threads = int(n);
        } else if (name == "tmax") {
            o.tmax = toNumber(arg, value);
            if (!(*o.tmax > 0)) bad(arg, "must be > 0");
        } else if (name == "tout") {
            o.tout = toNumber(arg, value);
            if (!(*o.tout > 0)) bad(arg, "must be > 0");
        } else if (name == "nsteps") {
            o.nsteps = toInteger(arg, value);
            if (*o.nsteps < 0) bad(arg, "must be >= 0");
        } else if (name == "sv") {
            o.save_h5 = o.save_vtk = false;
            std::string rest = value;
            if (rest.empty()) bad(arg, "a list is required (h5, vtk, none)");
            while (!rest.empty()) {
                const auto comma = rest.find(',');
                const std::string item = rest.substr(0, comma);
                rest = comma == std::string::npos ? "" : rest.substr(comma + 1);
                if (item == "h5") o.save_h5 = true;
                else if (item == "vtk") o.save_vtk = true;
                else if (item == "none") continue;
                else bad(arg, "unknown output \"" + item + "\" (h5, vtk, none)");
            }
        } else if (name == "cellmode") {
            if (value == "full" || value == "2h") o.cell_div = 1;
            else if (value == "h" || value == "half") o.cell_div = 2;
            else bad(arg, "use -cellmode:full or -cellmode:h");
        } else if (name == "progress") {
            o.progress_interval = toNumber(arg, value);
            if (o.progress_interval < 0) bad(arg, "must be >= 0");
        } else if (name == "quiet") {
            noValue();
            o.quiet = true;
        } else if (name == "symplectic") {
            noValue();
            o.step_algorithm = 2;
        } else if (name == "verlet") {
            o.step_algorithm = 1;
            if (has_value) {
                const long long n = toInteger(arg, value);
                if (n < 1) bad(arg, "must be >= 1");
                o.verlet_steps = int(n);
            }
        } else if (name == "wendland") {
            noValue();
            o.kernel = 2;
        } else if (name == "cubic") {
            noValue();
            o.kernel = 1;
        } else if (name == "viscoart" || name == "viscolam" || name == "viscolamsps") {
            o.visco = toNumber(arg, value);
            if (*o.visco < 0) bad(arg, "must be >= 0");
            o.visco_treatment = name == "viscoart" ? 1 : name == "viscolamsps" ? 2 : 3;
        } else if (name == "viscoboundfactor") {
            o.visco_bound_factor = toNumber(arg, value);
            if (*o.visco_bound_factor < 0) bad(arg, "must be >= 0");
        } else if (name == "ddt") {
            const long long k = toInteger(arg, value);
            if (k < 0 || k > 3) bad(arg, "use 0 (none), 1 (Molteni), 2 (Fourtakas) or 3 (Fourtakas full)");
            o.ddt = int(k);
        } else if (name == "ddtvalue") {
            o.ddt_value = toNumber(arg, value);
            if (*o.ddt_value < 0) bad(arg, "must be >= 0");
        } else if (name == "cfl") {
            o.cfl = toNumber(arg, value);
            if (!(*o.cfl > 0 && *o.cfl <= 1)) bad(arg, "must be in (0, 1]");
        } else if (name == "dtfixed") {
            o.dt_fixed = toNumber(arg, value);
            if (!(*o.dt_fixed > 0)) bad(arg, "must be > 0");
        } else {
            bad(arg, "unknown option");
        }
    }
    if (o.help || o.version) return o;
    if (positional.size() != 2)
        throw Error("expected OUTDIR/NAME and OUTDIR (got " + std::to_string(positional.size()) +
                    " arguments): seaspring [options] OUTDIR/NAME OUTDIR");
    o.case_path = positional[0];
    o.outdir = positional[1];
    return o;
}

void applyOverrides(const RunOptions& o, SolverParameters& p) {
    if (o.step_algorithm) p.step_algorithm = *o.step_algorithm;
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
