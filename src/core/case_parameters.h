// SeaSpring — MIT licence.
/// \file case_parameters.h
/// \brief The `<parameters>` keys of a DualSPHysics case: names, defaults and meaning.
///
/// gencase validates a case's keys against this table and writes every key, defaults
/// filled in, to the resolved case; the solver reads them from there.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace seaspring {

enum class ParameterKind { Number, Text, Deprecated };

struct ParameterInfo {
    const char* key;
    const char* default_value;  ///< nullptr: required
    ParameterKind kind;
    const char* meaning;
};

/// Every key SeaSpring knows, in the order they are written.
const std::vector<ParameterInfo>& knownParameters();
/// nullptr when unknown.
const ParameterInfo* findParameter(const std::string& key);

}  // namespace seaspring
