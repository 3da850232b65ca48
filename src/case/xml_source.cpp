// SeaSpring — MIT licence.
/// \file xml_source.cpp
#include "case/xml_source.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>

#include "core/error.h"

namespace seaspring::model {

namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s;
}

std::string trim(const std::string& s) {
    std::size_t b = 0, e = s.size();
    while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
    while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
    return s.substr(b, e - b);
}

/// A value for messages: long values are cut.
std::string clip(const std::string& v) {
    if (v.size() <= 80) return v;
    return v.substr(0, 60) + "... (" + std::to_string(v.size()) + " characters)";
}

/// The deepest element nesting a case file may have (DualSPHysics cases use fewer than 10):
/// bounds the work of every recursive walk and copy of the document, disabled ('_') subtrees
/// included.
constexpr int kMaxXmlDepth = 64;

/// The first element nested deeper than kMaxXmlDepth (null when none), found without recursion.
pugi::xml_node tooDeep(pugi::xml_node root) {
    int depth = 1;
    for (pugi::xml_node n = root; n;) {
        if (depth > kMaxXmlDepth && n.type() == pugi::node_element) return n;
        if (pugi::xml_node c = n.first_child()) {
            n = c;
            ++depth;
            continue;
        }
        while (n && n != root && !n.next_sibling()) {
            n = n.parent();
            --depth;
        }
        if (!n || n == root) break;
        n = n.next_sibling();
    }
    return pugi::xml_node();
}

}  // namespace

double PlainNumbers::evaluate(const std::string& text) const {
    throw ValueError("'#" + text + "': the resolved case holds plain numbers, not expressions (gencase writes them evaluated)");
}

double parseNumber(const std::string& text) {
    const std::string t = trim(text);
    if (t.empty()) throw ValueError("empty value where a number was expected");
    char* end = nullptr;
    const double v = std::strtod(t.c_str(), &end);
    if (end != t.c_str() + t.size())
        throw ValueError("'" + t + "' is not a number (write '#" + t +
                              "' for an expression)");
    if (!std::isfinite(v)) throw ValueError("'" + t + "' is not a finite number");
    return v;
}

XmlSource::XmlSource(const std::string& path) : path_(path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throwInputError(path, 0, "cannot open file");
    const std::string buffer((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    line_starts_.push_back(0);
    for (std::size_t i = 0; i < buffer.size(); ++i)
        if (buffer[i] == '\n') line_starts_.push_back(i + 1);
    const pugi::xml_parse_result r =
        doc_.load_buffer(buffer.data(), buffer.size(), pugi::parse_default | pugi::parse_comments);
    if (!r) {
        const auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(),
                                         static_cast<std::size_t>(r.offset));
        throwInputError(path, static_cast<int>(it - line_starts_.begin()),
                        std::string("XML parse error: ") + r.description());
    }
    if (!doc_.document_element()) throwInputError(path, 1, "no root element");
    if (const pugi::xml_node deep = tooDeep(doc_.document_element()))
        throwInputError(path, lineOf(deep),
                        "<" + std::string(deep.name()) + "> elements are nested deeper than " +
                            std::to_string(kMaxXmlDepth) + " levels (disabled '_' elements count too)");
}

std::string XmlSource::directory() const {
    const auto slash = path_.find_last_of('/');
    return slash == std::string::npos ? std::string(".") : path_.substr(0, slash);
}

int XmlSource::lineOf(pugi::xml_node node) const {
    const std::ptrdiff_t off = node.offset_debug();
    if (off < 0) return 0;
    const auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(),
                                     static_cast<std::size_t>(off));
    return static_cast<int>(it - line_starts_.begin());
}

std::string XmlSource::where(pugi::xml_node node) const {
    return path_ + ":" + std::to_string(lineOf(node));
}

void XmlSource::fail(pugi::xml_node node, const std::string& message) const {
    throwInputError(path_, lineOf(node), "<" + std::string(node.name()) + "> " + message);
}

double XmlSource::number(pugi::xml_node node, const char* attr,
                         const ValueEvaluator& ev) const {
    const pugi::xml_attribute a = node.attribute(attr);
    if (!a) fail(node, std::string("requires attribute '") + attr + "' (a number)");
    const std::string raw = trim(a.value());
    try {
        if (!raw.empty() && raw[0] == '#') return ev.evaluate(raw.substr(1));
        return parseNumber(raw);
    } catch (const ValueError& e) {
        fail(node, std::string("attribute ") + attr + "=\"" + clip(raw) + "\": " + e.what());
    }
}

