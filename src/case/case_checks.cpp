// SeaSpring — MIT licence.
/// \file case_checks.cpp
/// \brief The solver's checks of a case, shared with gencase (see case_checks.h).
#include "case/case_checks.h"

#include <cmath>
#include <string>

#include "core/format.h"

namespace seaspring::model {

void checkCaseConstants(const XmlSource& src, pugi::xml_node node, pugi::xml_node fallback, const CaseConstants& c,
                        bool has_fluid, bool has_boundary) {
    auto bad = [&](const char* name, double v, const std::string& why) {
        pugi::xml_node n = node ? node.child(name) : pugi::xml_node();
        if (!n) n = node ? node : fallback;
        src.fail(n, std::string(n.name() == std::string(name) ? "" : std::string(name) + " ") + "value=" +
                        shortText(v) + ": " + why);
    };
    const struct {
        const char* name;
        double v;
    } values[] = {{"gravity", c.gravity.x}, {"gravity", c.gravity.y}, {"gravity", c.gravity.z},
                  {"dp", c.dp},             {"rhop0", c.rhop0},       {"gamma", c.gamma},
                  {"cflnumber", c.cflnumber}, {"hswl", c.hswl},       {"speedsystem", c.speedsystem},
                  {"speedsound", c.speedsound}, {"h", c.h},           {"b", c.b},
                  {"massbound", c.massbound}, {"massfluid", c.massfluid}};
    for (const auto& e : values)
        if (!std::isfinite(e.v)) bad(e.name, e.v, "is not finite (check gravity, hswl, coefsound and dp)");
    if (c.dimensions != 2 && c.dimensions != 3) bad("dimensions", c.dimensions, "must be 2 or 3");
    if (!(c.dp > 0)) bad("dp", c.dp, "must be > 0");
    if (!(c.h > 0)) bad("h", c.h, "must be > 0");
    if (!(c.rhop0 > 0)) bad("rhop0", c.rhop0, "must be > 0");
    if (c.gamma != 7) bad("gamma", c.gamma, "is not supported by seaspring (supported: 7)");
    if (!(c.cflnumber > 0 && c.cflnumber <= 1)) bad("cflnumber", c.cflnumber, "must lie in (0, 1]");
    if (has_fluid && !(c.speedsound > 0)) bad("speedsound", c.speedsound, "must be > 0");
    if (has_fluid && !(c.b > 0)) bad("b", c.b, "must be > 0");
    if (!(c.speedsound >= 0)) bad("speedsound", c.speedsound, "must be >= 0");
    if (!(c.b >= 0)) bad("b", c.b, "must be >= 0");
    if (has_fluid && !(c.massfluid > 0)) bad("massfluid", c.massfluid, "must be > 0");
    if (has_boundary && !(c.massbound > 0)) bad("massbound", c.massbound, "must be > 0");
}

void checkCaseHasWork(const XmlSource& src, pugi::xml_node node, std::size_t nfluid, std::size_t nsolid) {
    if (nfluid == 0 && nsolid == 0)
        src.fail(node, "the case has neither fluid nor VCPM solid particles: there is nothing to simulate "
                       "(draw fluid with setmkfluid, or declare a solid in <vcpmsolids>)");
}

}  // namespace seaspring::model
