// SeaSpring — MIT licence.
/// \file json_writer.h
/// \brief A small JSON writer for run summaries (pretty-printed, 2-space indent), and an atomic
///        text-file write.
#pragma once

#include <string>
#include <vector>

namespace seaspring::io {

class JsonWriter {
public:
    /// Root object (no key) or an object member (key) / array element (no key in arrays).
    void beginObject(const std::string& key = "");
    void endObject();
    void beginArray(const std::string& key = "");
    void endArray();
    void value(const std::string& key, const std::string& v);
    void value(const std::string& key, const char* v);
    void value(const std::string& key, double v);  ///< non-finite -> null
    void value(const std::string& key, long long v);
    void value(const std::string& key, int v) { value(key, static_cast<long long>(v)); }
    void value(const std::string& key, bool v);
    /// The document; throws seaspring::Error when objects or arrays are still open.
    std::string str() const;

private:
    void prefix(const std::string& key);
    std::string out_;
    std::vector<char> stack_;  ///< '{' or '['
    std::vector<bool> first_;
    bool done_ = false;
};

/// JSON string literal of `s` (quotes included).
std::string jsonQuote(const std::string& s);

/// Writes `text` to `path` via a temporary file and rename; errors name the path.
void writeTextFileAtomic(const std::string& path, const std::string& text);

}  // namespace seaspring::io
