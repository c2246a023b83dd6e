// The checked JSON reader: nesting limit, duplicate keys, positions; and the recognition of
// UTF-16/32 text by the CSV reader.

#include <string>

#include <gtest/gtest.h>

#include "hyst/core/error.hpp"
#include "hyst/io/csv.hpp"
#include "hyst/io/json_text.hpp"
#include "hyst/io/limits.hpp"

namespace hyst::io {
namespace {

std::string error_of(const std::string& text) {
  try {
    parse_json_text(text, "t.json");
  } catch (const Error& error) {
    return error.what();
  }
  return "no error";
}

std::string nested(std::size_t depth) {
  return std::string(depth, '[') + std::string(depth, ']');
}

TEST(JsonText, AcceptsNestingUpToTheLimit) {
  const auto document = parse_json_text(nested(limits::kMaxJsonDepth), "t.json");
  EXPECT_TRUE(document.is_array());
}

TEST(JsonText, RefusesNestingBeyondTheLimitWithItsPosition) {
  EXPECT_EQ(error_of(nested(limits::kMaxJsonDepth + 1)),
            "t.json:1:257: JSON nesting deeper than 256 levels (the limit of hyst's JSON reader)");
  // 100 000 levels (the stack of the recursive printer used to overflow) end the same way.
  const std::string deep =
      "{\"a\":\n  " + std::string(100000, '[') + std::string(100000, ']') + "}";
  EXPECT_EQ(error_of(deep).substr(0, 12), "t.json:2:258");
}

TEST(JsonText, BracketsInsideStringsDoNotCount) {
  const std::string text = "{\"a\": \"" + std::string(1000, '[') + "\\\"{{{\", \"b\": [1]}";
  const auto document = parse_json_text(text, "t.json");
  EXPECT_EQ(document.at("b").at(0), 1);
}

TEST(JsonText, RefusesDuplicateKeysNamingKeyObjectAndBothPlaces) {
  EXPECT_EQ(error_of("{\"params\": {\"weights\": [1],\n  \"weights\": [2]}}"),
            "t.json:2:3: duplicate key 'weights' in 'params' (first at line 1, column 13)");
  // The same key written with an escape is the same key.
  EXPECT_EQ(error_of("{\"model\": 1, \"\\u006dodel\": 2}"),
            "t.json:1:14: duplicate key 'model' (first at line 1, column 2)");
  // A key with a line break or a NUL stays on one line; a long one is cut.
  EXPECT_EQ(error_of("{\"a\\nb\\u0000\": 1, \"a\\nb\\u0000\": 2}"),
            "t.json:1:19: duplicate key 'a?b?' (first at line 1, column 2)");
  const std::string key(100, 'k');
  EXPECT_EQ(
      error_of("{\"" + key + "\": 1, \"" + key + "\": 2}"),
      "t.json:1:109: duplicate key '" + key.substr(0, 60) + "...' (first at line 1, column 2)");
  // Equal keys in different objects, and equal values, are fine.
  EXPECT_NO_THROW(parse_json_text(R"({"a": {"x": 1}, "b": {"x": "x"}, "c": ["x", "x"]})", "t"));
  EXPECT_NO_THROW(parse_json_text(R"([{"x": 1}, {"x": 2}])", "t"));
}

TEST(JsonText, SyntaxErrorsAndOverflowKeepTheirMessages) {
  EXPECT_EQ(error_of("{\"a\": 1e400}"),
            "t.json: not valid JSON: number overflow parsing '1e400' at line 1, column 7");
  EXPECT_NE(error_of("{\"a\": [1, }").find("t.json: not valid JSON: parse error at line 1"),
            std::string::npos);
}

// Found by fuzz_json_entry_points: nlohmann's parser stops at a NUL byte, so that a model file
// followed by a NUL and anything at all was read without complaint.
TEST(JsonText, RefusesNulBytesWhereTheyStand) {
  using namespace std::string_literals;
  EXPECT_EQ(error_of("{\"a\": 1}\n\0garbage"s),
            "t.json:2:1: a NUL byte, which UTF-8 or ASCII text does not contain (a binary file?)");
  EXPECT_EQ(error_of("[\"x\0\"]"s).substr(0, 12), "t.json:1:4: ");
}

TEST(TextEncoding, Utf16AndUtf32AreNamed) {
  const auto csv_error = [](const std::string& bytes) {
    try {
      parse_csv(bytes, "w.csv");
    } catch (const Error& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  using namespace std::string_literals;
  const auto starts = [](const std::string& text, std::string_view prefix) {
    return text.substr(0, prefix.size()) == prefix;
  };
  EXPECT_TRUE(starts(csv_error("\xFF\xFEv\0,\0y\0\n\0"s),
                     "w.csv: the file is UTF-16 (little-endian, with a byte order mark); hyst "
                     "reads UTF-8 or ASCII text (convert it, e.g. with iconv -f UTF-16 -t UTF-8)"));
  EXPECT_TRUE(starts(csv_error("\0v\0,\0y\0\n"s),
                     "w.csv: the file is UTF-16 (big-endian, without a byte order mark)"));
  EXPECT_TRUE(starts(csv_error("v\0\0\0,\0\0\0"s),
                     "w.csv: the file is UTF-32 (little-endian, without a byte order mark)"));
  EXPECT_TRUE(starts(csv_error("\0\0\xFE\xFF\0\0\0v"s),
                     "w.csv: the file is UTF-32 (big-endian, with a byte order mark)"));
  // A NUL byte elsewhere (found by fuzzing: a table read once, written and read again came out
  // with the UTF-32 pattern at its start) is refused wherever it stands.
  EXPECT_EQ(csv_error("v\n1\n2\0\n"s),
            "w.csv:3:2: a NUL byte, which UTF-8 or ASCII text does not contain (a binary file?)");
  // A name starting with a UTF-16 byte order mark after a comment line: written back first in a
  // file, it would read as UTF-16 (found by fuzzing).
  EXPECT_EQ(csv_error("# c\n\xFE\xFFv,y\n1,2\n"s),
            "w.csv:2: column 1 of the header: the name starts with the bytes of a UTF-16 byte "
            "order mark (FE FF or FF FE)");
  // UTF-8 with its byte order mark is read.
  EXPECT_EQ(parse_csv("\xEF\xBB\xBFv\n1\n", "u.csv").names.at(0), "v");
}

}  // namespace
}  // namespace hyst::io
