// SeaSpring — MIT licence.
/// \file case_checks.h
/// \brief The checks the solver makes on a case, in one place: gencase runs the same ones before
///        it writes anything, so that it never writes a case seaspring would reject.
///
/// Each takes the XML element the values came from (the resolved case's `<constants>` in the
/// solver, the definition's `<constantsdef>` in gencase) so that a message names the file, the
/// line and the value.
#pragma once

#include <cstddef>

#include <pugixml.hpp>

#include "case/case_constants.h"
#include "case/xml_source.h"

namespace seaspring::model {

/// The constants: every value finite (gravity -1e300 gives an infinite B); dimensions 2 or 3;
/// dp, h, rhop0 > 0; gamma 7; cflnumber in (0, 1]; with fluid, speedsound, b and massfluid > 0
/// (a case without fluid needs no speed of sound); with fixed or moving boundaries, massbound > 0.
/// A message names `node`'s child of the constant's name, else `node`, else `fallback`.
void checkCaseConstants(const XmlSource& src, pugi::xml_node node, pugi::xml_node fallback, const CaseConstants& c,
                        bool has_fluid, bool has_boundary);

/// A case must hold fluid or VCPM solid particles: without either there is nothing to simulate.
void checkCaseHasWork(const XmlSource& src, pugi::xml_node node, std::size_t nfluid, std::size_t nsolid);

}  // namespace seaspring::model
