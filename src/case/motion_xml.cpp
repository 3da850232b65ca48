// SeaSpring — MIT licence.
/// \file motion_xml.cpp
/// \brief Parsing, validation and normalized writing/reading of the GenCase <motion> section.
#include "case/motion_xml.h"

#include <cctype>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "core/error.h"
#include "case/motion_table.h"

namespace seaspring::model {

namespace {

constexpr double kPi = 3.14159265358979323846;

struct KindName {
    const char* name;
    MovementKind kind;
};
/// The first name of each kind is the canonical one (written by writeMotion).
constexpr KindName kKindNames[] = {
    {"mvrect", MovementKind::Rect},         {"mvrectace", MovementKind::RectAce},
    {"mvrot", MovementKind::Rot},           {"mvrotsinu", MovementKind::RotSinu},
    {"mvrectsinu", MovementKind::RectSinu}, {"mvrectfile", MovementKind::RectFile},
    {"mvrotfile", MovementKind::RotFile},   {"wait", MovementKind::Wait},
    {"mvnull", MovementKind::Null},         {"mvsinu", MovementKind::RectSinu},
    {"mvfile", MovementKind::RectFile},     {"mvpredef", MovementKind::RectFile}};
constexpr const char* kUnsupported[] = {"mvcir",    "mvcirace",     "mvcirsinu",
                                        "mvrotace", "mvrotadvfile", "mvpathfile"};
constexpr const char* kSupportedList =
    "mvrect, mvrectace, mvrot, mvrotsinu, mvrectsinu (mvsinu), mvrectfile (mvfile), mvrotfile, "
    "wait, mvnull";

const char* canonicalName(MovementKind kind) {
    for (const KindName& k : kKindNames)
        if (k.kind == kind) return k.name;
    return "?";
}
bool isFileKind(MovementKind k) {
    return k == MovementKind::RectFile || k == MovementKind::RotFile;
}
bool usesAngles(MovementKind k) {
    return k == MovementKind::Rot || k == MovementKind::RotSinu || k == MovementKind::RectSinu ||
           k == MovementKind::RotFile;
}

/// Reads one <motion> element: the DualSPHysics definition, or writeMotion's normalized form.
struct Reader {
    const XmlSource& src;
    const ValueEvaluator& ev;
    bool normalized;

    /// The only child `name` of `parent` (error if repeated; if missing and required).
    pugi::xml_node single(pugi::xml_node parent, const char* name, bool required) const {
        pugi::xml_node found;
        for (pugi::xml_node c : parent.children(name)) {
            if (found)
                src.fail(c, std::string("appears twice in <") + parent.name() +
                                "> (first at line " + std::to_string(src.lineOf(found)) + ")");
            found = c;
        }
        if (!found && required)
            src.fail(parent, std::string("requires a child element <") + name + ">");
        return found;
    }

    /// Like XmlSource::checkAttributes, for a list built at run time.
    void checkAttrs(pugi::xml_node node, const std::vector<const char*>& allowed) const {
        for (pugi::xml_attribute a : node.attributes()) {
            const std::string name = a.name();
            if (name.empty() || name[0] == '_' || name == "comment" || name == "units_comment")
                continue;
            std::string list;
            bool ok = false;
            for (const char* s : allowed) {
                ok = ok || name == s;
                list += (list.empty() ? "" : ", ") + std::string(s);
            }
            if (!ok)
                src.fail(node, "unknown attribute '" + name + "=\"" + a.value() +
                                   "\"' (expected: " + list + ")");
        }
    }

    /// Fails with "attribute a="raw" (= value if an expression): message".
    [[noreturn]] void badAttr(pugi::xml_node n, const char* attr, const std::string& msg) const {
        const std::string raw = n.attribute(attr).value();
        const bool expr = raw.find('#') != std::string::npos;
        src.fail(n, std::string("attribute ") + attr + "=\"" + raw + "\"" +
                        (expr ? " (= " + num(src.number(n, attr, ev)) + ")" : "") + ": " + msg);
    }

    int lineAttr(pugi::xml_node e) const {
        return normalized ? src.integer(e, "line", ev) : src.lineOf(e);
    }

