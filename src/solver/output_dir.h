// SeaSpring — MIT licence.
/// \file output_dir.h
/// \brief OUTDIR never mixes two runs: before a run starts, the files an earlier run left there
///        (Run.out, run.json, parts.xdmf, ledger.csv, data/, vtk/, gauges/) are either refused
///        or, with -overwrite, removed. Other files (the case written by gencase, which usually
///        lives in OUTDIR too) are never touched.
#pragma once

#include <string>
#include <vector>

namespace seaspring::solver {

/// The names (relative to OUTDIR) of an earlier run's files and folders present in `outdir`.
std::vector<std::string> earlierRunFiles(const std::string& outdir);

/// Makes OUTDIR ready for a new run: creates it when missing; when it holds an earlier run,
/// throws seaspring::Error naming OUTDIR and what is there unless `overwrite`, in which case
/// those files and folders are removed. Returns what was removed.
std::vector<std::string> prepareOutputDir(const std::string& outdir, bool overwrite);

}  // namespace seaspring::solver
