// SeaSpring — MIT licence.
/// \file xml_source.h
/// \brief A loaded XML file that knows the line of every node, and typed attribute
///        access that reports errors as "file:line: <element> attribute 'a': ...".
#pragma once

#include <initializer_list>
#include <string>
#include <vector>

#include <pugixml.hpp>

#include "core/vec3.h"
#include "gencase/expression.h"

namespace seaspring::gencase {

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
    double number(pugi::xml_node node, const char* attr, const ExpressionEvaluator& ev) const;
    double number(pugi::xml_node node, const char* attr, const ExpressionEvaluator& ev,
                  double fallback) const;
    /// Integer attribute (the value must be integral).
    int integer(pugi::xml_node node, const char* attr, const ExpressionEvaluator& ev) const;
    int integer(pugi::xml_node node, const char* attr, const ExpressionEvaluator& ev,
                int fallback) const;
    /// Boolean attribute: true/false/1/0 (case-insensitive).
    bool boolean(pugi::xml_node node, const char* attr, bool fallback) const;
    /// String attribute; required unless a fallback is given.
    std::string text(pugi::xml_node node, const char* attr) const;
    std::string text(pugi::xml_node node, const char* attr, const std::string& fallback) const;
    /// Reads attributes x, y, z of `node` (each required unless `fallback` given).
    Vec3d vec3(pugi::xml_node node, const ExpressionEvaluator& ev) const;
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

/// Parses a number written in the file; throws ExpressionError if it is not one.
double parseNumber(const std::string& text);

}  // namespace seaspring::gencase