    Vec3d vec(pugi::xml_node n) const {
        src.checkAttributes(n, {"x", "y", "z"});
        return src.vec3(n, ev);
    }
    Vec3d vec(pugi::xml_node parent, const char* name) const {
        return vec(single(parent, name, true));
    }
    double scalar(pugi::xml_node n, const char* attr) const {
        src.checkAttributes(n, {attr});
        return src.number(n, attr, ev);
    }

    double angleFactor(pugi::xml_node e) const {
        const std::string u = src.text(e, "anglesunits", "degrees");
        if (u == "degrees") return kPi / 180.0;
        if (u == "radians") return 1.0;
        badAttr(e, "anglesunits", "expected degrees or radians");
    }

    void readAxis(pugi::xml_node e, Movement& m) const {
        m.axis_p1 = vec(e, "axisp1");
        m.axis_p2 = vec(e, "axisp2");
        const Vec3d p = m.axis_p1;
        if (p.x == m.axis_p2.x && p.y == m.axis_p2.y && p.z == m.axis_p2.z)
            src.fail(single(e, "axisp2", true),
                     "(" + num(p.x) + "," + num(p.y) + "," + num(p.z) +
                         ") equals <axisp1>: the rotation axis needs two different points");
    }

    /// Data of a file movement: <file> (definition) or <table> (normalized).
    void readData(pugi::xml_node e, Movement& m, double factor) const {
        const bool rect = m.kind == MovementKind::RectFile;
        TableSpec s;
        s.origin = std::string(" [data of <") + e.name() + "> at " + src.where(e) + "]";
        s.factor_x = rect ? 1.0 : factor;
        if (normalized) {
            const pugi::xml_node t = single(e, "table", true);
            src.checkAttributes(t, {"rows", "columns"});
            const int cols = rect ? 4 : 2, rows = src.integer(t, "rows", ev);
            if (src.integer(t, "columns", ev) != cols)
                badAttr(t, "columns", "expected " + std::to_string(cols));
            const pugi::xml_node text = t.first_child();
            std::istringstream in(text ? text.value() : "");
            s.name = src.path();
            s.first_line = src.lineOf(text ? text : t);
            s.min_cols = s.max_cols = cols;
            s.allow_header = false;
            if (rect) s.cy = 2, s.cz = 3;
            s.expect = std::to_string(cols) + " columns";
            m.table = readTable(in, s);
            if (static_cast<int>(m.table.time.size()) != rows || rows == 0)
                src.fail(t, "has " + std::to_string(m.table.time.size()) +
                                " rows, attribute rows=\"" + std::to_string(rows) +
                                "\" (expected equal and > 0)");
            m.source_file = src.text(e, "source");
            return;
        }
        const pugi::xml_node f = single(e, "file", true);
        s.expect = "at least 2 columns: time, angle";
        if (rect) {
            src.checkAttributes(f, {"name", "fields", "fieldtime", "fieldx", "fieldy", "fieldz"});
            s.min_cols = src.integer(f, "fields", ev);
            if (s.min_cols < 2) badAttr(f, "fields", "expected >= 2");
            s.tcol = src.integer(f, "fieldtime", ev);
            s.cx = src.integer(f, "fieldx", ev, -1);
            s.cy = src.integer(f, "fieldy", ev, -1);
            s.cz = src.integer(f, "fieldz", ev, -1);
            if (s.cx < 0 && s.cy < 0 && s.cz < 0)
                src.fail(f, "needs at least one of the attributes fieldx, fieldy, fieldz");
            const char* names[] = {"fieldtime", "fieldx", "fieldy", "fieldz"};
            const int idx[] = {s.tcol, s.cx, s.cy, s.cz};
            for (int i = 0; i < 4; ++i) {
                if (!f.attribute(names[i])) continue;
                if (idx[i] < 0 || idx[i] >= s.min_cols)
                    badAttr(f, names[i],
                            "expected a column index from 0 to fields-1 = " +
                                std::to_string(s.min_cols - 1));
                for (int j = 0; j < i; ++j)
                    if (f.attribute(names[j]) && idx[j] == idx[i])
                        badAttr(f, names[i], std::string("same column as ") + names[j]);
            }
            s.expect = "at least " + std::to_string(s.min_cols) + " columns (fields=\"" +
                       std::to_string(s.min_cols) + "\")";
        } else {
            src.checkAttributes(f, {"name"});
        }
        const std::string name = src.text(f, "name");
        if (name.empty()) badAttr(f, "name", "expected a file name");
        s.name = name[0] == '/' ? name : src.directory() + "/" + name;
        std::ifstream in(s.name);
        if (!in) src.fail(f, "cannot open motion file '" + s.name + "' (name=\"" + name + "\")");
        m.table = readTable(in, s);
        if (m.table.time.empty()) throwInputError(s.name, 0, "no data rows" + s.origin);
        m.source_file = s.name;
    }

