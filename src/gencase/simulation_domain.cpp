// SeaSpring — MIT licence.
/// \file simulation_domain.cpp
#include "gencase/simulation_domain.h"

#include <cctype>
#include <string>

namespace seaspring::gencase {

using model::parseNumber;

namespace {

std::string stripSpaces(const std::string& s) {
    std::string out;
    for (char c : s)
        if (!std::isspace(static_cast<unsigned char>(c))) out += c;
    return out;
}

double resolveOne(const XmlSource& src, pugi::xml_node n, const char* axis,
                  const ExpressionEvaluator& ev, double def, double size) {
    const pugi::xml_attribute a = n.attribute(axis);
    if (!a) return def;
    const std::string raw = a.value();
    const std::string v = stripSpaces(raw);
    if (v.rfind("default", 0) != 0) return src.number(n, axis, ev);
    std::string rest = v.substr(7);
    if (rest.empty()) return def;
    const char sign = rest[0];
    if (sign != '+' && sign != '-')
        src.fail(n, std::string(axis) + "=\"" + raw + "\": expected default, default+V, default-V, "
                                                     "default+V% or a number");
    rest.erase(0, 1);
    const bool percent = !rest.empty() && rest.back() == '%';
    if (percent) rest.pop_back();
    double amount = 0;
    try {
        amount = parseNumber(rest);
    } catch (const ExpressionError& e) {
        src.fail(n, std::string(axis) + "=\"" + raw + "\": " + e.what());
    }
    if (percent) amount = amount / 100.0 * size;
    return sign == '+' ? def + amount : def - amount;
}

}  // namespace

DomainBox resolveSimulationDomain(const XmlSource& src, pugi::xml_node node,
                                  const ExpressionEvaluator& ev, const DomainBox& box) {
    DomainBox d = box;
    if (!node) return d;
    src.checkAttributes(node, {});
    src.checkChildren(node, {"posmin", "posmax"});
    const Vec3d size = box.max - box.min;
    if (pugi::xml_node n = node.child("posmin")) {
        src.checkAttributes(n, {"x", "y", "z"});
        d.min = {resolveOne(src, n, "x", ev, box.min.x, size.x), resolveOne(src, n, "y", ev, box.min.y, size.y),
                 resolveOne(src, n, "z", ev, box.min.z, size.z)};
    }
    if (pugi::xml_node n = node.child("posmax")) {
        src.checkAttributes(n, {"x", "y", "z"});
        d.max = {resolveOne(src, n, "x", ev, box.max.x, size.x), resolveOne(src, n, "y", ev, box.max.y, size.y),
                 resolveOne(src, n, "z", ev, box.max.z, size.z)};
    }
    const char* axes = "xyz";
    const double lo[3] = {d.min.x, d.min.y, d.min.z}, hi[3] = {d.max.x, d.max.y, d.max.z};
    const double plo[3] = {box.min.x, box.min.y, box.min.z}, phi[3] = {box.max.x, box.max.y, box.max.z};
    for (int k = 0; k < 3; ++k)
        if (lo[k] > plo[k] || hi[k] < phi[k])
            src.fail(node, std::string("gives a domain [") + std::to_string(lo[k]) + ", " +
                               std::to_string(hi[k]) + "] along " + axes[k] +
                               " that does not contain all particles [" + std::to_string(plo[k]) +
                               ", " + std::to_string(phi[k]) + "]");
    return d;
}

}  // namespace seaspring::gencase
