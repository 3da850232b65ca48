// SeaSpring — MIT licence.
/// \file vcpm_solids.h
/// \brief `<special><vcpmsolids>`: which boundary MKs are VCPM lattice solids, their
///        material and their clamps. DualSPHysics' `<flexstrucs>` bodies are accepted too and
///        modelled as VCPM solids (their constitutive model and hourglass factor do not apply).
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include <pugixml.hpp>

#include "gencase/command_runner.h"
#include "gencase/expression.h"
#include "gencase/xml_source.h"

namespace seaspring::gencase {

/// A concentrated force on the solid particle nearest to `point` (initial configuration):
/// F(t) = force + rate * t [N] (2D: N per m of thickness).
struct PointLoad {
    double x = 0, y = 0, z = 0;
    double fx = 0, fy = 0, fz = 0;
    double ratex = 0, ratey = 0, ratez = 0;
    int line = 0;
};

struct SolidSpec {
    int mkbound = 0;
    std::uint16_t mk = 0;                 ///< global MK
    std::vector<int> clamp_mkbound;
    std::vector<std::uint16_t> clamp_mk;  ///< global MKs
    double density = 0;                   ///< rho_S [kg/m^3]
    double youngmod = 0;                  ///< E [Pa]
    double poissratio = 0;                ///< nu, in (-1, 0.5)
    double critstretch = 0;               ///< bond breaks at elongation/rest length > this; 0: never
    double damping = 0;                   ///< multiplies sqrt(E/(rho dp^2)); 0: no damping
    int line = 0;
    std::string declared_in;              ///< "vcpmsolids" or "flexstrucs"
    std::vector<PointLoad> loads;         ///< <pointload> children
};

/// Reads `<vcpmsolids>` and `<flexstrucs>` inside `<special>` (either may be absent).
std::vector<SolidSpec> parseSolids(const XmlSource& src, pugi::xml_node special,
                                   const ExpressionEvaluator& ev, const MkConfig& mk,
                                   std::ostream& log);

/// Parses an MK list "1", "0,2-3" into numbers; throws via src.fail on bad syntax.
std::vector<int> parseMkList(const XmlSource& src, pugi::xml_node node, const char* attr);

}  // namespace seaspring::gencase
