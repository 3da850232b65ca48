// SeaSpring — MIT licence.
/// \file run_report.h
/// \brief OUTDIR/run.json (the machine-readable run summary) and the closing summary lines.
#pragma once

#include <iosfwd>
#include <string>

#include "solver/simulation.h"

namespace seaspring::solver {

/// Writes the summary as JSON to `path` (atomically).
void writeRunJson(const std::string& path, const RunSummary& s);
/// "Memory: GPU arrays at most M MiB (B bytes per particle) of the device's T MiB; host peak H MiB
/// (B bytes per particle)\n" (the GPU part on the GPU only).
std::string memoryLine(const RunSummary& s);
/// Human-readable end-of-run lines.
void printSummary(std::ostream& os, const RunSummary& s);

}  // namespace seaspring::solver
