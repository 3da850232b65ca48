// SeaSpring — MIT licence.
/// \file constants.h
/// \brief `<constantsdef>`: read the user's values and derive h, c0, B and masses exactly as
///        DualSPHysics' GenCase does.
#pragma once

#include <iosfwd>

#include <pugixml.hpp>

#include "core/vec3.h"
#include "gencase/expression.h"
#include "gencase/xml_source.h"

namespace seaspring::gencase {

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

/// Derived constants, as written to the resolved case.
struct CaseConstants {
    int dimensions = 3;
    double dp = 0;
    Vec3d gravity{0, 0, -9.81};
    double rhop0 = 1000, gamma = 7, cflnumber = 0.2, coefsound = 20, coefh = 0, hdp = 0;
    int rhopgradient = 2;
    double hswl = 0, speedsystem = 0, speedsound = 0;
    double h = 0, b = 0, massbound = 0, massfluid = 0;
};

ConstantsInput parseConstantsDef(const XmlSource& src, pugi::xml_node node,
                                 const ExpressionEvaluator& ev);

/// Derives the constants. `fluid_height` is max(z) - min(z) over fluid particles (0 without
/// fluid): GenCase's automatic hswl.
CaseConstants computeConstants(const ConstantsInput& in, double dp, bool two_d, double fluid_height);

void printConstants(std::ostream& os, const CaseConstants& c);
/// Appends `<constants>` with every value (full precision) to `parent`.
void writeConstants(pugi::xml_node parent, const CaseConstants& c);
CaseConstants readConstants(const XmlSource& src, pugi::xml_node constants);

}  // namespace seaspring::gencase
