// SeaSpring — MIT licence.
/// \file vcpm_solids.h
/// \brief `<special><vcpmsolids>`: which boundary MKs are VCPM lattice solids, their
///        material and their clamps. DualSPHysics' `<flexstrucs>` bodies are accepted too and
///        modelled as VCPM solids (their constitutive model and hourglass factor do not apply).
///        The bodies are the case model's SolidBody (case/solid_body.h).
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include <pugixml.hpp>

#include "case/solid_body.h"
#include "case/xml_source.h"
#include "gencase/command_runner.h"
#include "gencase/expression.h"

namespace seaspring::gencase {

using model::PointLoad;
using model::SolidBody;
using model::XmlSource;

/// Reads `<vcpmsolids>` and `<flexstrucs>` inside `<special>` (either may be absent) of a case
/// of `dim` dimensions (constitmodel must fit it).
std::vector<SolidBody> parseSolids(const XmlSource& src, pugi::xml_node special,
                                   const ExpressionEvaluator& ev, const MkConfig& mk, int dim,
                                   std::ostream& log);

/// Parses an MK list "1", "0,2-3" into numbers; throws via src.fail on bad syntax.
std::vector<int> parseMkList(const XmlSource& src, pugi::xml_node node, const char* attr);

}  // namespace seaspring::gencase
