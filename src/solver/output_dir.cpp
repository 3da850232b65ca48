// SeaSpring — MIT licence.
/// \file output_dir.cpp
/// \brief An earlier run in OUTDIR is refused or cleared (see output_dir.h).
#include "solver/output_dir.h"

#include <filesystem>
#include <system_error>

#include "core/error.h"

namespace seaspring::solver {

namespace fs = std::filesystem;

namespace {
/// What a run writes into OUTDIR (docs/solver.md, Outputs).
const char* const kRunEntries[] = {"Run.out", "run.json", "parts.xdmf", "ledger.csv", "data", "vtk", "gauges"};
}  // namespace

std::vector<std::string> earlierRunFiles(const std::string& outdir) {
    std::vector<std::string> found;
    std::error_code ec;
    for (const char* e : kRunEntries)
        if (fs::exists(fs::path(outdir) / e, ec)) found.push_back(e);
    return found;
}

std::vector<std::string> prepareOutputDir(const std::string& outdir, bool overwrite) {
    std::error_code ec;
    if (fs::exists(outdir, ec) && !fs::is_directory(outdir, ec))
        throw Error(outdir + ": OUTDIR exists and is not a folder");
    const std::vector<std::string> found = earlierRunFiles(outdir);
    if (!found.empty() && !overwrite) {
        std::string list;
        for (const std::string& f : found) list += (list.empty() ? "" : ", ") + f;
        throw Error(outdir + ": OUTDIR holds an earlier run (" + list +
                    "); give -overwrite to remove those files first, or choose another OUTDIR");
    }
    for (const std::string& f : found) {
        fs::remove_all(fs::path(outdir) / f, ec);
        if (ec) throw Error((fs::path(outdir) / f).string() + ": cannot remove (" + ec.message() + ")");
    }
    fs::create_directories(outdir, ec);
    if (ec) throw Error(outdir + ": cannot create OUTDIR (" + ec.message() + ")");
    return found;
}

}  // namespace seaspring::solver
