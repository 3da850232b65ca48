// SeaSpring — MIT licence.
/// \file constants.cpp
#include "gencase/constants.h"
#include "core/format.h"

#include <cmath>
#include <cstdio>
#include <ostream>

#include "core/error.h"
#include "physics/eos_tait.h"

namespace seaspring::gencase {

namespace {

AutoValue readAuto(const XmlSource& src, pugi::xml_node n, const ExpressionEvaluator& ev) {
    src.checkAttributes(n, {"value", "auto"});
    AutoValue v;
    v.automatic = src.boolean(n, "auto", false);
    v.value = src.number(n, "value", ev, 0.0);
    if (!v.automatic && !n.attribute("value")) src.fail(n, "needs value=\"...\" when auto is false");
    return v;
}

double readValue(const XmlSource& src, pugi::xml_node n, const ExpressionEvaluator& ev) {
    src.checkAttributes(n, {"value"});
    return src.number(n, "value", ev);
}

}  // namespace

ConstantsInput parseConstantsDef(const XmlSource& src, pugi::xml_node node,
                                 const ExpressionEvaluator& ev) {
    ConstantsInput in;
    src.checkChildren(node, {"lattice", "gravity", "rhop0", "rhopgradient", "hswl", "gamma",
                             "speedsystem", "coefsound", "speedsound", "coefh", "hdp",
                             "cflnumber", "h", "b", "massbound", "massfluid"});
    bool has_coefh = false;
    for (pugi::xml_node n : node.children()) {
        if (XmlSource::isDisabled(n)) continue;
        const std::string name = n.name();
        if (name == "lattice") {
            src.checkAttributes(n, {"bound", "fluid"});
            in.lattice_bound = src.integer(n, "bound", ev, 1);
            in.lattice_fluid = src.integer(n, "fluid", ev, 1);
            if (in.lattice_bound != 1 || in.lattice_fluid != 1)
                src.fail(n, "only lattice 1 (simple cubic) is supported; got bound=" +
                                std::to_string(in.lattice_bound) + " fluid=" + std::to_string(in.lattice_fluid));
        } else if (name == "gravity") {
            src.checkAttributes(n, {"x", "y", "z"});
            in.gravity = src.vec3(n, ev);
        } else if (name == "rhop0") {
            in.rhop0 = readValue(src, n, ev);
            if (!(in.rhop0 > 0)) src.fail(n, "value=" + exactText(in.rhop0) + ": must be > 0");
        } else if (name == "rhopgradient") {
            src.checkAttributes(n, {"value"});
            in.rhopgradient = src.integer(n, "value", ev);
            if (in.rhopgradient < 1 || in.rhopgradient > 3)
                src.fail(n, "value=" + std::to_string(in.rhopgradient) + ": expected 1, 2 or 3");
        } else if (name == "gamma") {
            in.gamma = readValue(src, n, ev);
            if (!(in.gamma > 0)) src.fail(n, "value=" + exactText(in.gamma) + ": must be > 0");
        } else if (name == "coefsound") {
            in.coefsound = readValue(src, n, ev);
        } else if (name == "coefh") {
            in.coefh = readValue(src, n, ev);
            has_coefh = true;
            if (!(in.coefh > 0)) src.fail(n, "value=" + exactText(in.coefh) + ": must be > 0");
        } else if (name == "hdp") {
            in.hdp = readValue(src, n, ev);
            if (!(in.hdp > 0)) src.fail(n, "value=" + exactText(in.hdp) + ": must be > 0");
        } else if (name == "cflnumber") {
            in.cflnumber = readValue(src, n, ev);
            if (!(in.cflnumber > 0)) src.fail(n, "value=" + exactText(in.cflnumber) + ": must be > 0");
        } else {
            AutoValue v = readAuto(src, n, ev);
            if (name == "hswl") in.hswl = v;
            else if (name == "speedsystem") in.speedsystem = v;
            else if (name == "speedsound") in.speedsound = v;
            else if (name == "h") in.h = v;
            else if (name == "b") in.b = v;
            else if (name == "massbound") in.massbound = v;
            else in.massfluid = v;
        }
    }
    if (has_coefh && in.hdp > 0)
        src.fail(node, "gives both <coefh> and <hdp>: use one (prefix the other with '_')");
    return in;
}

CaseConstants computeConstants(const ConstantsInput& in, double dp, bool two_d, double fluid_height) {
    CaseConstants c;
    c.dimensions = two_d ? 2 : 3;
    c.dp = dp;
    c.gravity = in.gravity;
    c.rhop0 = in.rhop0;
    c.gamma = in.gamma;
    c.cflnumber = in.cflnumber;
    c.coefsound = in.coefsound;
    c.coefh = in.hdp > 0 ? 0.0 : in.coefh;
    c.hdp = in.hdp;
    c.rhopgradient = in.rhopgradient;
    const double g = std::sqrt(dot(in.gravity, in.gravity));
    c.hswl = in.hswl.automatic ? fluid_height : in.hswl.value;
    c.speedsystem = in.speedsystem.automatic ? std::sqrt(g * c.hswl) : in.speedsystem.value;
    c.speedsound = in.speedsound.automatic
                       ? std::max(in.coefsound * c.speedsystem, 10.0 * std::sqrt(g * c.hswl))
                       : in.speedsound.value;
    if (in.h.automatic)
        c.h = in.hdp > 0 ? in.hdp * dp : in.coefh * std::sqrt((two_d ? 2.0 : 3.0) * dp * dp);
    else
        c.h = in.h.value;
    c.b = in.b.automatic ? physics::taitB(c.speedsound, c.rhop0, c.gamma) : in.b.value;
    const double volume = two_d ? dp * dp : dp * dp * dp;
    c.massbound = in.massbound.automatic ? c.rhop0 * volume : in.massbound.value;
    c.massfluid = in.massfluid.automatic ? c.rhop0 * volume : in.massfluid.value;
    return c;
}

void printConstants(std::ostream& os, const CaseConstants& c) {
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "Constants:\n"
                  "  Dimensions:   %dD\n"
                  "  Dp:           %g m\n"
                  "  Gravity:      (%g, %g, %g) m/s^2\n"
                  "  RhopZero:     %g kg/m^3\n"
                  "  HSwl:         %.6g m\n"
                  "  SpeedSystem:  %.6g m/s\n"
                  "  CoefSound:    %g\n"
                  "  SpeedSound:   %.6g m/s\n"
                  "  Gamma:        %g\n"
                  "  H:            %.6g m  (%s)\n"
                  "  B:            %.6g Pa\n"
                  "  MassFluid:    %.6g kg\n"
                  "  MassBound:    %.6g kg\n"
                  "  CFLnumber:    %g\n",
                  c.dimensions, c.dp, c.gravity.x, c.gravity.y, c.gravity.z, c.rhop0, c.hswl,
                  c.speedsystem, c.coefsound, c.speedsound, c.gamma, c.h,
                  c.hdp > 0 ? ("hdp=" + exactText(c.hdp)).c_str() : ("coefh=" + exactText(c.coefh)).c_str(),
                  c.b, c.massfluid, c.massbound, c.cflnumber);
    os << buf;
}

}  // namespace seaspring::gencase
