// SeaSpring — MIT licence.
/// \file json_writer.h
/// \brief A small streaming JSON writer (pretty-printed, 2-space indent) for run summaries
///        such as run.json, and an atomic text-file write.
///
/// Usage:
/// \code
///   JsonWriter j;
///   j.beginObject();                 // the root: no key
///   j.value("case", "dambreak");     // object members take a key
///   j.beginArray("times");
///   j.value(0.5);                    // array elements take none
///   j.endArray();
///   j.endObject();
///   writeTextFileAtomic("out/run.json", j.str() + "\n");
/// \endcode
/// gives
/// \code
///   {
///     "case": "dambreak",
///     "times": [
///       0.5
///     ]
///   }
/// \endcode
/// Strings are escaped as JSON requires: `"` and `\` with a backslash; \b \f \n \r \t in
/// their short forms, other control characters (below U+0020) as \u00XX; everything else,
/// UTF-8 included, is copied byte for byte. Doubles are printed with "%.17g" (exact round
/// trip); NaN and infinities, which JSON cannot express, are written as null. Misuse throws
/// seaspring::Error: a key on an array element or the root, an object member without a key
/// (so the empty string cannot be a key), an end that does not match the open container,
/// anything after the root is complete, and str() on an unfinished document.
#pragma once

#include <string>
#include <type_traits>
#include <vector>

namespace seaspring::io {

class JsonWriter {
public:
    /// Opens an object: the root (no key), an object member (key) or an array element
    /// (no key).
    void beginObject(const std::string& key = "");
    void endObject();
    /// Opens an array, with the same key rules as beginObject.
    void beginArray(const std::string& key = "");
    void endArray();

    /// An object member (key) or, with key "", an array element or the root value.
    void value(const std::string& key, const std::string& v);
    void value(const std::string& key, const char* v);
    void value(const std::string& key, double v);  ///< "%.17g"; non-finite -> null
    void value(const std::string& key, long long v);
    void value(const std::string& key, unsigned long long v);
    void value(const std::string& key, int v) { value(key, static_cast<long long>(v)); }
    void value(const std::string& key, bool v);
    /// Any other integer type (unsigned, long, std::size_t, std::int64_t, ...), written
    /// exactly; plain `char` and `bool` are left out on purpose.
    template <typename T, typename = std::enable_if_t<std::is_integral_v<T> &&
                                                      !std::is_same_v<T, bool> &&
                                                      !std::is_same_v<T, char>>>
    void value(const std::string& key, T v) {
        if constexpr (std::is_signed_v<T>)
            value(key, static_cast<long long>(v));
        else
            value(key, static_cast<unsigned long long>(v));
    }

    /// Array elements (no key): the same as value("", v).
    void value(const std::string& v) { value(std::string(), v); }
    void value(const char* v) { value(std::string(), v); }
    void value(double v) { value(std::string(), v); }
    void value(bool v) { value(std::string(), v); }
    template <typename T, typename = std::enable_if_t<std::is_integral_v<T> &&
                                                      !std::is_same_v<T, bool> &&
                                                      !std::is_same_v<T, char>>>
    void value(T v) {
        value(std::string(), v);
    }

    /// The finished document (no trailing newline); throws seaspring::Error when nothing
    /// was written or an object or array is still open.
    std::string str() const;

private:
    /// Checks the key rules, then writes the separator, indent and `"key": `.
    void beginItem(const std::string& key);
    void open(const std::string& key, char bracket);
    void close(char bracket);

    std::string out_;
    std::vector<char> open_;       ///< '{' or '[' of each open container, innermost last
    std::vector<bool> has_items_;  ///< per open container: written anything yet?
    bool complete_ = false;        ///< the root value is finished
};

/// The JSON string literal of `s`, quotes included (escaping as described above).
std::string jsonQuote(const std::string& s);

/// Writes `text` to `path` through the temporary file "<path>.tmp" and a rename, so that
/// `path` is never seen half-written. Errors name the path and the system's reason.
void writeTextFileAtomic(const std::string& path, const std::string& text);

}  // namespace seaspring::io
