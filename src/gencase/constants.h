// SeaSpring — MIT licence.
/// \file constants.h
/// \brief `<constantsdef>`: read the user's values and derive h, c0, B and masses exactly as
///        DualSPHysics' GenCase does (the result, CaseConstants, is the case model's).
#pragma once

#include <iosfwd>

#include <pugixml.hpp>

#include "case/case_constants.h"
#include "case/xml_source.h"
#include "core/vec3.h"
#include "gencase/expression.h"

namespace seaspring::gencase {

using model::CaseConstants;
using model::XmlSource;

/// A value that GenCase either takes from the file or derives (`auto="true"`).
struct AutoValue {
    double value = 0;
    bool automatic = true;
};

/// What the user wrote in `<constantsdef>` (defaults as DualSPHysics).
struct ConstantsInput {
    int lattice_bound = 1, lattice_fluid = 1;
    Vec3d gravity{0, 0, -9.81};
    double rhop0 = 1000;
    int rhopgradient = 2;  ///< 1: rhop0, 2: water column, 3: maximum water height
    AutoValue hswl, speedsystem, speedsound, h, b, massbound, massfluid;
    double gamma = 7;
    double coefsound = 20;
    double coefh = 0.866025;
    double hdp = 0;  ///< >0: h = hdp*dp instead of coefh
    double cflnumber = 0.2;
};

ConstantsInput parseConstantsDef(const XmlSource& src, pugi::xml_node node,
                                 const ExpressionEvaluator& ev);

/// Derives the constants. `fluid_height` is max(z) - min(z) over fluid particles (0 without
/// fluid): GenCase's automatic hswl.
CaseConstants computeConstants(const ConstantsInput& in, double dp, bool two_d, double fluid_height);

void printConstants(std::ostream& os, const CaseConstants& c);

}  // namespace seaspring::gencase
