// SeaSpring — MIT licence.
/// \file case_constants.cpp
#include "case/case_constants.h"

#include <cstdio>
#include <string>
#include "core/format.h"

namespace seaspring::model {

void writeConstants(pugi::xml_node parent, const CaseConstants& c) {
    pugi::xml_node n = parent.append_child("constants");
    auto value = [&](const char* name, double v) {
        n.append_child(name).append_attribute("value") = exactText(v).c_str();
    };
    n.append_child("dimensions").append_attribute("value") = c.dimensions;
    value("dp", c.dp);
    pugi::xml_node gr = n.append_child("gravity");
    gr.append_attribute("x") = exactText(c.gravity.x).c_str();
    gr.append_attribute("y") = exactText(c.gravity.y).c_str();
    gr.append_attribute("z") = exactText(c.gravity.z).c_str();
    value("rhop0", c.rhop0);
    n.append_child("rhopgradient").append_attribute("value") = c.rhopgradient;
    value("hswl", c.hswl);
    value("gamma", c.gamma);
    value("speedsystem", c.speedsystem);
    value("coefsound", c.coefsound);
    value("speedsound", c.speedsound);
    value("coefh", c.coefh);
    value("hdp", c.hdp);
    value("cflnumber", c.cflnumber);
    value("h", c.h);
    value("b", c.b);
    value("massbound", c.massbound);
    value("massfluid", c.massfluid);
}

CaseConstants readConstants(const XmlSource& src, pugi::xml_node n) {
    const PlainNumbers ev;
    auto value = [&](const char* name) { return src.number(src.child(n, name), "value", ev); };
    CaseConstants c;
    c.dimensions = src.integer(src.child(n, "dimensions"), "value", ev);
    c.dp = value("dp");
    c.gravity = src.vec3(src.child(n, "gravity"), ev);
    c.rhop0 = value("rhop0");
    c.rhopgradient = src.integer(src.child(n, "rhopgradient"), "value", ev);
    c.hswl = value("hswl");
    c.gamma = value("gamma");
    c.speedsystem = value("speedsystem");
    c.coefsound = value("coefsound");
    c.speedsound = value("speedsound");
    c.coefh = value("coefh");
    c.hdp = value("hdp");
    c.cflnumber = value("cflnumber");
    c.h = value("h");
    c.b = value("b");
    c.massbound = value("massbound");
    c.massfluid = value("massfluid");
    return c;
}

}  // namespace seaspring::model
