// SeaSpring — MIT licence.
/// \file test_json_writer.cpp
/// \brief The JSON writer: exact expected text (layout, escaping, numbers), misuse errors, and
///        the atomic text-file write.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <string>
#include <unistd.h>

#include "core/error.h"
#include "error_expect.h"
#include "io/json_writer.h"

namespace seaspring::io {
namespace {

namespace fs = std::filesystem;

using test::errorOf;


TEST(JsonWriter, NestedDocumentExactText) {
    JsonWriter j;
    j.beginObject();
    j.value("program", "seaspring");
    j.value("name", std::string("dam break"));
    j.value("threads", 2);
    j.value("steps", 123456789012LL);
    j.value("hash", 18446744073709551615ULL);
    j.value("np", std::size_t(171496));
    j.value("offset", std::int64_t(-5));
    j.value("small", std::uint32_t(7));
    j.value("ok", true);
    j.value("failed", false);
    j.beginObject("particles");
    j.value("fluid", 128310);
    j.endObject();
    j.beginObject("empty_object");
    j.endObject();
    j.beginArray("empty_array");
    j.endArray();
    j.beginArray("list");
    j.value(1);
    j.value(0.5);
    j.value("text");
    j.value(false);
    j.beginObject();
    j.value("a", 1);
    j.endObject();
    j.beginArray();
    j.endArray();
    j.endArray();
    j.endObject();
    EXPECT_EQ(j.str(),
              "{\n"
              "  \"program\": \"seaspring\",\n"
              "  \"name\": \"dam break\",\n"
              "  \"threads\": 2,\n"
              "  \"steps\": 123456789012,\n"
              "  \"hash\": 18446744073709551615,\n"
              "  \"np\": 171496,\n"
              "  \"offset\": -5,\n"
              "  \"small\": 7,\n"
              "  \"ok\": true,\n"
              "  \"failed\": false,\n"
              "  \"particles\": {\n"
              "    \"fluid\": 128310\n"
              "  },\n"
              "  \"empty_object\": {},\n"
              "  \"empty_array\": [],\n"
              "  \"list\": [\n"
              "    1,\n"
              "    0.5,\n"
              "    \"text\",\n"
              "    false,\n"
              "    {\n"
              "      \"a\": 1\n"
              "    },\n"
              "    []\n"
              "  ]\n"
              "}");
}

TEST(JsonWriter, DoublesRoundTripAndNonFiniteIsNull) {
    JsonWriter j;
    j.beginArray();
    j.value(0.1);
    j.value(1.0 / 3.0);
    j.value(-0.0);
    j.value(2.0);
    j.value(1e300);
    j.value(std::numeric_limits<double>::denorm_min());
    j.value(std::numeric_limits<double>::quiet_NaN());
    j.value(std::numeric_limits<double>::infinity());
    j.value(-std::numeric_limits<double>::infinity());
    j.value(1.5f);  // float goes through double
    j.endArray();
    EXPECT_EQ(j.str(),
              "[\n"
              "  0.10000000000000001,\n"
              "  0.33333333333333331,\n"
              "  -0,\n"
              "  2,\n"
              "  1.0000000000000001e+300,\n"
              "  4.9406564584124654e-324,\n"
              "  null,\n"
              "  null,\n"
              "  null,\n"
              "  1.5\n"
              "]");
}

TEST(JsonWriter, StringEscaping) {
    EXPECT_EQ(jsonQuote(""), "\"\"");
    EXPECT_EQ(jsonQuote("say \"hi\""), "\"say \\\"hi\\\"\"");
    EXPECT_EQ(jsonQuote("C:\\dir\\file"), "\"C:\\\\dir\\\\file\"");
    EXPECT_EQ(jsonQuote("a\nb\tc\rd\be\ff"), "\"a\\nb\\tc\\rd\\be\\ff\"");
    EXPECT_EQ(jsonQuote(std::string("nul\0x", 5)), "\"nul\\u0000x\"");
    EXPECT_EQ(jsonQuote("\x01\x1f\x7f"), "\"\\u0001\\u001f\x7f\"");  // DEL needs no escape
    EXPECT_EQ(jsonQuote("/slash"), "\"/slash\"");
    // UTF-8 bytes pass through unchanged: "ρ 1000 kg/m³ — ok".
    const std::string utf8 = "\xcf\x81 1000 kg/m\xc2\xb3 \xe2\x80\x94 ok";
    EXPECT_EQ(jsonQuote(utf8), "\"" + utf8 + "\"");

    JsonWriter j;
    j.beginObject();
    j.value("key \"q\"\n", "v\\");
    j.endObject();
    EXPECT_EQ(j.str(), "{\n  \"key \\\"q\\\"\\n\": \"v\\\\\"\n}");
}

TEST(JsonWriter, RootScalarValue) {
    JsonWriter j;
    j.value("only");
    EXPECT_EQ(j.str(), "\"only\"");
    EXPECT_HAS(errorOf([&] { j.value(1); }), "the document is complete");
}

TEST(JsonWriter, MisuseThrows) {
    {
        JsonWriter j;
        j.beginArray();
        EXPECT_HAS(errorOf([&] { j.value("key", 1); }),
                   "JsonWriter: an array element takes no key (got \"key\")");
        EXPECT_HAS(errorOf([&] { j.beginObject("k"); }), "array element takes no key");
        EXPECT_HAS(errorOf([&] { j.endObject(); }), "endObject() while an array is open");
        EXPECT_HAS(errorOf([&] { (void)j.str(); }), "1 object(s) or array(s) still open");
    }
    {
        JsonWriter j;
        j.beginObject();
        EXPECT_HAS(errorOf([&] { j.value(2.0); }), "an object member needs a key");
        EXPECT_HAS(errorOf([&] { j.beginArray(); }), "an object member needs a key");
        EXPECT_HAS(errorOf([&] { j.endArray(); }), "endArray() while an object is open");
        j.beginObject("inner");
        EXPECT_HAS(errorOf([&] { (void)j.str(); }), "2 object(s) or array(s) still open");
        j.endObject();
        j.endObject();
        EXPECT_HAS(errorOf([&] { j.endObject(); }), "endObject() without an open object");
        EXPECT_HAS(errorOf([&] { j.beginObject(); }), "the document is complete");
        EXPECT_EQ(j.str(), "{\n  \"inner\": {}\n}");  // the errors changed nothing
    }
    {
        JsonWriter j;
        EXPECT_HAS(errorOf([&] { (void)j.str(); }), "the document is empty");
        EXPECT_HAS(errorOf([&] { j.endArray(); }), "endArray() without an open array");
        EXPECT_HAS(errorOf([&] { j.beginObject("root"); }), "the root value takes no key");
        j.beginObject();
        EXPECT_HAS(errorOf([&] { j.value("k", static_cast<const char*>(nullptr)); }),
                   "null string pointer for \"k\"");
    }
}

/// A fresh scratch folder per process and tag, removed at the end of the test.
struct Scratch {
    std::string dir;
    explicit Scratch(const std::string& tag)
        : dir((fs::path(::testing::TempDir()) /
               ("seaspring_json_" + std::to_string(::getpid()) + "_" + tag))
                  .string()) {
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    ~Scratch() {
        std::error_code ignored;
        fs::remove_all(dir, ignored);
    }
};

std::string readAll(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

TEST(WriteTextFileAtomic, WritesAndReplaces) {
    const Scratch scratch("write");
    const std::string& dir = scratch.dir;
    const std::string path = dir + "/run.json";
    writeTextFileAtomic(path, "first\n");
    EXPECT_EQ(readAll(path), "first\n");
    const std::string binary("a\0b\r\n", 5);
    writeTextFileAtomic(path, binary);
    EXPECT_EQ(readAll(path), binary);
    writeTextFileAtomic(path, "");
    EXPECT_TRUE(fs::exists(path));
    EXPECT_EQ(fs::file_size(path), 0u);
    EXPECT_FALSE(fs::exists(path + ".tmp"));
}

TEST(WriteTextFileAtomic, ErrorsNameThePathAndReason) {
    const Scratch scratch("errors");
    const std::string& dir = scratch.dir;
    const std::string missing = dir + "/no_such_folder/run.json";
    const std::string msg = errorOf([&] { writeTextFileAtomic(missing, "x"); });
    EXPECT_HAS(msg, missing + ": cannot write the file (creating " + missing + ".tmp)");
    EXPECT_HAS(msg, "No such file or directory");

    // A non-empty folder where the file goes: the temporary file is written, the rename
    // fails, and the temporary file is removed again.
    const std::string blocked = dir + "/blocked";
    fs::create_directories(blocked + "/inside");
    const std::string msg2 = errorOf([&] { writeTextFileAtomic(blocked, "x"); });
    EXPECT_HAS(msg2, blocked + ": cannot write the file (renaming " + blocked + ".tmp)");
    EXPECT_HAS(msg2, "Is a directory");
    EXPECT_FALSE(fs::exists(blocked + ".tmp"));
    EXPECT_TRUE(fs::is_directory(blocked + "/inside"));
}

}  // namespace
}  // namespace seaspring::io
