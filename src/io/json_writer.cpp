// SeaSpring — MIT licence.
/// \file json_writer.cpp
/// \brief The pretty-printing JSON writer and the atomic text-file write.
#include "io/json_writer.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "core/error.h"

namespace seaspring::io {
namespace {

[[noreturn]] void misuse(const std::string& message) {
    throw Error("JsonWriter: " + message);
}

const char* containerName(char bracket) { return bracket == '{' ? "object" : "array"; }

/// Removes the temporary file and throws "PATH: cannot write the file (STEP TMP): reason".
[[noreturn]] void failTextWrite(const std::string& path, const std::string& tmp,
                                const char* step, int err) {
    std::remove(tmp.c_str());
    throw Error(formatLocation(path, 0, std::string("cannot write the file (") + step + " " +
                                            tmp + "): " + std::strerror(err)));
}

}  // namespace

std::string jsonQuote(const std::string& s) {
    std::string out;
    out.reserve(s.size() + 2);
    out += '"';
    for (const char ch : s) {
        const auto c = static_cast<unsigned char>(ch);
        switch (c) {
            case '"': out += "\\\""; break;
            case '\\': out += "\\\\"; break;
            case '\b': out += "\\b"; break;
            case '\f': out += "\\f"; break;
            case '\n': out += "\\n"; break;
            case '\r': out += "\\r"; break;
            case '\t': out += "\\t"; break;
            default:
                if (c < 0x20) {
                    char escaped[8];
                    std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(c));
                    out += escaped;
                } else {
                    out += ch;  // printable ASCII and UTF-8 bytes as they are
                }
        }
    }
    out += '"';
    return out;
}

void JsonWriter::beginItem(const std::string& key) {
    if (complete_) misuse("the document is complete; nothing may follow the root value");
    if (open_.empty()) {
        if (!key.empty()) misuse("the root value takes no key (got \"" + key + "\")");
        return;
    }
    const bool in_object = open_.back() == '{';
    if (in_object && key.empty()) misuse("an object member needs a key");
    if (!in_object && !key.empty())
        misuse("an array element takes no key (got \"" + key + "\")");
    out_ += has_items_.back() ? ",\n" : "\n";
    has_items_.back() = true;
    out_.append(2 * open_.size(), ' ');
    if (in_object) {
        out_ += jsonQuote(key);
        out_ += ": ";
    }
}

void JsonWriter::open(const std::string& key, char bracket) {
    beginItem(key);
    out_ += bracket;
    open_.push_back(bracket);
    has_items_.push_back(false);
}

void JsonWriter::close(char bracket) {
    const char* name = containerName(bracket);
    const std::string call = bracket == '{' ? "endObject()" : "endArray()";
    if (open_.empty()) misuse(call + " without an open " + name);
    if (open_.back() != bracket)
        misuse(call + " while an " + containerName(open_.back()) + " is open");
    const bool had_items = has_items_.back();
    open_.pop_back();
    has_items_.pop_back();
    if (had_items) {
        out_ += '\n';
        out_.append(2 * open_.size(), ' ');
    }
    out_ += bracket == '{' ? '}' : ']';
    if (open_.empty()) complete_ = true;
}

void JsonWriter::beginObject(const std::string& key) { open(key, '{'); }
void JsonWriter::beginArray(const std::string& key) { open(key, '['); }
void JsonWriter::endObject() { close('{'); }
void JsonWriter::endArray() { close('['); }

void JsonWriter::value(const std::string& key, const std::string& v) {
    beginItem(key);
    out_ += jsonQuote(v);
    if (open_.empty()) complete_ = true;
}

void JsonWriter::value(const std::string& key, const char* v) {
    if (v == nullptr) misuse("null string pointer for \"" + key + "\"");
    value(key, std::string(v));
}

void JsonWriter::value(const std::string& key, double v) {
    beginItem(key);
    if (std::isfinite(v)) {
        char text[32];
        std::snprintf(text, sizeof text, "%.17g", v);
        for (char* c = text; *c != '\0'; ++c)
            if (*c == ',') *c = '.';  // a decimal comma, should a locale have set one
        out_ += text;
    } else {
        out_ += "null";
    }
    if (open_.empty()) complete_ = true;
}

void JsonWriter::value(const std::string& key, long long v) {
    beginItem(key);
    out_ += std::to_string(v);
    if (open_.empty()) complete_ = true;
}

void JsonWriter::value(const std::string& key, unsigned long long v) {
    beginItem(key);
    out_ += std::to_string(v);
    if (open_.empty()) complete_ = true;
}

void JsonWriter::value(const std::string& key, bool v) {
    beginItem(key);
    out_ += v ? "true" : "false";
    if (open_.empty()) complete_ = true;
}

std::string JsonWriter::str() const {
    if (!open_.empty())
        misuse(std::to_string(open_.size()) + " object(s) or array(s) still open (innermost: " +
               containerName(open_.back()) + ")");
    if (!complete_) misuse("the document is empty");
    return out_;
}

void writeTextFileAtomic(const std::string& path, const std::string& text) {
    const std::string tmp = path + ".tmp";
    std::FILE* file = std::fopen(tmp.c_str(), "wb");
    if (file == nullptr) failTextWrite(path, tmp, "creating", errno);
    const std::size_t written = std::fwrite(text.data(), 1, text.size(), file);
    const int write_errno = errno;
    if (written != text.size()) {
        std::fclose(file);
        failTextWrite(path, tmp, "writing", write_errno);
    }
    if (std::fclose(file) != 0) failTextWrite(path, tmp, "closing", errno);
    if (std::rename(tmp.c_str(), path.c_str()) != 0) failTextWrite(path, tmp, "renaming", errno);
}

}  // namespace seaspring::io