    Movement movement(pugi::xml_node e, MovementKind kind) const {
        Movement m;
        m.kind = kind;
        std::vector<const char*> attrs = {"id"};
        if (kind != MovementKind::Null) attrs.insert(attrs.end(), {"duration", "next"});
        if (usesAngles(kind)) attrs.push_back("anglesunits");
        if (normalized) attrs.push_back("line");
        if (normalized && isFileKind(kind)) attrs.push_back("source");
        checkAttrs(e, attrs);
        m.line = lineAttr(e);
        m.id = src.integer(e, "id", ev);
        if (m.id < 1) badAttr(e, "id", "expected an integer >= 1");
        if (kind != MovementKind::Null) {
            m.duration = src.number(e, "duration", ev);
            if (!(m.duration >= 0 || m.duration == -1))
                badAttr(e, "duration", "expected a time >= 0, or -1 (forever)");
            const int next = src.integer(e, "next", ev, 0);
            m.next = next == 0 ? -1 : next;
        }
        const double f = usesAngles(kind) ? angleFactor(e) : 1.0;
        switch (kind) {
            case MovementKind::Rect:
                src.checkChildren(e, {"vel"});
                m.vel = vec(e, "vel");
                break;
            case MovementKind::RectAce:
                src.checkChildren(e, {"velini", "ace"});
                m.ace = vec(e, "ace");
                if (pugi::xml_node v = single(e, "velini", false))
                    m.has_velini = true, m.velini = vec(v);
                break;
            case MovementKind::Rot:
                src.checkChildren(e, {"vel", "axisp1", "axisp2"});
                m.ang_vel = scalar(single(e, "vel", true), "ang") * f;
                readAxis(e, m);
                break;
            case MovementKind::RotSinu:
                src.checkChildren(e, {"freq", "ampl", "phase", "axisp1", "axisp2"});
                m.ang_freq = scalar(single(e, "freq", true), "v");
                m.ang_ampl = scalar(single(e, "ampl", true), "v") * f;
                if (pugi::xml_node p = single(e, "phase", false))
                    m.has_phase = true, m.ang_phase = scalar(p, "v") * f;
                readAxis(e, m);
                break;
            case MovementKind::RectSinu:
                src.checkChildren(e, {"freq", "ampl", "phase"});
                m.freq = vec(e, "freq");
                m.ampl = vec(e, "ampl");
                if (pugi::xml_node p = single(e, "phase", false))
                    m.has_phase = true, m.phase = f * vec(p);
                break;
            case MovementKind::RectFile:
                if (normalized)
                    src.checkChildren(e, {"table"});
                else
                    src.checkChildren(e, {"file"});
                readData(e, m, f);
                break;
            case MovementKind::RotFile:
                if (normalized)
                    src.checkChildren(e, {"table", "axisp1", "axisp2"});
                else
                    src.checkChildren(e, {"file", "axisp1", "axisp2"});
                readData(e, m, f);
                readAxis(e, m);
                break;
            case MovementKind::Wait:
            case MovementKind::Null: src.checkChildren(e, {}); break;
        }
        return m;
    }

