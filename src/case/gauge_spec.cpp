// SeaSpring — MIT licence.
/// \file gauge_spec.cpp
#include "case/gauge_spec.h"
#include "core/format.h"

#include <cctype>
#include <cstdio>
#include <set>

namespace seaspring::model {

namespace {

struct KindName {
    const char* name;
    GaugeKind kind;
};
constexpr KindName kKinds[] = {{"velocity", GaugeKind::Velocity}, {"pressure", GaugeKind::Pressure},
                               {"swl", GaugeKind::Swl},           {"maxz", GaugeKind::MaxZ},
                               {"force", GaugeKind::Force},       {"solidmarker", GaugeKind::SolidMarker}};
constexpr const char* kSupported = "velocity, pressure, swl, maxz, force, solidmarker";
constexpr const char* kTimingChildren[] = {"savevtkpart", "computedt", "computetime",
                                           "output",      "outputdt",  "outputtime"};

bool isTimingChild(const std::string& n) {
    for (const char* t : kTimingChildren)
        if (n == t) return true;
    return false;
}

/// Reads a time-interval `<computedt value>` (>= 0).
double readInterval(const XmlSource& src, pugi::xml_node n, const ValueEvaluator& ev) {
    src.checkAttributes(n, {"value"});
    const double v = src.number(n, "value", ev);
    if (!(v >= 0)) src.fail(n, "value=\"" + std::string(n.attribute("value").value()) + "\": must be >= 0 [s]");
    return v;
}

/// `<computetime|outputtime start= end=>`: either may be absent.
void readWindow(const XmlSource& src, pugi::xml_node n, const ValueEvaluator& ev,
                std::optional<double>& start, std::optional<double>& end) {
    src.checkAttributes(n, {"start", "end"});
    if (n.attribute("start")) start = src.number(n, "start", ev);
    if (n.attribute("end")) end = src.number(n, "end", ev);
    if (start && end && *end < *start)
        src.fail(n, "end=\"" + std::string(n.attribute("end").value()) + "\" is before start=\"" +
                        n.attribute("start").value() + "\"");
}

/// The timing children of a gauge or of <default> (others are left to the caller).
void readTiming(const XmlSource& src, pugi::xml_node node, const ValueEvaluator& ev, GaugeTiming& t) {
    src.checkUnique(node, {"savevtkpart", "computedt", "computetime", "output", "outputdt", "outputtime"});
    for (pugi::xml_node c : node.children()) {
        if (c.type() != pugi::node_element || XmlSource::isDisabled(c)) continue;
        const std::string n = c.name();
        if (n == "savevtkpart" || n == "output") {
            src.checkAttributes(c, {"value"});
            if (!c.attribute("value")) src.fail(c, "needs value=\"true\" or value=\"false\"");
            (n == "output" ? t.output : t.savevtkpart) = src.boolean(c, "value", false);
        } else if (n == "computedt") {
            t.computedt = readInterval(src, c, ev);
        } else if (n == "outputdt") {
            t.outputdt = readInterval(src, c, ev);
        } else if (n == "computetime") {
            readWindow(src, c, ev, t.compute_start, t.compute_end);
        } else if (n == "outputtime") {
            readWindow(src, c, ev, t.output_start, t.output_end);
        }
    }
}

/// A length given as value=, coefdp= (times dp) or coefh= (times h, where `allow_h`).
double readLength(const XmlSource& src, pugi::xml_node n, const ValueEvaluator& ev, double dp, double h,
                  bool allow_h) {
    if (allow_h) src.checkAttributes(n, {"value", "coefdp", "coefh"});
    else src.checkAttributes(n, {"value", "coefdp"});
    const int given = (n.attribute("value") ? 1 : 0) + (n.attribute("coefdp") ? 1 : 0) +
                      (allow_h && n.attribute("coefh") ? 1 : 0);
    if (given != 1)
        src.fail(n, std::string("needs exactly one of value=, coefdp=") + (allow_h ? ", coefh=" : ""));
    double v;
    const char* attr = n.attribute("value") ? "value" : (n.attribute("coefdp") ? "coefdp" : "coefh");
    v = src.number(n, attr, ev);
    if (std::string(attr) == "coefdp") v *= dp;
    if (std::string(attr) == "coefh") v *= h;
    if (!(v > 0)) src.fail(n, std::string(attr) + "=\"" + n.attribute(attr).value() + "\": the length must be > 0");
    return v;
}

void checkName(const XmlSource& src, pugi::xml_node n, const std::string& name, std::set<std::string>& seen) {
    if (name.empty()) src.fail(n, "needs name=\"...\" (it names the CSV file)");
    for (unsigned char ch : name)
        if (!(std::isalnum(ch) || ch == '_' || ch == '-' || ch == '.'))
            src.fail(n, "name=\"" + name + "\": use letters, digits, '_', '-' and '.' only (it names a file)");
    if (!seen.insert(name).second) src.fail(n, "name=\"" + name + "\" is used by another gauge");
}

GaugeSpec readGauge(const XmlSource& src, pugi::xml_node n, GaugeKind kind, const ValueEvaluator& ev,
                    double dp, double h) {
    GaugeSpec g;
    g.kind = kind;
    g.line = src.lineOf(n);
    src.checkAttributes(n, {"name", "active"});
    g.name = src.text(n, "name", "");
    readTiming(src, n, ev, g.timing);
    auto point = [&](const char* child) {
        pugi::xml_node p = src.child(n, child);
        src.checkAttributes(p, {"x", "y", "z"});
        return src.vec3(p, ev);
    };
    std::vector<const char*> allowed;
    switch (kind) {
        case GaugeKind::Velocity:
        case GaugeKind::Pressure:
            allowed = {"point", "kclimit"};
            g.point = point("point");
            if (pugi::xml_node k = n.child("kclimit")) {
                src.checkAttributes(k, {"value"});
                g.kclimit = src.number(k, "value", ev);
                if (!(g.kclimit > 0 && g.kclimit <= 1))
                    src.fail(k, "value=\"" + std::string(k.attribute("value").value()) + "\": must lie in (0, 1]");
            }
            break;
        case GaugeKind::Swl: {
            allowed = {"point0", "point2", "pointdp", "masslimit"};
            g.point0 = point("point0");
            g.point2 = point("point2");
            g.pointdp = 0.5 * dp;
            if (pugi::xml_node p = n.child("pointdp")) g.pointdp = readLength(src, p, ev, dp, h, false);
            if (pugi::xml_node m = n.child("masslimit")) {
                src.checkAttributes(m, {"value", "coef"});
                if ((m.attribute("value") ? 1 : 0) + (m.attribute("coef") ? 1 : 0) != 1)
                    src.fail(m, "needs exactly one of value= [kg] or coef= (times the fluid particle mass)");
                const char* attr = m.attribute("value") ? "value" : "coef";
                const double v = src.number(m, attr, ev);
                if (!(v > 0)) src.fail(m, std::string(attr) + "=\"" + m.attribute(attr).value() + "\": must be > 0");
                (m.attribute("value") ? g.masslimit : g.masslimit_coef) = v;
            }
            const Vec3d d = g.point2 - g.point0;
            if (!(d.x * d.x + d.y * d.y + d.z * d.z > 0)) src.fail(n, "point0 and point2 are the same point");
            break;
        }
        case GaugeKind::MaxZ: {
            allowed = {"point0", "height", "distlimit"};
            g.point0 = point("point0");
            pugi::xml_node hn = src.child(n, "height");
            src.checkAttributes(hn, {"value"});
            g.height = src.number(hn, "value", ev);
            if (!(g.height > 0)) src.fail(hn, "value=\"" + std::string(hn.attribute("value").value()) + "\": must be > 0 [m]");
            g.distlimit = readLength(src, src.child(n, "distlimit"), ev, dp, h, true);
            break;
        }
        case GaugeKind::Force:
        case GaugeKind::SolidMarker: {
            allowed = {"target"};
            if (kind == GaugeKind::SolidMarker) {
                allowed.push_back("point");
                g.point = point("point");
            }
            pugi::xml_node t = kind == GaugeKind::Force ? src.child(n, "target") : n.child("target");
            if (t) {
                src.checkAttributes(t, {"mkbound"});
                g.target_mkbound = src.integer(t, "mkbound", ev);
                if (g.target_mkbound < 0)
                    src.fail(t, "mkbound=\"" + std::string(t.attribute("mkbound").value()) + "\": must be >= 0");
            }
            break;
        }
    }
    for (pugi::xml_node c : n.children()) {
        if (c.type() != pugi::node_element || XmlSource::isDisabled(c)) continue;
        const std::string cn = c.name();
        bool ok = isTimingChild(cn);
        for (const char* a : allowed) ok = ok || cn == a;
        if (!ok) {
            std::string list;
            for (const char* a : allowed) list += std::string(list.empty() ? "" : ", ") + a;
            src.fail(c, "is not a child of <" + std::string(n.name()) + "> (expected " + list +
                            " and the timing elements computedt, computetime, output, outputdt, outputtime, savevtkpart)");
        }
    }
    return g;
}

void writeTiming(const GaugeTiming& t, pugi::xml_node n) {
    auto value = [&](const char* name, const std::string& v) {
        n.append_child(name).append_attribute("value") = v.c_str();
    };
    auto window = [&](const char* name, const auto& start, const auto& end) {  // optional start/end
        if (!start && !end) return;
        pugi::xml_node w = n.append_child(name);
        if (start) w.append_attribute("start") = exactText(*start).c_str();
        if (end) w.append_attribute("end") = exactText(*end).c_str();
    };
    if (t.savevtkpart) value("savevtkpart", *t.savevtkpart ? "true" : "false");
    if (t.computedt) value("computedt", exactText(*t.computedt));
    window("computetime", t.compute_start, t.compute_end);
    if (t.output) value("output", *t.output ? "true" : "false");
    if (t.outputdt) value("outputdt", exactText(*t.outputdt));
    window("outputtime", t.output_start, t.output_end);
}

void writePoint(pugi::xml_node n, const char* name, const Vec3d& p) {
    pugi::xml_node c = n.append_child(name);
    c.append_attribute("x") = exactText(p.x).c_str();
    c.append_attribute("y") = exactText(p.y).c_str();
    c.append_attribute("z") = exactText(p.z).c_str();
}

}  // namespace

const char* gaugeElementName(GaugeKind k) {
    for (const KindName& kn : kKinds)
        if (kn.kind == k) return kn.name;
    return "?";
}

GaugeSet parseGauges(const XmlSource& src, pugi::xml_node gauges, const ValueEvaluator& ev, double dp,
                     double h) {
    GaugeSet set;
    if (!gauges) return set;
    src.checkAttributes(gauges, {"active"});
    if (!src.boolean(gauges, "active", true)) return set;
    src.checkUnique(gauges, {"default"});
    std::set<std::string> names;
    for (pugi::xml_node n : gauges.children()) {
        if (n.type() != pugi::node_element || XmlSource::isDisabled(n)) continue;
        const std::string name = n.name();
        if (name == "default") {
            src.checkAttributes(n, {});
            for (pugi::xml_node c : n.children())
                if (c.type() == pugi::node_element && !XmlSource::isDisabled(c) && !isTimingChild(c.name()))
                    src.fail(c, "is not a <default> setting (expected computedt, computetime, output, outputdt, "
                                "outputtime, savevtkpart)");
            readTiming(src, n, ev, set.defaults);
            continue;
        }
        const KindName* kind = nullptr;
        for (const KindName& kn : kKinds)
            if (name == kn.name) kind = &kn;
        if (!kind) src.fail(n, std::string("is not a gauge SeaSpring supports (supported: ") + kSupported + ")");
        if (!src.boolean(n, "active", true)) continue;
        GaugeSpec g = readGauge(src, n, kind->kind, ev, dp, h);
        checkName(src, n, g.name, names);
        set.gauges.push_back(std::move(g));
    }
    return set;
}

GaugeSet readGauges(const XmlSource& src, pugi::xml_node gauges, double dp, double h) {
    return parseGauges(src, gauges, PlainNumbers{}, dp, h);
}

void writeGauges(const GaugeSet& set, pugi::xml_node parent) {
    pugi::xml_node root = parent.append_child("gauges");
    pugi::xml_node def = root.append_child("default");
    writeTiming(set.defaults, def);
    for (const GaugeSpec& g : set.gauges) {
        pugi::xml_node n = root.append_child(gaugeElementName(g.kind));
        n.append_attribute("name") = g.name.c_str();
        writeTiming(g.timing, n);
        switch (g.kind) {
            case GaugeKind::Velocity:
            case GaugeKind::Pressure:
                writePoint(n, "point", g.point);
                n.append_child("kclimit").append_attribute("value") = exactText(g.kclimit).c_str();
                break;
            case GaugeKind::Swl: {
                writePoint(n, "point0", g.point0);
                writePoint(n, "point2", g.point2);
                n.append_child("pointdp").append_attribute("value") = exactText(g.pointdp).c_str();
                if (g.masslimit) n.append_child("masslimit").append_attribute("value") = exactText(*g.masslimit).c_str();
                if (g.masslimit_coef) n.append_child("masslimit").append_attribute("coef") = exactText(*g.masslimit_coef).c_str();
                break;
            }
            case GaugeKind::MaxZ:
                writePoint(n, "point0", g.point0);
                n.append_child("height").append_attribute("value") = exactText(g.height).c_str();
                n.append_child("distlimit").append_attribute("value") = exactText(g.distlimit).c_str();
                break;
            case GaugeKind::Force:
            case GaugeKind::SolidMarker:
                if (g.kind == GaugeKind::SolidMarker) writePoint(n, "point", g.point);
                if (g.target_mkbound >= 0)
                    n.append_child("target").append_attribute("mkbound") = std::to_string(g.target_mkbound).c_str();
                break;
        }
    }
}

}  // namespace seaspring::model
