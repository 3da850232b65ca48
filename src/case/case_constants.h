// SeaSpring — MIT licence.
/// \file case_constants.h
/// \brief The derived constants of a case (dp, h, c0, B, masses, ...) as the resolved case
///        holds them in `<constants>`: written by gencase, read by the solver.
#pragma once

#include <pugixml.hpp>

#include "case/xml_source.h"
#include "core/vec3.h"

namespace seaspring::model {

/// Derived constants, as written to the resolved case (DualSPHysics' names and meaning).
struct CaseConstants {
    int dimensions = 3;
    double dp = 0;
    Vec3d gravity{0, 0, -9.81};
    double rhop0 = 1000, gamma = 7, cflnumber = 0.2, coefsound = 20, coefh = 0, hdp = 0;
    int rhopgradient = 2;
    double hswl = 0, speedsystem = 0, speedsound = 0;
    double h = 0, b = 0, massbound = 0, massfluid = 0;
};

/// Appends `<constants>` with every value (full precision) to `parent`.
void writeConstants(pugi::xml_node parent, const CaseConstants& c);
/// Reads a `<constants>` written by writeConstants (every value required, plain numbers).
CaseConstants readConstants(const XmlSource& src, pugi::xml_node constants);

}  // namespace seaspring::model