    MotionObject object(pugi::xml_node o) const {
        MotionObject obj;
        checkAttrs(o, normalized ? std::vector<const char*>{"ref", "line"}
                                 : std::vector<const char*>{"ref"});
        obj.line = lineAttr(o);
        obj.mkbound = src.integer(o, "ref", ev);
        if (obj.mkbound < 0) badAttr(o, "ref", "expected a mkbound >= 0");
        pugi::xml_node begin;
        std::map<int, pugi::xml_node> nodes;  // id -> element
        for (pugi::xml_node c : o.children()) {
            if (XmlSource::isDisabled(c)) continue;
            const std::string name = c.name();
            if (name == "begin") {
                if (begin)
                    src.fail(c, "appears twice (first at line " +
                                    std::to_string(src.lineOf(begin)) +
                                    "): SeaSpring supports one <begin> per object");
                begin = c;
                continue;
            }
            if (name == "obj" || name == "objreal")
                src.fail(c,
                         "nested object groups are not supported by SeaSpring: declare each moving "
                         "object as <objreal ref=\"mkbound\"> directly in <motion>");
            for (const char* u : kUnsupported)
                if (name == u)
                    src.fail(c, std::string("is not supported by SeaSpring (supported: ") +
                                    kSupportedList + ")");
            const KindName* kind = nullptr;
            for (const KindName& k : kKindNames)
                if (name == k.name) kind = &k;
            if (!kind)
                throwInputError(src.path(), src.lineOf(c),
                                "unknown element <" + name +
                                    "> inside <objreal> (expected: begin, " + kSupportedList + ")");
            obj.movements.push_back(movement(c, kind->kind));
            const auto [it, inserted] = nodes.emplace(obj.movements.back().id, c);
            if (!inserted)
                badAttr(c, "id",
                        "already used by the movement at line " +
                            std::to_string(src.lineOf(it->second)) + " of this object");
        }
        std::string ids;
        for (const auto& kv : nodes) ids += (ids.empty() ? "" : ", ") + std::to_string(kv.first);
        ids = " (ids of ref=" + std::to_string(obj.mkbound) + ": " + (ids.empty() ? "none" : ids) +
              ")";
        if (!begin) src.fail(o, "requires a child element <begin mov=\"..\" start=\"..\"/>");
        src.checkAttributes(begin, {"mov", "start", "finish"});
        obj.first_movement = src.integer(begin, "mov", ev);
        obj.start = src.number(begin, "start", ev);
        if (obj.start < 0) badAttr(begin, "start", "expected a time >= 0");
        if (begin.attribute("finish")) {
            const double fin = src.number(begin, "finish", ev);
            if (fin != -1 && fin < obj.start)
                badAttr(begin, "finish",
                        "expected a time >= start (" + num(obj.start) + "), or -1 (none)");
            if (fin != -1) obj.finish = fin;
        }
        if (!obj.movement(obj.first_movement))
            badAttr(begin, "mov", "does not name a movement of this object" + ids);
        for (const Movement& m : obj.movements)
            if (m.next != -1 && !obj.movement(m.next))
                badAttr(nodes.at(m.id), "next", "does not name a movement of this object" + ids);
        return obj;
    }

