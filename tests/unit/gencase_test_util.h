// SeaSpring — MIT licence.
/// \file gencase_test_util.h
/// \brief Helpers for gencase tests: write a case to a scratch file, build it in memory, or
///        run the gencase binary and capture its exit code and output.
#pragma once

#include <string>

#include "gencase/case_builder.h"

namespace seaspring::test {

/// A fresh scratch directory under the system temp directory (removed at exit of the test).
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

}  // namespace seaspring::test
