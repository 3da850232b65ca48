// SeaSpring — MIT licence.
/// \file json_writer.cpp
#include "io/json_writer.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/error.h"

namespace seaspring::io {

std::string jsonQuote(const std::string& s) {
    std::string o = "\"";
    for (unsigned char c : s) {
        switch (c) {
            case '"': o += "\\\""; break;
            case '\\': o += "\\\\"; break;
            case '\n': o += "\\n"; break;
            case '\t': o += "\\t"; break;
            case '\r': o += "\\r"; break;
            default:
                if (c < 0x20) {
                    char b[8];
                    std::snprintf(b, sizeof b, "\\u%04x", c);
                    o += b;
                } else {
                    o += char(c);
                }
        }
    }
    return o + "\"";
}

void JsonWriter::prefix(const std::string& key) {
    if (done_) throw Error("JsonWriter: the document is already complete");
    if (stack_.empty()) {
        if (!key.empty()) throw Error("JsonWriter: the root value takes no key");
        return;
    }
    const bool in_object = stack_.back() == '{';
    if (in_object && key.empty()) throw Error("JsonWriter: object members need a key");
    if (!in_object && !key.empty()) throw Error("JsonWriter: array elements take no key (\"" + key + "\")");
    out_ += first_.back() ? "\n" : ",\n";
    first_.back() = false;
    out_.append(2 * stack_.size(), ' ');
    if (in_object) out_ += jsonQuote(key) + ": ";
}

void JsonWriter::beginObject(const std::string& key) {
    prefix(key);
    out_ += "{";
    stack_.push_back('{');
    first_.push_back(true);
}

void JsonWriter::beginArray(const std::string& key) {
    prefix(key);
    out_ += "[";
    stack_.push_back('[');
    first_.push_back(true);
}

void JsonWriter::endObject() {
    if (stack_.empty() || stack_.back() != '{') throw Error("JsonWriter: endObject without an open object");
    const bool empty = first_.back();
    stack_.pop_back();
    first_.pop_back();
    if (!empty) {
        out_ += "\n";
        out_.append(2 * stack_.size(), ' ');
    }
    out_ += "}";
    if (stack_.empty()) done_ = true;
}

void JsonWriter::endArray() {
    if (stack_.empty() || stack_.back() != '[') throw Error("JsonWriter: endArray without an open array");
    const bool empty = first_.back();
    stack_.pop_back();
    first_.pop_back();
    if (!empty) {
        out_ += "\n";
        out_.append(2 * stack_.size(), ' ');
    }
    out_ += "]";
    if (stack_.empty()) done_ = true;
}

void JsonWriter::value(const std::string& key, const std::string& v) {
    prefix(key);
    out_ += jsonQuote(v);
}
void JsonWriter::value(const std::string& key, const char* v) { value(key, std::string(v)); }
void JsonWriter::value(const std::string& key, double v) {
    prefix(key);
    if (!std::isfinite(v)) {
        out_ += "null";
        return;
    }
    char b[32];
    std::snprintf(b, sizeof b, "%.17g", v);
    out_ += b;
}
void JsonWriter::value(const std::string& key, long long v) {
    prefix(key);
    out_ += std::to_string(v);
}
void JsonWriter::value(const std::string& key, bool v) {
    prefix(key);
    out_ += v ? "true" : "false";
}

std::string JsonWriter::str() const {
    if (!stack_.empty()) throw Error("JsonWriter: " + std::to_string(stack_.size()) + " object(s)/array(s) still open");
    return out_;
}

void writeTextFileAtomic(const std::string& path, const std::string& text) {
    const std::string tmp = path + ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) throw Error(path + ": cannot write: " + std::strerror(errno));
        out << text;
        if (!out) throw Error(path + ": cannot write: " + std::strerror(errno));
    }
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) throw Error(path + ": cannot write: " + ec.message());
}

}  // namespace seaspring::io