    MotionSet motion(pugi::xml_node node) const {
        src.checkAttributes(node, {});
        MotionSet set;
        std::map<int, pugi::xml_node> refs;
        for (pugi::xml_node c : node.children()) {
            if (XmlSource::isDisabled(c)) continue;
            const std::string name = c.name();
            if (name == "obj")
                src.fail(c,
                         "groups are not supported by SeaSpring: declare each moving object as "
                         "<objreal ref=\"mkbound\"> directly in <motion>");
            if (name != "objreal")
                throwInputError(
                    src.path(), src.lineOf(c),
                    "unknown element <" + name + "> inside <motion> (expected: objreal)");
            set.objects.push_back(object(c));
            const auto [it, inserted] = refs.emplace(set.objects.back().mkbound, c);
            if (!inserted)
                badAttr(c, "ref",
                        "already used by the <objreal> at line " +
                            std::to_string(src.lineOf(it->second)));
        }
        return set;
    }
};

void setNum(pugi::xml_node n, const char* attr, double v) {
    n.append_attribute(attr).set_value(num(v, 17).c_str());
}
void addVec(pugi::xml_node parent, const char* name, Vec3d v) {
    pugi::xml_node n = parent.append_child(name);
    setNum(n, "x", v.x);
    setNum(n, "y", v.y);
    setNum(n, "z", v.z);
}
void addScalar(pugi::xml_node parent, const char* name, double v) {
    setNum(parent.append_child(name), "v", v);
}

void writeMovement(pugi::xml_node o, const Movement& m) {
    pugi::xml_node e = o.append_child(canonicalName(m.kind));
    e.append_attribute("id").set_value(m.id);
    if (m.kind != MovementKind::Null) {
        setNum(e, "duration", m.duration);
        e.append_attribute("next").set_value(m.next == -1 ? 0 : m.next);
    }
    if (usesAngles(m.kind)) e.append_attribute("anglesunits").set_value("radians");
    e.append_attribute("line").set_value(m.line);
    if (isFileKind(m.kind)) e.append_attribute("source").set_value(m.source_file.c_str());
    switch (m.kind) {
        case MovementKind::Rect: addVec(e, "vel", m.vel); break;
        case MovementKind::RectAce:
            if (m.has_velini) addVec(e, "velini", m.velini);
            addVec(e, "ace", m.ace);
            break;
        case MovementKind::Rot: setNum(e.append_child("vel"), "ang", m.ang_vel); break;
        case MovementKind::RotSinu:
            addScalar(e, "freq", m.ang_freq);
            addScalar(e, "ampl", m.ang_ampl);
            if (m.has_phase) addScalar(e, "phase", m.ang_phase);
            break;
        case MovementKind::RectSinu:
            addVec(e, "freq", m.freq);
            addVec(e, "ampl", m.ampl);
            if (m.has_phase) addVec(e, "phase", m.phase);
            break;
        case MovementKind::RectFile:
        case MovementKind::RotFile: {
            const bool rect = m.kind == MovementKind::RectFile;
            pugi::xml_node t = e.append_child("table");
            t.append_attribute("rows").set_value(
                static_cast<unsigned long long>(m.table.time.size()));
            t.append_attribute("columns").set_value(rect ? 4 : 2);
            std::string text = "\n";
            for (std::size_t i = 0; i < m.table.time.size(); ++i) {
                const Vec3d v = m.table.value[i];
                text += num(m.table.time[i], 17) + " " + num(v.x, 17);
                if (rect) text += " " + num(v.y, 17) + " " + num(v.z, 17);
                text += "\n";
            }
            t.append_child(pugi::node_pcdata).set_value(text.c_str());
            break;
        }
        case MovementKind::Wait:
        case MovementKind::Null: break;
    }
    if (m.kind == MovementKind::Rot || m.kind == MovementKind::RotSinu ||
        m.kind == MovementKind::RotFile) {
        addVec(e, "axisp1", m.axis_p1);
        addVec(e, "axisp2", m.axis_p2);
    }
}

}  // namespace

MotionSet readMotionElement(const XmlSource& src, pugi::xml_node motion_node, const ValueEvaluator& ev,
                            MotionSyntax syntax) {
    return Reader{src, ev, syntax == MotionSyntax::Normalized}.motion(motion_node);
}

void writeMotion(const MotionSet& set, pugi::xml_node parent) {
    pugi::xml_node motion = parent.append_child("motion");
    for (const MotionObject& obj : set.objects) {
        pugi::xml_node o = motion.append_child("objreal");
        o.append_attribute("ref").set_value(obj.mkbound);
        o.append_attribute("line").set_value(obj.line);
        pugi::xml_node b = o.append_child("begin");
        b.append_attribute("mov").set_value(obj.first_movement);
        setNum(b, "start", obj.start);
        setNum(b, "finish", std::isinf(obj.finish) ? -1.0 : obj.finish);
        for (const Movement& m : obj.movements) writeMovement(o, m);
    }
}

MotionSet readMotion(const XmlSource& src, pugi::xml_node motion_node) {
    return readMotionElement(src, motion_node, PlainNumbers{}, MotionSyntax::Normalized);
}

}  // namespace seaspring::model
