// SeaSpring — MIT licence.
/// \file simulation_domain.h
/// \brief `<simulationdomain>`: the box the solver keeps particles in, from the particles'
///        bounding box and the forms `default`, `default + v`, `default - v%`, a number or
///        `#expression`.
#pragma once

#include <pugixml.hpp>

#include "case/parameters.h"
#include "case/xml_source.h"
#include "core/vec3.h"
#include "gencase/expression.h"

namespace seaspring::gencase {

using model::DomainBox;
using model::XmlSource;

/// `node` may be empty (then the domain is the bounding box). Percentages are of the
/// bounding box size along that axis.
DomainBox resolveSimulationDomain(const XmlSource& src, pugi::xml_node node,
                                  const ExpressionEvaluator& ev, const DomainBox& particles_box);

}  // namespace seaspring::gencase
