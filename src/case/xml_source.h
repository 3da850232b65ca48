// SeaSpring — MIT licence.
/// \file xml_source.h
/// \brief A loaded XML file that knows the line of every node, and typed attribute
///        access that reports errors as "file:line: <element> attribute 'a': ...".
///
/// Both case files are read through it: gencase's definition (CASE_Def.xml, whose values
/// may be GenCase expressions "#...", evaluated by gencase's ExpressionEvaluator) and the
/// resolved case (plain numbers only: PlainNumbers).
#pragma once

#include <cstdint>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

#include <pugixml.hpp>

#include "core/vec3.h"

namespace seaspring::model {

/// Raised for a value that is not a number, or an expression that cannot be evaluated. The
/// message names the value and the problem; callers add file:line.
class ValueError : public std::runtime_error {
public:
    explicit ValueError(const std::string& m) : std::runtime_error(m) {}
};

/// Evaluates the values written "#..." in a case file (without the '#').
class ValueEvaluator {
public:
    virtual ~ValueEvaluator() = default;
    /// The value of `text`; throws ValueError when it cannot be evaluated.
    virtual double evaluate(const std::string& text) const = 0;
};

/// The evaluator of the resolved case: it holds plain numbers only (gencase evaluates the
/// expressions of the definition), so any "#..." value is an error.
class PlainNumbers : public ValueEvaluator {
public:
    double evaluate(const std::string& text) const override;
};

class XmlSource {
public:
    /// Loads and parses `path`; throws seaspring::Error with the parse error location.
    explicit XmlSource(const std::string& path);

    const std::string& path() const { return path_; }
    /// Directory of the file (for relative paths inside it), ending without '/'.
    std::string directory() const;
    pugi::xml_document& document() { return doc_; }
    pugi::xml_node root() const { return doc_.document_element(); }

    /// 1-based line of a node in the file (0 if unknown).
    int lineOf(pugi::xml_node node) const;
    /// "file:line" of a node.
    std::string where(pugi::xml_node node) const;
    /// Throws seaspring::Error "file:line: <name> message".
    [[noreturn]] void fail(pugi::xml_node node, const std::string& message) const;

    /// Numeric attribute; a value starting with '#' is an expression evaluated with `ev`.
    /// Missing attribute -> error (required) or `fallback`.
    double number(pugi::xml_node node, const char* attr, const ValueEvaluator& ev) const;
    double number(pugi::xml_node node, const char* attr, const ValueEvaluator& ev,
                  double fallback) const;
    /// Integer attribute (the value must be integral).
    int integer(pugi::xml_node node, const char* attr, const ValueEvaluator& ev) const;
    int integer(pugi::xml_node node, const char* attr, const ValueEvaluator& ev,
                int fallback) const;
    /// Non-negative integer attribute written as plain digits, at most `max` (required).
    std::uint32_t count(pugi::xml_node node, const char* attr, std::uint32_t max = 0xffffffffu) const;
    /// Boolean attribute: true/false/1/0 (case-insensitive).
    bool boolean(pugi::xml_node node, const char* attr, bool fallback) const;
    /// String attribute; required unless a fallback is given.
    std::string text(pugi::xml_node node, const char* attr) const;
    std::string text(pugi::xml_node node, const char* attr, const std::string& fallback) const;
    /// Reads attributes x, y, z of `node` (each required unless `fallback` given).
    Vec3d vec3(pugi::xml_node node, const ValueEvaluator& ev) const;
    /// The single required child `name` of `node`.
    pugi::xml_node child(pugi::xml_node node, const char* name) const;

    /// Rejects attributes not in `allowed`. Attributes whose name starts with '_' (GenCase's
    /// way of commenting out) and "comment", "units_comment" are always accepted.
    void checkAttributes(pugi::xml_node node, std::initializer_list<const char*> allowed) const;
    /// Rejects child elements not in `allowed` (names starting with '_' are skipped).
    void checkChildren(pugi::xml_node node, std::initializer_list<const char*> allowed) const;

    /// Rejects a second occurrence of any of the `unique` child elements (a repeated section
    /// would otherwise be silently ignored).
    void checkUnique(pugi::xml_node node, std::initializer_list<const char*> unique) const;

    /// True for elements that GenCase treats as commented out (name starts with '_').
    static bool isDisabled(pugi::xml_node node);

private:
    std::string path_;
    pugi::xml_document doc_;
    std::vector<std::size_t> line_starts_;  ///< byte offset where each line starts
};

/// Parses a number written in the file; throws ValueError if it is not one.
double parseNumber(const std::string& text);

}  // namespace seaspring::model