double XmlSource::number(pugi::xml_node node, const char* attr, const ValueEvaluator& ev,
                         double fallback) const {
    if (!node.attribute(attr)) return fallback;
    return number(node, attr, ev);
}

int XmlSource::integer(pugi::xml_node node, const char* attr,
                       const ValueEvaluator& ev) const {
    const double v = number(node, attr, ev);
    if (v != std::floor(v) || std::fabs(v) > 2.0e9)
        fail(node, std::string("attribute ") + attr + "=\"" + node.attribute(attr).value() +
                       "\": expected an integer");
    return static_cast<int>(v);
}

int XmlSource::integer(pugi::xml_node node, const char* attr, const ValueEvaluator& ev,
                       int fallback) const {
    if (!node.attribute(attr)) return fallback;
    return integer(node, attr, ev);
}

std::uint32_t XmlSource::count(pugi::xml_node node, const char* attr, std::uint32_t max) const {
    const std::string t = text(node, attr);
    char* end = nullptr;
    const unsigned long long v = std::strtoull(t.c_str(), &end, 10);
    if (t.empty() || t.find_first_not_of("0123456789") != std::string::npos || *end || v > max)
        fail(node, std::string("attribute ") + attr + "=\"" + t + "\": expected an integer in 0.." +
                       std::to_string(max));
    return std::uint32_t(v);
}

bool XmlSource::boolean(pugi::xml_node node, const char* attr, bool fallback) const {
    const pugi::xml_attribute a = node.attribute(attr);
    if (!a) return fallback;
    const std::string v = lower(trim(a.value()));
    if (v == "true" || v == "1") return true;
    if (v == "false" || v == "0") return false;
    fail(node, std::string("attribute ") + attr + "=\"" + a.value() +
                   "\": expected true, false, 1 or 0");
}

std::string XmlSource::text(pugi::xml_node node, const char* attr) const {
    const pugi::xml_attribute a = node.attribute(attr);
    if (!a) fail(node, std::string("requires attribute '") + attr + "'");
    return a.value();
}

std::string XmlSource::text(pugi::xml_node node, const char* attr,
                            const std::string& fallback) const {
    const pugi::xml_attribute a = node.attribute(attr);
    return a ? std::string(a.value()) : fallback;
}

Vec3d XmlSource::vec3(pugi::xml_node node, const ValueEvaluator& ev) const {
    return {number(node, "x", ev), number(node, "y", ev), number(node, "z", ev)};
}

pugi::xml_node XmlSource::child(pugi::xml_node node, const char* name) const {
    pugi::xml_node c = node.child(name);
    if (!c) fail(node, std::string("requires a child element <") + name + ">");
    return c;
}

bool XmlSource::isDisabled(pugi::xml_node node) {
    return node.type() != pugi::node_element || node.name()[0] == '_';
}

void XmlSource::checkAttributes(pugi::xml_node node,
                                std::initializer_list<const char*> allowed) const {
    for (pugi::xml_attribute a : node.attributes()) {
        const std::string name = a.name();
        if (name.empty() || name[0] == '_' || name == "comment" || name == "units_comment")
            continue;
        bool ok = false;
        for (const char* s : allowed) ok = ok || name == s;
        if (!ok) {
            std::string list;
            for (const char* s : allowed) list += (list.empty() ? "" : ", ") + std::string(s);
            fail(node, "unknown attribute '" + name + "=\"" + a.value() + "\"' (expected: " +
                           (list.empty() ? std::string("none") : list) + ")");
        }
    }
}

void XmlSource::checkChildren(pugi::xml_node node,
                              std::initializer_list<const char*> allowed) const {
    for (pugi::xml_node c : node.children()) {
        if (isDisabled(c)) continue;
        const std::string name = c.name();
        bool ok = false;
        for (const char* s : allowed) ok = ok || name == s;
        if (!ok) {
            std::string list;
            for (const char* s : allowed) list += (list.empty() ? "" : ", ") + std::string(s);
            throwInputError(path_, lineOf(c),
                            "unknown element <" + name + "> inside <" + node.name() +
                                "> (expected: " + (list.empty() ? std::string("none") : list) + ")");
        }
    }
}

void XmlSource::checkUnique(pugi::xml_node node, std::initializer_list<const char*> unique) const {
    for (const char* name : unique) {
        pugi::xml_node first = node.child(name);
        if (!first) continue;
        for (pugi::xml_node n = first.next_sibling(name); n; n = n.next_sibling(name))
            throwInputError(path_, lineOf(n),
                            "<" + std::string(name) + "> appears twice inside <" + node.name() +
                                "> (first at line " + std::to_string(lineOf(first)) +
                                "): merge them into one");
    }
}

}  // namespace seaspring::model
