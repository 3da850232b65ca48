// SeaSpring — MIT licence.
/// \file gencase_test_util.h
/// \brief Helpers for gencase tests: write a case to a scratch file, build it in memory, or
///        run the gencase binary and capture its exit code and output.
#pragma once

#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "gencase/case_builder.h"

namespace seaspring::test {

/// A pool for caseXml's mainlist. Floor (mkbound 0): z = -0.2, x and y in 0..0.4; water
/// (mkfluid 0): x, y, z in 0..0.4. All bounds are multiples of 0.2, so it also works at
/// dp = 0.2. dp 0.1: floor 5*5 = 25, water 5*5*5 = 125 -> 150; dp 0.2: floor 3*3 = 9, water
/// 3*3*3 = 27 -> 36.
inline constexpr const char* kPool =
    "<setmkbound mk=\"0\"/><drawbox><boxfill>solid</boxfill><point x=\"0\" y=\"0\" z=\"-0.2\"/>"
    "<size x=\"0.4\" y=\"0.4\" z=\"0\"/></drawbox>\n"
    "<setmkfluid mk=\"0\"/><drawbox><boxfill>solid</boxfill><point x=\"0\" y=\"0\" z=\"0\"/>"
    "<size x=\"0.4\" y=\"0.4\" z=\"0.4\"/></drawbox>";

/// A fresh scratch directory under the system temp directory (emptied when created again;
/// left in place afterwards for inspection).
std::string scratchDir(const std::string& tag);
/// Writes `text` to dir/name and returns the path.
std::string writeFile(const std::string& dir, const std::string& name, const std::string& text);

/// A minimal case around `mainlist` commands (dp, 3D or 2D domain, optional extra XML
/// inside <casedef> after <geometry> and inside <execution><special>).
std::string caseXml(const std::string& mainlist, double dp = 0.1, bool two_d = false,
                    const std::string& casedef_extra = "", const std::string& special = "",
                    const std::string& parameters = "");

/// Builds the case in memory (throws seaspring::Error on bad input).
gencase::GeneratedCase buildCase(const std::string& def_path, double dp = 0);

struct CommandResult {
    int exit_code;
    std::string output;  ///< stdout and stderr together
};
CommandResult runGencase(const std::string& args);

/// Builds the case in memory and keeps the builder (for source(), result(), write());
/// `log` must outlive the builder. Throws seaspring::Error on bad input.
std::unique_ptr<gencase::CaseBuilder> buildCaseKeepBuilder(const std::string& def_path,
                                                           std::ostream& log, double dp = 0);
/// The message of the seaspring::Error that buildCase throws, or "" when it succeeds.
std::string buildError(const std::string& def_path, double dp = 0);
/// 1-based line of the first occurrence of `needle` in `text` (0 when absent).
int lineOf(const std::string& text, const std::string& needle);
/// Regular files under `dir` (recursive), as paths relative to `dir`, sorted; empty when
/// `dir` does not exist.
std::vector<std::string> listFiles(const std::string& dir);

}  // namespace seaspring::test
